/*
 * pcl_ext: registering a building scan to its 2D map, or to another scan, by plane
 * matching (Khoshelham & Gorte 2009).
 */
#pragma once

#include <pcl_ext/io/footprints.h>
#include <pcl_ext/registration/footprint_coverage.h>
#include <pcl_ext/registration/map_planes.h>
#include <pcl_ext/registration/plane_distances.h>
#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/plane_matching.h>

#include <pcl/registration/registration.h>

#include <limits>
#include <string>
#include <vector>

namespace pcl_ext {
/** \brief Registration of a building scan to a 2D map by plane matching (Khoshelham &
 * Gorte, "Registering pointclouds of polyhedral buildings to 2D maps", 3D-ARCH 2009).
 *
 * - Map planes (section 3.1): a wall on every footprint edge (eqs. 1-2, signed d) and a
 * floor, see computeMapPlanes; set with setFootprints() or setMapPlanes().
 * - Scan planes: any PlaneExtractor (default SACPlaneExtraction), fitted and turned to
 * the scanner side by fitScanPlanes(), or given with setSourcePlanes().
 * - Estimation (section 3.2, eqs. 8-12) projected onto a rigid (default) or similarity
 *   transform, see estimatePlaneTransformation; search (section 3.3) by initiate and
 * extend with the three constraints, see matchPlanes.
 * - Scan to scan (the paper's future work): without map planes, the target cloud's
 * planes are extracted the same way and play the map's part.
 * - Beyond the paper: with footprints and points known to lie over them (an airborne
 * scan's roofs, setCoverageIndices()), the candidate poses of the search are checked
 * against the whole map (FootprintCoverage, PlaneMatchingParameters::coverage_margin);
 * a scan that is not levelled is levelled from its planes (setEstimateVertical()), a
 * stepped ground by its flat patches (estimateFlatPatchNormal).
 *
 * Departures from the text are listed with each function (signed d, projection, offsets
 * at the data, sign handling, up-axis and extent checks, bounds around a guess).
 * align() works as for any pcl::Registration, also through a pcl::Registration pointer:
 * every check is made in computeTransformation() or when the input is set, and a
 * failure is a PCL_ERROR and hasConverged() == false. getFitnessScore() is the mean
 * distance between the matched planes after the transform, on the scan points (section
 * 4 measures the same distances for Tables 1-2). getFinalTransformation() maps the scan
 * into the map's local frame (map coordinates minus getLocalOrigin()), in float as
 * PCL's interface has it, and getFinalTransformationDouble() gives it in double. The
 * guess of align(output, guess) is in that frame too (a georeferenced scan: a
 * translation by -getLocalOrigin()) and is used only by the bounds of
 * setMaxRotationFromGuess() and setMaxTranslationFromGuess(). Deterministic for any
 * thread count.
 */
template <typename PointSource, typename PointTarget>
class PlaneMatchingRegistration
: public pcl::Registration<PointSource, PointTarget, float> {
public:
  using Base = pcl::Registration<PointSource, PointTarget, float>;
  using typename Base::Matrix4;
  using typename Base::PointCloudSource;
  using typename Base::PointCloudSourceConstPtr;
  using typename Base::PointCloudTarget;
  using Ptr = pcl::shared_ptr<PlaneMatchingRegistration<PointSource, PointTarget>>;
  using ConstPtr =
      pcl::shared_ptr<const PlaneMatchingRegistration<PointSource, PointTarget>>;

  PlaneMatchingRegistration();

  /** \brief The scan, as pcl::Registration::setInputSource, with the indices checked
   * against it (see setIndices()). An empty cloud is a PCL_ERROR, as there, but it is
   * kept, so that align() fails on it instead of registering the previous cloud again.
   */
  void
  setInputSource (const PointCloudSourceConstPtr& cloud) override;

  /** \brief The points of the scan to register, as PCLBase::setIndices; default: all.
   * The scan planes come from the indexed points only (their inlier indices still index
   * the input cloud). pcl::Registration::align copies the indexed points into its
   * output before computeTransformation() runs, so the indices are checked whenever
   * they or the source cloud are set: an index outside the cloud is a PCL_ERROR, the
   * indices are held back (getIndices() gives an empty set) until indices or cloud are
   * set again, and align() then fails (PCL_ERROR, empty output, not converged). Indices
   * changed through their pointer after being set must be set again. */
  void
  setIndices (const pcl::IndicesPtr& indices) override;
  void
  setIndices (const pcl::IndicesConstPtr& indices) override;
  void
  setIndices (const pcl::PointIndicesConstPtr& indices) override;
  /** \brief A block of an organised cloud, as PCLBase (which checks it against the
   * cloud). */
  using Base::setIndices;

  /** \brief The mean distance between the matched planes after the final transform, in
   * the units of the clouds (metres): for each pair of the match set, the root mean
   * square of the orthogonal distances of the scan plane's inlier points, moved by
   * getFinalTransformationDouble(), to its (infinite) map plane (scan to scan: the
   * target cloud's plane); then the mean over the pairs, each plane counting once. With
   * noise sigma on the points and the right pose it is about sigma; a wrong pose adds
   * its misalignment. This is not pcl::Registration's score (the mean squared distance
   * to the nearest target point, here the map's wall corners):
   * pcl::Registration::getFitnessScore is not virtual, so through a pcl::Registration
   * pointer that score is the one called.
   * \param[in] max_range inlier points farther than this from their map plane are left
   * out (default: none) \return the mean; std::numeric_limits<double>::max () when the
   * last align() did not converge or no matched plane has a finite inlier within \a
   * max_range (planes given by setSourcePlanes() without inliers) */
  double
  getFitnessScore (double max_range = std::numeric_limits<double>::max());
  /** \brief pcl::Registration's score of two sets of correspondence distances. */
  using Base::getFitnessScore;

  /** \brief The distances of Khoshelham & Gorte's Tables 1-2 after the last align():
   * computePlaneDistances on the source cloud, the scan planes, the target planes and
   * the match set, with getFinalTransformationDouble(). Unlike getFitnessScore(), every
   * inlier counts and the figures are per point and per pair (mean, maximum, RMS,
   * normal angle). After an align() that did not converge the match set is empty, and
   * so are \a metrics.
   * \param[out] metrics the distances (reset first)
   * \return false (PCL_ERROR, empty metrics) without a source cloud, or as
   * computePlaneDistances (scan planes set by setSourcePlanes() since align() that no
   * longer fit the match set) */
  bool
  getPlaneDistances (PlaneDistanceMetrics& metrics) const;

  /** \brief Map planes from footprints (section 3.1). The local origin is \a
   * parameters.origin, or when it is zero and \a choose_origin is true,
   * chooseLocalOrigin() (bounding-box centre rounded to metres); getLocalOrigin()
   * reports it. Sets a target cloud of the walls' corners so that pcl::Registration's
   * checks pass. \return false (PCL_ERROR, no map) on invalid footprints, see
   * computeMapPlanes */
  bool
  setFootprints (const std::vector<io::Footprint>& footprints,
                 const MapPlaneParameters& parameters = MapPlaneParameters(),
                 bool choose_origin = true);

  /** \brief Map planes given directly (local frame); also sets the corner target cloud.
   */
  void
  setMapPlanes (const std::vector<MapPlane>& planes,
                const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

  /** \brief Forget the map: register to the target cloud's planes (scan to scan). */
  void
  clearMap ();

  /** \brief Scan planes given directly, skipping extraction (their inliers index the
   * source). */
  void
  setSourcePlanes (const std::vector<ScanPlane>& planes)
  {
    source_planes_ = planes;
    source_planes_given_ = true;
  }

  /** \brief The plane extractor for the source (and, scan to scan, the target).
   * Default: SACPlaneExtraction with its defaults. The source extractor gets the whole
   * source cloud and the indices of setIndices (null without them); its planes must be
   * taken among them. */
  void
  setPlaneExtractor (const PlaneExtractor<PointSource>& extractor)
  {
    source_extractor_ = extractor;
  }
  void
  setTargetPlaneExtractor (const PlaneExtractor<PointTarget>& extractor)
  {
    target_extractor_ = extractor;
  }

  /** \brief Scanner positions of the source (and target) cloud, to orient scan normals;
   * default: each cloud's sensor origin. */
  void
  setSourceViewpoints (const ScanViewpoints& viewpoints)
  {
    source_viewpoints_ = viewpoints;
  }
  void
  setTargetViewpoints (const ScanViewpoints& viewpoints)
  {
    target_viewpoints_ = viewpoints;
  }

  /** \brief All search parameters at once (see PlaneMatchingParameters for defaults and
   * ranges). */
  void
  setMatchingParameters (const PlaneMatchingParameters& parameters)
  {
    parameters_ = parameters;
  }
  const PlaneMatchingParameters&
  getMatchingParameters () const
  {
    return parameters_;
  }

  /** \brief k, the pairs of an initial combination; default 4, range [3, 8] (paper: k).
   */
  void
  setInitialPairs (int k)
  {
    parameters_.k = k;
  }
  /** \brief m, the scan planes used to initiate; default 10, range [k, 64] (paper: m).
   */
  void
  setInitialScanPlanes (int m)
  {
    parameters_.scan_initial = m;
  }
  /** \brief n, the map planes used to initiate; default 10, range [k, 64] (paper: n).
   */
  void
  setInitialMapPlanes (int n)
  {
    parameters_.map_initial = n;
  }
  /** \brief Constraint 1, near-vertical/horizontal planes only; default on
   * (section 3.3). */
  void
  setVerticalConstraint (bool on)
  {
    parameters_.vertical_constraint = on;
  }
  /** \brief Constraint 2, relative orientation of the normals; default on
   * (section 3.3). */
  void
  setOrientationConstraint (bool on)
  {
    parameters_.orientation_constraint = on;
  }
  /** \brief Constraint 3, transformation residual of the initial pairs; default on. */
  void
  setResidualConstraint (bool on)
  {
    parameters_.residual_constraint = on;
  }
  /** \brief Estimate a similarity (eq. 5 with free s) instead of a rigid transform;
   * default off. */
  void
  setSimilarity (bool on)
  {
    parameters_.model =
        on ? PlaneTransformationModel::Similarity : PlaneTransformationModel::Rigid;
  }
  /** \brief Residual and extension tolerances: normal angle in degrees, (0, 90),
   * default 3; plane offset in metres, > 0, default 0.5 (the paper gives none; 2.5 x
   * its 20 cm noise). */
  void
  setTolerances (double angle_deg, double distance)
  {
    parameters_.angle_tolerance_deg = angle_deg;
    parameters_.distance_tolerance = distance;
  }
  /** \brief Use scan normals as oriented (scanner side) against outward walls; default
   * off. */
  void
  setOrientedNormals (bool on)
  {
    parameters_.oriented_normals = on;
  }
  /** \brief Beyond the paper: largest rotation, in degrees, between the estimate and
   * the guess given to align(output, guess); (0, inf], default infinity: no bound, the
   * paper's search of every pose, which ignores the guess. With a rough pose (GNSS/INS,
   * a georeferenced scan), a bound rejects the poses a repetitive street grid also fits
   * (a quarter turn onto the next block) and prunes the search. A value that is not
   * positive (or NaN) makes align() fail with a PCL_ERROR. */
  void
  setMaxRotationFromGuess (double degrees)
  {
    parameters_.max_rotation_from_guess_deg = degrees;
  }
  double
  getMaxRotationFromGuess () const
  {
    return parameters_.max_rotation_from_guess_deg;
  }
  /** \brief Beyond the paper: largest distance, in metres, between where the estimate
   * and the guess put the centre of the scan planes (the middle of the bounding box of
   * their centroids); (0, inf], default infinity: no bound. As setMaxRotationFromGuess.
   */
  void
  setMaxTranslationFromGuess (double metres)
  {
    parameters_.max_translation_from_guess = metres;
  }
  double
  getMaxTranslationFromGuess () const
  {
    return parameters_.max_translation_from_guess;
  }
  /** \brief Beyond the paper: estimate the scan's vertical direction from its planes
   * (estimateUpDirection) and level the scan planes before the search, so that
   * constraint 1 holds for a scan tilted by up to 20 degrees; default on. Registering
   * to a map only (scan to scan, both clouds are taken as they are). The final
   * transform includes the levelling, and a rigid one keeps its vertical: the rotation
   * of the match set is turned into the nearest rotation about the vertical and the
   * translation re-fitted (refineAboutVertical), so that the tilt comes from all the
   * scan's horizontal and vertical planes, not from the matched few. */
  void
  setEstimateVertical (bool on)
  {
    estimate_vertical_ = on;
  }
  bool
  getEstimateVertical () const
  {
    return estimate_vertical_;
  }
  /** \brief Beyond the paper: the points of the scan that lie over a footprint in plan
   * (an airborne scan's roof points, LAS class 6), indices into the source cloud;
   * default none. With them and a map set by setFootprints(), each candidate pose of
   * the search is scored by the share of these points (every (n / 4,096)-th of n,
   * rounded down: fewer than 8,192) it puts inside the footprints, and one whose share
   * falls short of the highest is not chosen (PlaneMatchingParameters::coverage_margin,
   * matchPlanes). An index outside the source cloud or a non-finite point is left out.
   */
  void
  setCoverageIndices (const pcl::IndicesConstPtr& indices)
  {
    coverage_indices_ = indices;
  }
  const pcl::IndicesConstPtr&
  getCoverageIndices () const
  {
    return coverage_indices_;
  }
  /** \brief The up direction found by the last align() in the scan frame ((0, 0, 1)
   * when not estimated). */
  const Eigen::Vector3d&
  getSourceUp () const
  {
    return source_up_;
  }
  /** \brief Threads of the search, 0 = all cores (default); the result does not depend
   * on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    parameters_.threads = threads;
  }

  /** \name Reports of the last align()
   * \{ */
  const std::vector<ScanPlane>&
  getSourcePlanes () const
  {
    return source_planes_;
  }
  /** \brief Map planes, or the target cloud's planes scan to scan. */
  const std::vector<Plane>&
  getTargetPlanes () const
  {
    return target_planes_;
  }
  const std::vector<MapPlane>&
  getMapPlanes () const
  {
    return map_planes_;
  }
  /** \brief Match set, its transform and residuals, and the Table 3 / figure 6 counts.
   */
  const PlaneMatchingResult&
  getMatchingResult () const
  {
    return result_;
  }
  /** \brief The final transform in double (scan to map - origin). */
  const Eigen::Matrix4d&
  getFinalTransformationDouble () const
  {
    return final_double_;
  }
  /** \brief The map's local origin (map coordinates = local + origin). */
  const Eigen::Vector3d&
  getLocalOrigin () const
  {
    return origin_;
  }
  /** \} */

protected:
  using Base::converged_;
  using Base::fake_indices_;
  using Base::final_transformation_;
  using Base::indices_;
  using Base::input_;
  using Base::reg_name_;
  using Base::source_cloud_updated_;
  using Base::target_;
  using Base::transformation_;

  void
  computeTransformation (PointCloudSource& output, const Matrix4& guess) override;

private:
  void
  setCornerTarget ();
  /** \brief The body of every setIndices overload: PCLBase's, then the check of
   * holdBackIndicesOutOfRange. */
  template <typename IndicesT>
  void
  setCheckedIndices (const IndicesT& indices);
  /** \brief Hold back indices that do not fit the source cloud, or restore held-back
   * ones that fit a new cloud; \a method names the caller in the PCL_ERROR. */
  void
  holdBackIndicesOutOfRange (const char* method);
  /** \brief Source plane sets by the extractor, from the indexed points when indices
   * are set. */
  bool
  extractSourcePlaneSets (std::vector<pcl::PointIndices>& sets) const;

  PlaneMatchingParameters parameters_;
  PlaneExtractor<PointSource> source_extractor_;
  PlaneExtractor<PointTarget> target_extractor_;
  ScanViewpoints source_viewpoints_, target_viewpoints_;
  std::vector<MapPlane> map_planes_;
  bool has_map_ = false;
  std::shared_ptr<const FootprintCoverage> coverage_; // the footprints' areas
  pcl::IndicesConstPtr coverage_indices_;
  std::vector<ScanPlane> source_planes_;
  bool source_planes_given_ = false;
  std::vector<ScanPlane> target_scan_planes_;
  std::vector<Plane> target_planes_;
  PlaneMatchingResult result_;
  pcl::IndicesPtr
      held_back_indices_; // indices out of range of the source, see setIndices
  Eigen::Matrix4d final_double_ = Eigen::Matrix4d::Identity();
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  bool estimate_vertical_ = true;
  Eigen::Vector3d source_up_ = Eigen::Vector3d::UnitZ();
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/registration/impl/plane_matching_registration.hpp>
#endif
