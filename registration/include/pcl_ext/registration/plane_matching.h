/*
 * pcl_ext: the initiate-and-extend plane matching of Khoshelham & Gorte (2009),
 * section 3.3.
 */
#pragma once

#include <pcl_ext/registration/plane_transformation_estimation.h>
#include <pcl_ext/registration/planes.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace pcl_ext {
/** \brief Parameters of matchPlanes (defaults follow the paper where it gives a value).
 */
struct PlaneMatchingParameters {
  int k = 4; ///< initial pairs per combination, >= 3 (paper: k = 4, Table 3 also 3)
  int scan_initial = 10; ///< m: scan planes used to initiate, >= k (paper: 7-12)
  int map_initial = 10;  ///< n: map planes used to initiate, >= k (paper: 7-12)
  bool vertical_constraint =
      true; ///< constraint 1: only near-vertical/horizontal planes
  bool orientation_constraint =
      true; ///< constraint 2: relative orientation of the normals
  bool residual_constraint =
      true; ///< constraint 3: transformation residual of the k pairs
  /** \brief Beyond the paper: the initial planes are chosen for matching, not by size:
   * the largest horizontal plane (it fixes the height), then the vertical planes
   * longest in plan (the walls a footprint edge can match), then the others largest
   * first. false: the largest planes (the paper's choice), where ground, roof and
   * superfluous planes crowd out the walls at small m and n. */
  bool walls_first = true;
  double vertical_tolerance_deg = 10.0; ///< constraint 1 tolerance, (0, 45) degrees
  double orientation_tolerance_deg =
      5.0; ///< constraint 2: angle difference, (0, 90) degrees
  double angle_tolerance_deg =
      3.0; ///< residual and extension: normal angle, (0, 90) degrees
  double distance_tolerance = 0.5; ///< residual and extension: plane offset (m), > 0
  /** \brief Whether plane signs are meaningful (scan normals turned to the scanner
   * side, map walls facing out of the building, floor up). false (default) treats (n,
   * d) and (-n, -d) as one plane and picks the sign of each pair from the transform (an
   * extracted plane has no natural sign). */
  bool oriented_normals = false;
  /** \brief Beyond the paper: reject pairs whose bounding boxes, the scan one
   * transformed, do not overlap within \a extent_margin. Coplanar walls (the two wings
   * of an H) are distinct map planes; without it a superfluous plane in line with one
   * wing can take the other. */
  bool check_extents = true;
  double extent_margin = 2.0; ///< slack of the extent test (m), >= 0
  /** \brief Beyond the paper: bounds around an initial guess of the pose (a rough
   * GNSS/INS or georeferenced pose). Every estimate, initial or extended, whose
   * rotation differs from the guess's by more than \a max_rotation_from_guess_deg, or
   * that puts the centre of the scan planes (the middle of the bounding box of their
   * centroids) farther than \a max_translation_from_guess from where the guess puts it,
   * is rejected. Both (0, inf]; infinity (the default) is the paper's global search,
   * which ignores the guess. */
  double max_rotation_from_guess_deg = std::numeric_limits<double>::infinity();
  double max_translation_from_guess =
      std::numeric_limits<double>::infinity(); ///< metres
  /** \brief Beyond the paper: a symmetric footprint has several equally good poses.
   * Every match set of another pose (more than 1 degree or 1 m from those before it)
   * with at most \a ambiguity_pairs fewer matches than the best, and whose scan planes
   * that the best does not pair hold at least \a ambiguity_support times the inliers of
   * those the best pairs and it does not, is reported in
   * PlaneMatchingResult::candidates; >= 0, default 0 (as many matches as the best), and
   * [0, 1], default 0.5 (the poses of a symmetric map pair the same scan planes; a
   * ceiling seen through the windows in the floor's place has a fraction of the
   * ground's inliers). */
  int ambiguity_pairs = 0;
  double ambiguity_support = 0.5;
  /** \brief Beyond the paper, with a pose score (see matchPlanes, e.g. the share of an
   * airborne scan's roof points a pose puts over the footprints, FootprintCoverage):
   * among the match sets of distinct poses with at most \a coverage_pairs fewer matches
   * than the best, the first in the best-first order whose score is within \a
   * coverage_margin of the highest is the result; the others below that are not
   * candidates. Defaults 1 and 0.1, from the shares of the candidates on the AHN
   * tuning tile (docs/khoshelham_gorte.md): the quarter and half turns of a tile put
   * far fewer roof points over the footprints than the poses near the truth, which
   * differ among themselves by less than the margin. >= 0, and [0, 1]. */
  int coverage_pairs = 1;
  double coverage_margin = 0.1;
  int min_matches = 0;            ///< least final matches to converge; 0 = k
  double min_conditioning = 1e-2; ///< degeneracy threshold of the normals, (0, 1)
  PlaneTransformationModel model = PlaneTransformationModel::Rigid;
  unsigned int threads = 0; ///< 0 = all cores; the result does not depend on it
};

/** \brief Search statistics: the numbers of initial combinations of Table 3 and
 * figure 6. */
struct PlaneMatchingStatistics {
  int m = 0, n = 0, k = 0;         ///< values used (m, n capped by the plane counts)
  std::uint64_t unconstrained = 0; ///< eq. 13: C(m, k) P(n, k)
  std::uint64_t vertical = 0;      ///< after constraint 1 (= unconstrained if off)
  /** \brief After constraints 1-2 (enumerated). With bounds around the guess, only the
   * pairs those bounds can accept are enumerated (see matchPlanes), so the count is
   * smaller than the paper's Table 3 for the same planes. */
  std::uint64_t orientation = 0;
  std::uint64_t degenerate = 0;  ///< of those, normals not spanning 3D: not estimated
  std::uint64_t residual = 0;    ///< after constraints 1-3 (and the bounds): extended
  std::uint64_t estimations = 0; ///< transformation estimates computed in all
  double seconds = 0.0;          ///< wall time of the search and estimation
};

/** \brief A match set and its transform. */
struct PlaneMatchingCandidate {
  std::size_t support = 0; ///< inliers of the matched scan planes
  std::vector<PlanePair> matches;
  PlaneTransformationResult estimate;
};

/** \brief Result of matchPlanes. */
struct PlaneMatchingResult {
  bool converged = false;
  std::vector<PlanePair> matches;     ///< the best match set, initial pairs first
  PlaneTransformationResult estimate; ///< transform and residuals of the best match set
  /** \brief The best match set first, then those of other poses supported nearly as
   * well (PlaneMatchingParameters::ambiguity_pairs), best first: more than one means
   * the map cannot tell these poses apart (a symmetric footprint). */
  std::vector<PlaneMatchingCandidate> candidates;
  PlaneMatchingStatistics statistics;
};

/** \brief Plane matching by initiate and extend (Khoshelham & Gorte 2009, section 3.3).
 *
 * The first m scan planes and n map planes (walls first, see \a walls_first; or the
 * largest, by support for the scan and by extent for the map, as the paper) form
 * all combinations of k pairs (eq. 13), pruned by the enabled constraints:
 * 1. near-vertical planes pair with vertical ones and near-horizontal with horizontal
 * ones, others are left out (|n_z| against \a vertical_tolerance_deg). The constraint
 * rests on a levelled scanner, so pcl_ext also requires the transform to keep the
 * scan's up axis within that tolerance of the map's: without it a plane set and its
 * image turned upside down about the floor are the same unoriented planes, and a
 * mirror-symmetric plan matches both ways;
 * 2. relative orientation: the angle between any two scan normals of a combination
 * equals that of their map normals within \a orientation_tolerance_deg (Gorte et al.
 * 2008);
 * 3. transformation residual: every pair fits the transform estimated from the k pairs
 * within \a angle_tolerance_deg and \a distance_tolerance. The paper applies it for k >
 * 3 only, since its affine fit of 3 planes is exact; the projected rigid fit is not, so
 * it applies for k = 3 too. Combinations whose map normals do not span 3D are counted
 * as degenerate and skipped. Before its estimate, each sign pattern of a combination is
 * screened by necessary conditions of constraint 3 that need no estimate (see
 * plane_matching_scoring.cpp): for four pairs, the combination of their distance rows
 * that cancels the translation must stay within what the tolerances allow, and under
 * constraint 1 no near-horizontal pair may turn the up axis over. They skip most
 * estimates (docs/khoshelham_gorte.md has the counts on the building scene) and never
 * reject a combination the estimate would accept, so the counts and the result are
 * those of estimating every combination.
 * Each surviving combination is extended: every other scan plane (all of them, largest
 * first) is transformed to the map and paired with the most similar unused map plane;
 * the pair is kept if the transform re-estimated with it keeps every residual within
 * the tolerances. Passes repeat until nothing is added. Best = most matches, then most
 * support (inliers of the matched scan planes), then least residual norm, then first in
 * enumeration order (so the result does not depend on the thread count). With one floor
 * in the map, the ground and a ceiling seen through the windows give match sets of
 * equal size: the support (the ground has far more points) tells them apart, as do
 * oriented normals (the ceiling faces down).
 *
 * Bounds around a guess (beyond the paper, off by default): with \a
 * max_rotation_from_guess_deg or \a max_translation_from_guess finite, an estimate
 * farther from \a guess is rejected like one breaking constraint 3, at initiation and
 * at every extension step. The paper searches the whole pose space, which on a street
 * grid of parallel walls also fits a quarter turn onto the next block; a user with a
 * rough pose knows better. With the residual constraint on, the bounds also prune
 * before estimating, by necessary conditions (as the screens above, they never reject a
 * combination the bounds and the tolerances would accept):
 * - an initial pair is enumerated only if the guess's rotation brings the scan normal
 * within \a angle_tolerance_deg plus the rotation bound of the map normal, and (rigid
 * model, translation bounded) the guess brings the scan plane's anchor within \a
 * distance_tolerance + the translation bound + 2 sin(rotation bound / 2) times the
 *   anchor's distance from the centre of the scan planes;
 * - with extents checked (rigid model, translation bounded), a map plane whose extent
 * the bounds cannot bring within \a extent_margin of the scan planes' bounding box
 * neither initiates nor extends: the n initial map planes are the largest of the
 * others.
 *
 * Sign handling (extracted planes have no natural sign, and the paper does not say how
 * to choose one): without \a oriented_normals, each initial combination is tried with
 * every sign pattern consistent with constraint 2 and with the handedness of its
 * normals (a rotation keeps the sign of det(n_i, n_j, n_l); a pattern whose affine
 * block still has a negative determinant is replaced by its mirror, all signs flipped),
 * and extension picks the sign agreeing with the current transform.
 *
 * \param[in] scan planes in the source frame
 * \param[in] map planes in the target frame
 * \param[in] parameters see PlaneMatchingParameters
 * \param[out] result the match set, transform and statistics
 * Pose score (beyond the paper, none by default): with \a pose_score, the match sets
 * of distinct poses within \a coverage_pairs of the best are scored, and the first of
 * them, best first, that scores within \a coverage_margin of the highest is the
 * result; the candidates are then chosen around it as above, among those that pass the
 * same test. A match set's count of pairs cannot tell the pose of a whole block from
 * its half turn when the walls are roof outlines a few degrees off; what the map says
 * about the rest of the scan can.
 *
 * \param[in] scan planes in the source frame
 * \param[in] map planes in the target frame
 * \param[in] parameters see PlaneMatchingParameters
 * \param[out] result the match set, transform and statistics
 * \param[in] guess an initial scan-to-map pose, used only by the bounds of \a
 * parameters
 * \param[in] pose_score a score of a scan-to-map pose, higher is better (for instance
 * FootprintCoverage::share); empty: none
 * \return result.converged; false with a PCL_ERROR for invalid parameters, too few or
 * non-finite planes, a non-finite guess, or when no combination yields a valid
 * transform
 */
bool
matchPlanes (const std::vector<Plane>& scan,
             const std::vector<Plane>& map,
             const PlaneMatchingParameters& parameters,
             PlaneMatchingResult& result,
             const Eigen::Matrix4d& guess = Eigen::Matrix4d::Identity(),
             const std::function<double (const Eigen::Matrix4d&)>& pose_score = {});

/** \brief Eq. 13: C(m, k) P(n, k), saturating at the largest std::uint64_t. */
std::uint64_t
countInitialCombinations (int m, int n, int k);

/** \brief Whether \a parameters are valid; PCL_ERROR naming the first bad one if not.
 */
bool
checkPlaneMatchingParameters (const PlaneMatchingParameters& parameters);
} // namespace pcl_ext
