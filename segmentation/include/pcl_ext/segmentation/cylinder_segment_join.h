/*
 * pcl_ext: joining the segments that lie on one cylinder (pipes cut at their supports).
 */
#pragma once

#include <pcl_ext/segmentation/cylinder_join.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cmath>
#include <optional>
#include <vector>

namespace pcl_ext {
/** \brief Joins the segments of a segmentation that lie on one cylinder or cone: the
 * straight runs of a pipe cut apart where it rests on its supports, the legs of an
 * elbow, the pieces of a tree trunk cut where branches leave it.
 *
 * Sithole & Mapurisa (section 5.2.1, figure 12) segment pipe racks into pipes and note
 * that "from the data structure it is possible to obtain the axes ... in the pipes",
 * which they do not elaborate; of a tree (figure 14) they find "the trunk and larger
 * branches". This class does it after any segmenter (ProfileSegmentation,
 * pcl::EuclideanClusterExtraction, pcl::RegionGrowing). Where a pipe rests on a beam, a
 * scanner below sees only its underside next to the beam, and a segmenter that cuts at
 * creases (curve fitting) cuts the pipe there into its spans; a thin trunk splits where
 * branches leave it. Not in the paper.
 *
 * Each input segment is searched for cylinders or cones without normals
 * (cylinders::detectCylinders: hypotheses from local patches, grown along the axis and
 * refined by Gauss-Newton, kept when the points near the surface lie on it, so planes
 * and box faces are rejected); a segment can hold several (two pipes side by side). Two
 * pieces are joined when they continue one another (cylinder_join::continues): parallel
 * axes, each passing through the other's facing end, radii where they face each other
 * within the allowed difference and a gap along the axis no longer than the maximum; or
 * the two legs of an elbow, axes meeting near both ends. The pieces of a straight run
 * are then refitted as one cylinder (or cone) over all their inliers: a piece alone is
 * often a short strip seen from one side (a pipe's underside next to a support), whose
 * radius its points fix poorly (docs/sithole_mapurisa.md). A segment whose pieces all
 * joined one group and cover at least the whole-segment fraction of it joins that group
 * whole; otherwise only the points on its pieces move, and the rest stays a segment.
 * Last, a segment in which no piece was found joins a group when most of its points lie
 * on one of the group's pieces (the fragments at a trunk's branch junctions).
 *
 * The lengths default to multiples of the average point spacing of the segments'
 * points (profiles::estimatePointSpacing, or setPointSpacing), so that the join needs
 * no setting in the cloud's units: the inlier band 0.6 spacings, radii from 0.8 to 24
 * spacings, gaps up to 80 spacings, and hypotheses drawn from patches of 24 spacings
 * (at 0.025 m, the spacing of the generated \c pipes scene: 0.015 m, 0.02 to 0.6 m,
 * 2 m and 0.6 m). Each can be set in the cloud's units instead. Work is per segment
 * and parallel (OpenMP);
 * the result does not depend on the number of threads, and the random draws are seeded
 * (setSeed). Points with non-finite coordinates are never fitted and go with most of
 * their segment.
 *
 * docs/sithole_mapurisa.md reports what the join measures on the generated \c pipes and
 * \c tree scenes after curve fitting.
 */
template <typename PointT>
class CylinderSegmentJoin : public pcl::PCLBase<PointT> {
public:
  using PointCloud = pcl::PointCloud<PointT>;
  using Ptr = pcl::shared_ptr<CylinderSegmentJoin<PointT>>;
  using ConstPtr = pcl::shared_ptr<const CylinderSegmentJoin<PointT>>;

  /** \brief A cylinder found in an input segment, with its inliers as cloud indices. */
  struct JoinedCylinder {
    /** \brief Axis point, direction, radius, extent, inliers; when joined in a
     * straight run, the run's axis, radius and taper over the piece's extent. */
    cylinders::Cylinder cylinder;
    std::size_t input_segment; ///< index into the input segments
    int output_segment;        ///< index into the output of join(); -1 when not joined
  };

  CylinderSegmentJoin() = default;

  /** \brief The segmentation to refine (indices into the input cloud). */
  void
  setInputSegments (const std::vector<pcl::PointIndices>& segments)
  {
    segments_ = segments;
  }
  const std::vector<pcl::PointIndices>&
  getInputSegments () const
  {
    return segments_;
  }

  /** \brief Average point spacing the default lengths are multiples of. Default 0:
   * estimated from the segments' points (profiles::estimatePointSpacing); pass the
   * segmenter's (ProfileSegmentation::getUsedPointSpacing) to skip the estimate; valid:
   * 0 or > 0. */
  void
  setPointSpacing (double spacing)
  {
    spacing_ = spacing;
  }
  double
  getPointSpacing () const
  {
    return spacing_;
  }

  /** \brief Inlier band around a cylinder's surface, in the cloud's units (valid: >
   * 0); unset by default: 0.6 point spacings (setDistanceToleranceFactor). */
  void
  setDistanceTolerance (double tolerance)
  {
    tolerance_ = tolerance;
  }
  /** \brief The tolerance set in the cloud's units; 0 when it follows the spacing. */
  double
  getDistanceTolerance () const
  {
    return tolerance_.value_or (0.0);
  }
  /** \brief Inlier band in point spacings when no tolerance is set. Default 0.6 (three
   * times the 5 mm range noise of the generated scenes at their 0.025 m). */
  void
  setDistanceToleranceFactor (double factor)
  {
    tolerance_factor_ = factor;
    tolerance_.reset();
  }
  double
  getDistanceToleranceFactor () const
  {
    return tolerance_factor_;
  }

  /** \brief Radii of the cylinders looked for, in the cloud's units (valid: 0 < min <=
   * max); unset by default: 0.8 to 24 point spacings (setRadiusLimitFactors). */
  void
  setRadiusLimits (double min_radius, double max_radius)
  {
    min_radius_ = min_radius;
    max_radius_ = max_radius;
  }
  /** \brief The radii set in the cloud's units; 0 when they follow the spacing. */
  void
  getRadiusLimits (double& min_radius, double& max_radius) const
  {
    min_radius = min_radius_.value_or (0.0);
    max_radius = max_radius_.value_or (0.0);
  }
  /** \brief Radii in point spacings when none are set. Default 0.8 and 24: a
   * cylinder thinner than a spacing has too few points around it to be told from a
   * line, and the largest is half the patch. */
  void
  setRadiusLimitFactors (double min_factor, double max_factor)
  {
    min_radius_factor_ = min_factor;
    max_radius_factor_ = max_factor;
    min_radius_.reset();
    max_radius_.reset();
  }
  void
  getRadiusLimitFactors (double& min_factor, double& max_factor) const
  {
    min_factor = min_radius_factor_;
    max_factor = max_radius_factor_;
  }

  /** \brief Longest gap bridged between two pieces of a straight run, or from a leg's
   * end to where the axes of an elbow meet, in the cloud's units (valid: >= 0); unset
   * by default: 80 point spacings (setMaxGapFactor). */
  void
  setMaxGap (double gap)
  {
    max_gap_ = gap;
  }
  /** \brief The gap set in the cloud's units; -1 when it follows the spacing. */
  double
  getMaxGap () const
  {
    return max_gap_.value_or (-1.0);
  }
  /** \brief Longest gap in point spacings when none is set. Default 80 (a support and
   * the band of curve ends on either side of it). */
  void
  setMaxGapFactor (double factor)
  {
    max_gap_factor_ = factor;
    max_gap_.reset();
  }
  double
  getMaxGapFactor () const
  {
    return max_gap_factor_;
  }

  /** \brief Largest angle between the axes of one straight run, in radians. Default 5
   * degrees; valid: [0, pi/2). */
  void
  setMaxAxisAngle (double angle)
  {
    parameters_.max_axis_angle = angle;
  }
  double
  getMaxAxisAngle () const
  {
    return parameters_.max_axis_angle;
  }

  /** \brief Smallest angle between the legs of an elbow, in radians. Default 30
   * degrees; valid: (max axis angle, pi/2]. Fitted axes are never exactly square: a
   * value at pi/2 joins no elbow, 80 degrees the right-angled ones. */
  void
  setMinElbowAngle (double angle)
  {
    parameters_.min_elbow_angle = angle;
  }
  double
  getMinElbowAngle () const
  {
    return parameters_.min_elbow_angle;
  }

  /** \brief Largest difference of two joined radii, as a share of the larger. Default
   * 0.3; valid: [0, 1). */
  void
  setMaxRadiusDifference (double share)
  {
    parameters_.max_radius_difference = share;
  }
  double
  getMaxRadiusDifference () const
  {
    return parameters_.max_radius_difference;
  }

  /** \brief How far one axis may pass from the other's end, in radii (plus the distance
   * tolerance). Default 0.3; valid: >= 0. */
  void
  setMaxAxisOffset (double radii)
  {
    parameters_.max_axis_offset = radii;
  }
  double
  getMaxAxisOffset () const
  {
    return parameters_.max_axis_offset;
  }

  /** \brief Radius of the patch a cylinder hypothesis is drawn from, in the cloud's
   * units (valid: > 0; at least twice the largest radius: the patch must be longer than
   * wide); unset by default: 24 point spacings (setNeighbourhoodRadiusFactor). */
  void
  setNeighbourhoodRadius (double radius)
  {
    neighbourhood_radius_ = radius;
  }
  /** \brief The patch radius set in the cloud's units; 0 when it follows the spacing.
   */
  double
  getNeighbourhoodRadius () const
  {
    return neighbourhood_radius_.value_or (0.0);
  }
  /** \brief Patch radius in point spacings when none is set. Default 24. */
  void
  setNeighbourhoodRadiusFactor (double factor)
  {
    neighbourhood_factor_ = factor;
    neighbourhood_radius_.reset();
  }
  double
  getNeighbourhoodRadiusFactor () const
  {
    return neighbourhood_factor_;
  }

  /** \brief Hypotheses drawn per cylinder, and how many of the best are grown. Default
   * 300 and 20; valid: >= 1. */
  void
  setNumberOfHypotheses (unsigned int drawn, unsigned int grown)
  {
    parameters_.detection.hypotheses = drawn;
    parameters_.detection.refined_hypotheses = grown;
  }
  unsigned int
  getNumberOfHypotheses () const
  {
    return parameters_.detection.hypotheses;
  }

  /** \brief Fewest points on a cylinder. Default 40; valid: >= 3. */
  void
  setMinCylinderSize (std::size_t points)
  {
    parameters_.detection.min_points = points;
  }
  std::size_t
  getMinCylinderSize () const
  {
    return parameters_.detection.min_points;
  }

  /** \brief The surface test: of the points within three tolerances of a cylinder's
   * surface, the share that must lie within one. Default 0.9; valid: [0, 1]. A pipe
   * seen from outside has nearly all of them on its surface; a cylinder that rounds the
   * corner of a box column or a beam grazes its faces and has far fewer. */
  void
  setMinSurfaceFraction (double share)
  {
    parameters_.detection.min_surface_fraction = share;
  }
  double
  getMinSurfaceFraction () const
  {
    return parameters_.detection.min_surface_fraction;
  }

  /** \brief Largest taper (change of the radius per unit length along the axis) fitted:
   * 0 fits cylinders only; above, cones too (a tree trunk narrows upwards), and radii
   * are compared where two pieces face each other. Default 0.1; valid: [0, 1). */
  void
  setMaxTaper (double taper)
  {
    parameters_.detection.max_taper = taper;
  }
  double
  getMaxTaper () const
  {
    return parameters_.detection.max_taper;
  }

  /** \brief Cylinders looked for per segment. Default 8; valid: >= 1. */
  void
  setMaxCylindersPerSegment (unsigned int count)
  {
    parameters_.detection.max_cylinders = count;
  }
  unsigned int
  getMaxCylindersPerSegment () const
  {
    return parameters_.detection.max_cylinders;
  }

  /** \brief A segment moves whole into the group of its pieces when they cover at least
   * this share of it (and belong to one group). Default 0.5; valid: [0, 1]. */
  void
  setWholeSegmentFraction (double share)
  {
    parameters_.whole_segment_fraction = share;
  }
  double
  getWholeSegmentFraction () const
  {
    return parameters_.whole_segment_fraction;
  }

  /** \brief A segment in which no cylinder was found joins a group when at least this
   * share of its points lies on the surface of one of the group's pieces (within the
   * tolerance, along the piece or within the maximum gap of its ends). Default 0.5;
   * valid: [0, 1] (0: off). */
  void
  setAbsorbFraction (double share)
  {
    parameters_.absorb_fraction = share;
  }
  double
  getAbsorbFraction () const
  {
    return parameters_.absorb_fraction;
  }

  /** \brief Seed of the random draws. Default 1. */
  void
  setSeed (std::uint64_t seed)
  {
    parameters_.detection.seed = seed;
  }
  std::uint64_t
  getSeed () const
  {
    return parameters_.detection.seed;
  }

  /** \brief OpenMP threads; 0 = all cores (default). Results do not depend on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }
  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

  /** \brief Join the input segments that lie on one cylinder.
   * \param[out] segments the joined segmentation, largest first (points in no input
   * segment stay out); empty on error (with a PCL_ERROR) */
  void
  join (std::vector<pcl::PointIndices>& segments);

  /** \brief Whether a length follows the point spacing (is not set in the cloud's
   * units), so that join() needs the spacing. */
  bool
  getLengthsFollowSpacing () const
  {
    return !tolerance_ || !min_radius_ || !max_radius_ || !max_gap_ ||
           !neighbourhood_radius_;
  }

  /** \brief The settings join() runs with where the point spacing is \a spacing: the
   * lengths not set in the cloud's units are their factors times it, and the threads
   * resolved (0: all cores). For a caller that runs the join over segments it reads
   * one at a time (cylinder_join::joinSegments). */
  cylinder_join::JoinParameters
  getParameters (double spacing) const;

  /** \brief The cylinders found by the last join(). */
  const std::vector<JoinedCylinder>&
  getCylinders () const
  {
    return cylinders_;
  }

  /** \brief The point spacing and the lengths used by the last join(), in the cloud's
   * units (the detection's and the join's settings as run). */
  double
  getUsedPointSpacing () const
  {
    return used_spacing_;
  }
  const cylinder_join::JoinParameters&
  getUsedParameters () const
  {
    return used_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief The lengths in the cloud's units: set ones, the others from the spacing.
   * \return false when a length is needed and the spacing cannot be estimated */
  bool
  resolveLengths (const std::vector<Eigen::Vector3d>& xyz,
                  cylinder_join::JoinParameters& p);

  std::vector<pcl::PointIndices> segments_;
  cylinder_join::JoinParameters parameters_;
  double spacing_ = 0.0;
  double tolerance_factor_ = 0.6, min_radius_factor_ = 0.8, max_radius_factor_ = 24.0,
         max_gap_factor_ = 80.0, neighbourhood_factor_ = 24.0;
  std::optional<double> tolerance_, min_radius_, max_radius_, max_gap_,
      neighbourhood_radius_;
  unsigned int threads_ = 0;
  std::vector<JoinedCylinder> cylinders_;
  double used_spacing_ = 0.0;
  cylinder_join::JoinParameters used_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/cylinder_segment_join.hpp>
#endif
