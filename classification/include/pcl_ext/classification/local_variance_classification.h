/*
 * pcl_ext: surface / edge / boundary classification by local variance (Belton & Lichti
 * 2006, section 2).
 */
#pragma once

#include <pcl_ext/common/noise_estimation.h>
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/features/centroid_offset_test_options.h>
#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/point_types.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

namespace pcl_ext {
/** \brief Labels every point surface, edge or boundary from the covariance of its
 * neighbourhood (Belton & Lichti 2006, section 2, eq. 1-8).
 *
 * The paper's workflow, in one pass over one neighbourhood search:
 * 1. curvature kappa = l0 / (l0 + l1 + l2) of each neighbourhood (eq. 4); points with
 *    kappa <= the curvature threshold are surface (the cheap test of section 2.2);
 * 2. points above it are re-checked by the variance of kappa over their neighbourhood
 *    (eq. 5): var(kappa) > the variance threshold makes an edge, otherwise they are
 * surface (curved but smooth, e.g. a pipe, section 2.2 and figure 1);
 * 3. surface points whose position is far from their neighbourhood's centroid are
 * boundary points (section 2.3, eq. 6-8; see pcl_ext::centroidOffsetStatistic). Each
 * test can run alone or in any combination (setTests): the curvature test alone calls
 * every point above the threshold an edge; the variance test alone checks every point;
 * the boundary test alone splits all points into boundary and surface.
 *
 * The covariance of each neighbourhood is computed once and used for kappa, the
 * boundary test and (through kappa) the variance test; the loops are OpenMP-parallel
 * (setNumberOfThreads) and the labels do not depend on the thread count.
 *
 * Output: classify() gives one pcl::Label per index with a pcl_ext::PointClass value
 * (1 surface, 2 edge, 3 boundary); extract() gives the indices of each class. Points
 * without a valid neighbourhood (non-finite, fewer than 3 neighbours, coincident or
 * collinear neighbours, fewer than 3 valid curvatures for eq. 5) are 0, "unknown".
 *
 * setDerivedSettings() estimates the noise about the surfaces from the cloud and
 * removes it from eq. 4-6 (setNoiseEstimation; see pcl_ext::estimateNoiseAndSpacing; a
 * cloud whose noise cannot be estimated gets the paper's eq. 4-6 with a PCL_WARN) and
 * sets the curvature threshold at the median kappa; setPaperSettings() restores every
 * value of the paper. Options beyond the paper, off by default: boundary labels over a
 * band of the neighbourhood
 * (setBoundaryBand, setBoundaryBandFraction), edges required to bend the normals
 * (setCreaseAngle) and the k neighbours capped at a radius (setMaxRadius). Together
 * (noise removed, band fraction 0.6, crease angle 70 degrees) they meet the surface,
 * edge and boundary goals on the generated scenes (docs/belton_lichti.md has the
 * figures).
 *
 * Departures from the text: eq. 6 is scaled by the neighbourhood size (see
 * pcl_ext::ChiSquaredBoundaryEstimation, setScaleByNeighbourhoodSize); with indices,
 * eq. 5 averages over the neighbours that are among the indices (only their kappa is
 * computed); the curvature threshold, which the paper leaves to the user, is derived
 * from the data by default (setCurvatureThreshold); optionally the noise about the
 * surfaces, given or estimated from the cloud, is removed from the smallest eigenvalue
 * before eq. 4-5 (setNoiseStandardDeviation, setNoiseEstimation; off by default).
 *
 * \code
 * pcl_ext::LocalVarianceClassification<pcl::PointXYZ> lvc;
 * lvc.setInputCloud (cloud);
 * lvc.setKSearch (50);
 * pcl::PointCloud<pcl::Label> labels;
 * lvc.classify (labels);
 * \endcode
 */
template <typename PointT>
class LocalVarianceClassification : public pcl::PCLBase<PointT>,
                                    public NeighbourhoodOptions<PointT>,
                                    public CentroidOffsetTestOptions {
public:
  using Ptr = pcl::shared_ptr<LocalVarianceClassification<PointT>>;
  using ConstPtr = pcl::shared_ptr<const LocalVarianceClassification<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using NeighbourhoodsConstPtr = typename Neighbourhoods<PointT>::ConstPtr;
  using SearchPtr = typename Neighbourhoods<PointT>::SearchPtr;

  /** \brief The tests of the workflow, combined with |. */
  enum Test : unsigned int {
    CURVATURE_TEST = 1, ///< kappa > curvature threshold (eq. 4)
    VARIANCE_TEST = 2,  ///< var(kappa) > variance threshold (eq. 5)
    BOUNDARY_TEST = 4,  ///< chi-squared centroid test (eq. 6-8)
    ALL_TESTS = 7
  };

  LocalVarianceClassification() = default;

  /** \brief The paper's settings: no noise removed (nor estimated), the variance
   * tolerance 1e-4, the curvature threshold 3 times the median kappa, confidence 0.95,
   * eq. 6 scaled by the neighbourhood size, no boundary band, no crease angle. */
  void
  setPaperSettings ()
  {
    curvature_threshold_ = 0.0;
    curvature_factor_ = 3.0;
    variance_threshold_ = 1e-4;
    noise_sigma_ = 0.0;
    estimate_noise_ = false;
    boundary_band_ = false;
    boundary_band_fraction_ = 1.0;
    crease_angle_ = 0.0;
    confidence_ = 0.95;
    scale_by_size_ = true;
  }

  /** \brief The paper's settings with what the method needs estimated from the cloud:
   * the noise about the surfaces estimated and removed from eq. 4-6
   * (setNoiseEstimation) and the curvature threshold at the median kappa (factor 1).
   * docs/belton_lichti.md has what they give on scenes they were not chosen on. */
  void
  setDerivedSettings ()
  {
    setPaperSettings();
    curvature_factor_ = 1.0;
    estimate_noise_ = true;
  }

  /** \brief Curvature threshold (the cheap test of section 2.2, on kappa of eq. 4).
   * Valid: >= 0. Default 0: derived from the data as factor * median(kappa)
   * (setCurvatureThresholdFactor), the median over the noise sample's twenty thousand
   * points chosen by position (sampleCurvatureMedian), which fixes it on a cloud of any
   * size and which the tiles of a cloud give exactly. Most points of a TLS scene lie on
   * smooth surfaces, so the median kappa is the noise level of a smooth surface at the
   * scene's typical spacing: for a plane with range noise sigma and neighbourhood
   * radius r (k = pi r^2 / s^2 at spacing s), kappa ~= 2 sigma^2 / r^2, which is also a
   * way to set it by hand. r varies with range, so one threshold cannot fit a whole TLS
   * scene: setNoiseStandardDeviation removes that part of kappa per neighbourhood.
   * Points below it are never re-checked, so a low value costs time, not accuracy.
   * getCurvatureThresholdUsed() gives the value of the last classify(). */
  void
  setCurvatureThreshold (double threshold)
  {
    curvature_threshold_ = threshold;
  }

  double
  getCurvatureThreshold () const
  {
    return curvature_threshold_;
  }

  /** \brief Multiple of the median kappa used when the curvature threshold is 0.
   * Valid: >= 0. Default 0: chosen from the cloud (curvatureFactorFor): 3, or 1 where
   * the noise estimated from the cloud exceeds kMaxNoiseToSpacing point spacings (a
   * range camera's frames). On such frames the crease points of boxes lie below 3
   * times the median, are never re-checked by eq. 5, and boxes and table grow into one
   * segment; on a scanner's cloud, where the noise is a small share of the spacing, 1
   * would have eq. 5 re-check the noisy faces too. setPaperSettings uses 3,
   * setDerivedSettings 1. getCurvatureThresholdFactorUsed() gives the last
   * classify()'s. */
  void
  setCurvatureThresholdFactor (double factor)
  {
    curvature_factor_ = factor;
  }

  double
  getCurvatureThresholdFactor () const
  {
    return curvature_factor_;
  }

  /** \brief Whether the cloud's noise \a estimate is valid and exceeds
   * kMaxNoiseToSpacing point spacings: a range camera's rather than a scanner's. */
  static bool
  isRangeCameraNoise (const NoiseEstimate& estimate)
  {
    return estimate.valid && estimate.sigma > kMaxNoiseToSpacing * estimate.spacing;
  }

  /** \brief The factor of setCurvatureThresholdFactor when it is chosen from the cloud,
   * given the cloud's noise \a estimate: 1 for a range camera's noise
   * (isRangeCameraNoise), else 3. */
  static double
  curvatureFactorFor (const NoiseEstimate& estimate)
  {
    return isRangeCameraNoise (estimate) ? 1.0 : 3.0;
  }

  /** \brief The noise sigma classify() removes when it estimates the noise
   * (setNoiseEstimation) and finds \a estimate: its sigma, or 0 when the estimate is
   * not valid or its noise exceeds kMaxNoiseToSpacing spacings. */
  static double
  noiseSigmaRemovedFor (const NoiseEstimate& estimate)
  {
    return estimate.valid && !(estimate.sigma > kMaxNoiseToSpacing * estimate.spacing)
               ? estimate.sigma
               : 0.0;
  }

  /** \brief The factor the last classify() used (0 when the threshold was set). */
  double
  getCurvatureThresholdFactorUsed () const
  {
    return curvature_factor_used_;
  }

  /** \brief The curvature threshold the last classify() used (derived or set). */
  double
  getCurvatureThresholdUsed () const
  {
    return curvature_threshold_used_;
  }

  /** \brief kappa (eq. 4) of every point of the input cloud as the last classify()
   * computed it (indexed like the cloud; NaN where not computed). */
  const std::vector<float>&
  getCurvatures () const
  {
    return kappa_;
  }

  /** \brief Variance-of-curvature tolerance (eq. 5): above it a point is an edge.
   * Default 1e-4 (the paper's, from user trials); valid: >= 0. */
  void
  setVarianceThreshold (double threshold)
  {
    variance_threshold_ = threshold;
  }

  double
  getVarianceThreshold () const
  {
    return variance_threshold_;
  }

  /** \brief Range noise standard deviation sigma of the scanner, in the cloud's units,
   * removed from the smallest eigenvalue before eq. 4-5: kappa = l0' / (l0' + l1 + l2)
   * with l0' = max(l0 - sigma^2, 0). Default: estimated from the cloud
   * (setNoiseEstimation), or 0 (the default): the paper's eq. 4 exactly. Setting a
   * value turns the estimate off. Valid: finite, >= 0.
   *
   * Why: range noise adds up to sigma^2 (its component along the normal) to l0 of every
   * neighbourhood, so a plane has kappa ~= sigma^2 / (l1 + l2), which depends on the
   * neighbourhood's extent, not on the surface. Near a scanner k neighbours span a few
   * centimetres, the noise dominates l0, and kappa and its variance (eq. 5) exceed the
   * paper's tolerance on flat walls (section 2.1 notes that the threshold depends on
   * range, incidence and the scanner's error, after Bae et al. 2005). A crease inside
   * the neighbourhood raises l0 by a fraction of the neighbourhood's squared extent,
   * far above sigma^2 wherever the neighbourhood is wider than a few sigma, so it still
   * reaches the tests. Give the scanner's range noise (for several scanners the
   * largest); overestimating it by half costs little. With it set, most surface points
   * get kappa = 0, so the derived curvature threshold is usually 0 and every point with
   * kappa above the noise floor is re-checked by eq. 5. Where all neighbourhoods have
   * the same extent (uniform density) the derived threshold already absorbs the noise
   * and this option can add false edges far from the creases (every crease point is an
   * edge either way). It pays on TLS scans, where the extent varies with range
   * (docs/belton_lichti.md has the figures of both cases).
   *
   * The boundary test (eq. 6) uses it too: the index point's own noise displaces it
   * from the centroid, so u^2 and v^2 are compared with l1 / n + sigma^2 and l2 / n +
   * sigma^2 instead of l1 / n and l2 / n (see pcl_ext::centroidOffsetStatistic). Where
   * k neighbours span a few centimetres this removes the false boundaries the noise
   * alone makes. */
  void
  setNoiseStandardDeviation (double sigma)
  {
    noise_sigma_ = sigma;
    estimate_noise_ = false;
  }

  double
  getNoiseStandardDeviation () const
  {
    return noise_sigma_;
  }

  /** \brief Noise above this many point spacings is estimated but not removed
   * (setNoiseEstimation). */
  static constexpr double kMaxNoiseToSpacing = 0.2;

  /** \brief Estimate the noise sigma of setNoiseStandardDeviation from the cloud
   * (pcl_ext::estimateNoiseFromSample over the neighbourhoods of the points of the
   * smallest position keys, pcl_ext::noiseSampleKeyOf: about 20,000, the same points
   * whatever the order of the cloud or the parts it is cut into). Default false
   * (setDerivedSettings turns it on); setNoiseStandardDeviation turns it off. When the
   * cloud does not let it estimate the noise, classify() says why (PCL_WARN) and
   * removes none: the paper's eq. 4-6. Noise above kMaxNoiseToSpacing point spacings
   * (a range camera's, where the spacing is about the noise) is not removed either: a
   * crease then shows in l0 by about as much as the noise, and removing the one
   * removes the other. */
  void
  setNoiseEstimation (bool estimate)
  {
    estimate_noise_ = estimate;
  }

  bool
  getNoiseEstimation () const
  {
    return estimate_noise_;
  }

  /** \brief The noise sigma the last classify() removed (estimated or set). */
  double
  getNoiseStandardDeviationUsed () const
  {
    return noise_sigma_used_;
  }

  /** \brief The last classify()'s estimate of the noise and the point spacing (not
   * valid when the noise was set, or when it could not be estimated: see its reason).
   */
  const NoiseEstimate&
  getNoiseEstimate () const
  {
    return noise_estimate_;
  }

  /** \brief Smallest crease an edge must show, as the angle between normals, in
   * radians: a point the variance test (eq. 5) calls an edge stays one only when some
   * neighbour's normal differs from its own by more than this angle; otherwise it goes
   * on through the workflow as a surface point (the boundary test). Default 0: off, the
   * paper's workflow; valid: 0 .. pi/2 (normals are unoriented, so angles above pi/2
   * are folded).
   *
   * Why: eq. 5 measures how much kappa (eq. 4) varies, and on a curved surface kappa
   * also varies with the shape of the neighbourhood, not only with a crease: next to a
   * shadow or the end of a pipe the neighbourhood becomes one-sided and kappa changes,
   * though every normal in it lies on one smooth cylinder. The paper's own
   * principal-direction analysis (section 5) and its closing remark (interrogating
   * index points "with regards to the principle curvature directions, not just the
   * normal directions") point to the normals for this. The angle is the widest between
   * two normals of the neighbourhood (each the eigenvector of l0 of its own
   * neighbourhood, already computed), found in two passes over the neighbours of each
   * edge candidate: from the point's own normal to the farthest, then from that to the
   * farthest from it (on a crease the point's own normal is a blend of the two faces').
   * Near a crease those normals are blends too, so a right angle shows as less: pi/4
   * keeps nearly every right-angled crease of walls, boxes and beams, and larger angles
   * trade crease points for fewer false edges on curved surfaces (docs/belton_lichti.md
   * has the edge F1 for several angles). */
  void
  setCreaseAngle (double radians)
  {
    crease_angle_ = radians;
  }

  double
  getCreaseAngle () const
  {
    return crease_angle_;
  }

  /** \brief Give the boundary class the reach of the edge class. Default false (the
   * paper): a point is boundary when it fails eq. 6 itself, which happens within about
   * half a neighbourhood radius of a border (farther in, the missing side moves the
   * centroid too little). true: surface points with such a point among their neighbours
   * are boundary too, so that, like an edge point (whose neighbourhood reaches across a
   * crease), a boundary point is one whose neighbourhood reaches the border. */
  void
  setBoundaryBand (bool band)
  {
    boundary_band_ = band;
  }

  bool
  getBoundaryBand () const
  {
    return boundary_band_;
  }

  /** \brief The share of each neighbourhood, nearest neighbours first, that the
   * boundary band reaches through (setBoundaryBand): a surface point becomes boundary
   * when one of its nearest ceil(fraction * size) neighbours fails eq. 6. Default 1:
   * the whole neighbourhood; valid: 0 < fraction <= 1.
   *
   * Eq. 6 fires within about half a neighbourhood radius of a border, so the whole
   * neighbourhood carries the band to about 1.5 radii, past the points whose
   * neighbourhood reaches the border; a fraction below 1 stops it nearer
   * (docs/belton_lichti.md has the boundary F1 for several fractions). */
  void
  setBoundaryBandFraction (double fraction)
  {
    boundary_band_fraction_ = fraction;
  }

  double
  getBoundaryBandFraction () const
  {
    return boundary_band_fraction_;
  }

  /** \brief Which tests run, a combination of Test flags. Default ALL_TESTS (the
   * paper's workflow); valid: any non-empty combination. */
  void
  setTests (unsigned int tests)
  {
    tests_ = tests;
  }

  unsigned int
  getTests () const
  {
    return tests_;
  }

  /** \brief One label per index: a pcl_ext::PointClass value (0 unknown, 1 surface, 2
   * edge, 3 boundary). Empty after a PCL_ERROR on bad input or parameters. */
  void
  classify (pcl::PointCloud<pcl::Label>& labels);

  /** \brief The indices of each class: \a clusters[c] lists the points of PointClass c,
   * so there are always kNumPointClasses lists (unknown first), some maybe empty. Empty
   * after a PCL_ERROR. */
  void
  extract (std::vector<pcl::PointIndices>& clusters);

protected:
  using NeighbourhoodOptions<PointT>::threads_;
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Parameter checks; PCL_ERROR and false on the first bad one. */
  bool
  checkParameters () const;

  /** \brief Pass 1: kappa per point (NaN without a tangent plane) and the eq. 6
   * statistic per row. */
  template <bool dense>
  void
  computeCovariances (const Neighbourhoods<PointT>& nb);

  /** \brief Pass 2: the label of each row from kappa, var(kappa) and the statistic. */
  void
  label (const Neighbourhoods<PointT>& nb, pcl::PointCloud<pcl::Label>& labels) const;

  /** \brief Pass 3 (setBoundaryBand): surface rows with a boundary neighbour among
   * their nearest (setBoundaryBandFraction) become boundary. */
  void
  widenBoundaries (const Neighbourhoods<PointT>& nb,
                   pcl::PointCloud<pcl::Label>& labels) const;

  /** \brief The factor times the median kappa of the noise sample (with the noise
   * removed): sampleCurvatureMedian. */
  double
  deriveCurvatureThreshold () const;

  /** \brief The noise sample's neighbourhoods (noiseSampleKeyOf): what the noise and
   * spacing (setNoiseEstimation, or the curvature factor chosen from the cloud) and
   * the median kappa of a derived curvature threshold are estimated from. */
  template <bool dense>
  void
  sampleNeighbourhoods (const Neighbourhoods<PointT>& nb);

  /** \brief The noise sigma to remove from the estimate (setNoiseEstimation). */
  void
  removeEstimatedNoise ();

  /** \brief setCreaseAngle: cosine of the widest angle between two normals of a row. */
  template <typename Row>
  float
  widestNormalCosine (const Row& nn, const Eigen::Vector3f& own) const;

  double curvature_threshold_ = 0.0;
  double curvature_factor_ = 0.0;
  double curvature_factor_used_ = 0.0;
  double curvature_threshold_used_ = 0.0;
  double variance_threshold_ = 1e-4;
  double noise_sigma_ = 0.0;
  bool estimate_noise_ = false;
  double noise_sigma_used_ = 0.0;
  NoiseEstimate noise_estimate_;
  std::vector<KeyedSpread> noise_sample_; ///< during classify()
  bool boundary_band_ = false;
  double boundary_band_fraction_ = 1.0;
  double crease_angle_ = 0.0;
  unsigned int tests_ = ALL_TESTS;

  std::vector<float> kappa_;     ///< per point of the cloud; NaN when not computed
  std::vector<float> statistic_; ///< eq. 6 per row
  std::vector<Eigen::Vector3f>
      normals_; ///< per point of the cloud, with setCreaseAngle
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/classification/impl/local_variance_classification.hpp>
#endif
