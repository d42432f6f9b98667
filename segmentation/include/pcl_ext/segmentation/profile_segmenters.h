/*
 * pcl_ext: segmenters for the points of one profile (Sithole & Mapurisa, section 4.1).
 */
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace profiles {
/** \brief The points of one profile in the profile's own frame. */
struct ProfilePoints {
  std::vector<Eigen::Vector2f> uv; ///< coordinates in the profile plane
  std::vector<float> t;            ///< coordinate across the profile, in [0, width)
};

/** \brief An edge between two points of a profile (local indices, a < b). */
struct LocalEdge {
  std::uint32_t a;
  std::uint32_t b;
};

/** \brief The local gap of every point of a profile, for link thresholds that follow
 * the local point density (not in the paper, which uses one threshold "slightly larger
 * than the average point spacing"; see ProfileSegmentation::setLocalThreshold).
 *
 * The gap of a point is the distance to its nearest distinct point of the profile (at
 * most \a max_distance, which also bounds the search). The local gap is the median of
 * the gaps of the point and its \a neighbours nearest points within \a max_distance: a
 * stretch of chain sparser than the rest (a surface far from the scanner) lengthens it,
 * a single wide gap (a chain's end, a hole) does not. Coincident points share their
 * representative's value. Deterministic. \param[out] gaps one per point */
void
localGaps (const ProfilePoints& profile,
           double max_distance,
           unsigned int neighbours,
           std::vector<float>& gaps);

/** \brief Proximity chaining (section 4.1.1): every point is linked to its \a
 * neighbours nearest points in the profile plane; links longer than \a threshold are
 * cut.
 *
 * Coincident points are linked to one another first and chain as one point, so
 * duplicates cannot use up the links. Ties are broken by index: deterministic.
 * \param[in] thresholds optional per-point thresholds (see localGaps) replacing \a
 * threshold: a link i-j is kept when not longer than the smaller of the two; \a
 * threshold must then be their maximum \param[out] edges without duplicates */
void
proximityEdges (const ProfilePoints& profile,
                double threshold,
                unsigned int neighbours,
                std::vector<LocalEdge>& edges,
                const std::vector<float>* thresholds = nullptr);

/** \brief Minimum spanning tree of the profile points with edges longer than \a
 * threshold cut (section 3: "segmentation of minimum spanning trees"). Its components
 * are the single-linkage clusters at \a threshold. \param[in] thresholds optional
 * per-point thresholds, as for proximityEdges \param[out] edges sorted, without
 * duplicates */
void
spanningTreeEdges (const ProfilePoints& profile,
                   double threshold,
                   std::vector<LocalEdge>& edges,
                   const std::vector<float>* thresholds = nullptr);

/** \brief Curve reconstruction (section 5.2: the paper segments the profiles of the
 * nested spheres by "first fitting curves to profile points using the curve
 * reconstruction algorithm proposed by Dey et al. (2000) and then applying a proximity
 * threshold on the curves"): the nearest-neighbour crust of T.K. Dey and P. Kumar, "A
 * simple provable algorithm for curve reconstruction" (SODA 1999), then links longer
 * than \a threshold cut.
 *
 * Each point is linked to its nearest point q and to its half neighbour, the nearest
 * point s on the other side (angle q-p-s over 90 degrees). For curves sampled densely
 * enough (every point of the curve within a third of its local feature size of a
 * sample), these are exactly the curves' edges, like the conservative crust of Dey,
 * Mehlhorn and Ramos the paper cites, and no Delaunay triangulation is needed. Unlike
 * proximity chaining with k > 2 links, two curves closer to each other than the
 * threshold but farther than their own spacing are not linked: the spheres within
 * spheres of section 5.2. Departure: the paper's reference is the conservative crust,
 * which also handles curves with ends without a threshold; here the threshold cuts the
 * links past a curve's ends. Coincident points chain as one point; ties by index:
 * deterministic. \param[in] thresholds optional per-point thresholds, as for
 * proximityEdges \param[out] edges sorted, without duplicates */
void
crustEdges (const ProfilePoints& profile,
            double threshold,
            std::vector<LocalEdge>& edges,
            const std::vector<float>* thresholds = nullptr);

/** \brief Parameters of the curve-fitting profile segmenter. */
struct CurveFitParameters {
  double threshold = 0.0; ///< proximity threshold of the chains (the spanning-tree cut)
  double window = 0.0;    ///< half length of the fitted stretch on each side of a point
  double tangent_radius =
      0.0; ///< radius of the neighbourhood giving the local direction
  unsigned int min_side_points = 5; ///< fewer points on a side: a curve end, not judged
  bool corrected_aic = false; ///< select by AICc (small-sample AIC) rather than AIC
  /** \brief Optional per-point multipliers of the window and the tangent radius (the
   * local threshold over the global one, see localGaps): the fits then span about as
   * many points where the profile is sparse as where it is dense. */
  const std::vector<float>* window_scale = nullptr;
  bool side_frames = false; ///< fit each side along its own principal axis
};

/** \brief What the curve fits say about each point of a profile. */
struct CurveScores {
  std::vector<std::uint8_t> evaluated; ///< 1 when both sides could be fitted
  std::vector<float> turn;             ///< angle between the two sides' normals (rad)
  std::vector<float> rms; ///< larger residual RMS of the two sides (over n - p each)
  /** \brief The noise sigma the two sides' fits show together: their pooled residual
   * variance (rss_l + rss_r) / (n_l - p_l + n_r - p_r) over the median of chi-square /
   * dof at those degrees of freedom, (1 - 2 / (9 dof))^3 (Wilson & Hilferty, 1931), so
   * that the median of this over the points of a smooth surface is the noise sigma. */
  std::vector<float> noise;
  /** \brief Standard error of \a turn (rad) per metre of noise sigma, propagated to
   * first order from the two fits' coefficients: how much of the turn the noise alone
   * could make. */
  std::vector<float> turn_sigma;
};

/** \brief One polynomial curve fit, chosen by the Akaike information criterion. */
struct PolynomialFit {
  int degree = -1;    ///< 1, 2 or 3; -1 when no model could be fitted
  double slope = 0.0; ///< dy/dx at x = 0
  Eigen::Vector3d terms = Eigen::Vector3d::Zero(); ///< a1, a2, a3 (0 beyond the degree)
  double rss = 0.0;                                ///< residual sum of squares
  /** \brief rss / (n - p), p = degree + 2 fitted terms (the polynomial's and the t
   * term): the unbiased estimate of the noise variance of y. */
  double residual_variance = 0.0;
  /** \brief n ln(rss / n) + 2 k, plus 2 k (k + 1) / (n - k - 1) when corrected (AICc),
   * with k = p + 1 parameters: the p fitted terms and the noise variance (Hurvich &
   * Tsai, 1989); infinite for a line kept where AICc cannot be scored (n <= k + 1). */
  double aic = 0.0;
  /** \brief (Phi^T Phi)^-1 restricted to (a1, a2, a3) (0 beyond the degree): their
   * covariance is this times the noise variance of y. */
  Eigen::Matrix3d unit_covariance = Eigen::Matrix3d::Zero();

  /** \brief dy/dx at \a x. */
  double
  slopeAt (double x) const
  {
    return terms[0] + x * (2.0 * terms[1] + 3.0 * x * terms[2]);
  }

  /** \brief d2y/dx2 at \a x. */
  double
  secondDerivativeAt (double x) const
  {
    return 2.0 * terms[1] + 6.0 * x * terms[2];
  }
};

/** \brief Fit y = a0 + a1 x + ... + ad x^d + c t for d = 1, 2, 3 and keep the model of
 * lowest AIC. The t term absorbs the slant of a surface crossing the profile obliquely
 * (the profile has a width), so the residuals measure the curve, not the profile's
 * thickness. A model of p = d + 2 terms needs n >= p + 1 points (one residual degree
 * of freedom). With AICc a parabola or a cubic also needs n > k + 1 = p + 2, as the
 * correction is infinite at n = k + 1 (undefined below): a parabola needs 7 points, a
 * cubic 8; with 4 or 5 points the line is kept, its AICc infinite. \param[in] x, y, t
 * sample coordinates (same length) \param[in] scale a length used to condition the
 * normal equations (e.g. the window) \param[in] corrected use AICc, the small-sample
 * correction of Hurvich & Tsai (1989, "Regression and time series model selection in
 * small samples"); false: the paper's plain AIC \param[in] max_degree the highest
 * degree tried (1 to 3) */
PolynomialFit
fitPolynomialAic (const std::vector<double>& x,
                  const std::vector<double>& y,
                  const std::vector<double>& t,
                  double scale,
                  bool corrected = false,
                  int max_degree = 3);

/** \brief Curve fitting (section 4.1.2), the scoring half: for every point, the points
 * of its chain within the window are split at the point by the local direction, a
 * polynomial chosen by AIC is fitted on each side, and the turn of the unit normal
 * between the middles of the two sides, less the turn the fitted curvature explains, is
 * measured, with the worse fit's residual and the turn's standard error per unit noise.
 * \param[in] chain_edges spanning-tree edges: only points of the same chain are fitted
 */
void
scoreCurveTurns (const ProfilePoints& profile,
                 const std::vector<LocalEdge>& chain_edges,
                 const CurveFitParameters& parameters,
                 CurveScores& scores);
/** \brief Parameters of joinCurvesAcrossJunctions. */
struct JunctionParameters {
  double threshold =
      0.0;             ///< chain link threshold: attachments closer than 2x are one end
  double window = 0.0; ///< length of the stretch of a curve end that is fitted
  double max_turn = 0.0;  ///< radians, as for the curve ends
  double tolerance = 0.0; ///< residual RMS a curve through the junction may have (> 0)
  bool corrected_aic = false;      ///< select by AICc rather than AIC
  unsigned int min_end_points = 5; ///< a shorter end is not fitted
  /** \brief Optional per-point multipliers of the window (see CurveFitParameters). */
  const std::vector<float>* window_scale = nullptr;
  /** \brief Optional per-point flags of points that may not carry a join (the curve
   * ends of other stacks, which leave the graph). */
  const std::vector<std::uint8_t>* removed = nullptr;
};

/** \brief Curve fitting (section 4.1.2), the extraction half for entangled curves: the
 * curves that run through a junction of a profile are followed across it.
 *
 * Where curves cross or touch in a profile (two surfaces crossing, a pipe on its
 * support, a branch leaving a trunk), the points near the junction are curve ends: a
 * side of each is not one curve. Removing them cuts every curve there, which splits a
 * surface along the line where another crosses it. Here the arms are the chains of the
 * points that are not curve ends; an arm of fewer than \a min_end_points points,
 * shorter than the window, or a blob (no principal direction) less than two windows
 * across is part of the junction (fits that passed by chance, or the crossing itself,
 * whose fits are not judged), and a junction is a chain of such points. Where at least
 * three arms meet (a crossing, or a curve with another leaving it; two arms are a
 * crease or a curve's end), the ends of every two arms (the points of each within the
 * window of where it meets the junction) are fitted as one curve, a line or a parabola
 * chosen by AIC along the line between them: a cubic's inflection would let two
 * touching curves pass for one S-shaped curve. A pair is one curve when its ends turn
 * by at most \a max_turn, lie at most six windows apart and the joint fit's residual
 * RMS is within \a tolerance; pairs are taken in increasing residual, each end at most
 * once, so that of two crossing curves each arm continues the arm that prolongs it.
 * This is the paper's "the model fitting and selection is repeated until no new curves
 * are detected" for the junctions the splitting leaves. Deterministic.
 * \param[in] curve_ends one flag per point of the profile \param[out] joins one edge
 * per pair, between the pair's nearest points not \a removed (local indices, a < b), in
 * a deterministic order \param[out] absorbed optional: the points of the short arms of
 * every junction a curve was followed across, in increasing order; they are curve ends
 * too */
void
joinCurvesAcrossJunctions (const ProfilePoints& profile,
                           const std::vector<LocalEdge>& chain_edges,
                           const std::vector<std::uint8_t>& curve_ends,
                           const JunctionParameters& parameters,
                           std::vector<LocalEdge>& joins,
                           std::vector<std::uint32_t>* absorbed = nullptr);
} // namespace profiles
} // namespace pcl_ext
