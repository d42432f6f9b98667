/*
 * pcl_ext: profile-intersection segmentation (Sithole & Mapurisa).
 */
#pragma once

#include <pcl_ext/segmentation/cluster_size_limits.h>
#include <pcl_ext/segmentation/profile_graph.h>
#include <pcl_ext/segmentation/profile_pipeline.h>
#include <pcl_ext/segmentation/profile_stacks.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief Segmentation by intersecting profiles: G. Sithole and W.T. Mapurisa, "3D
 * object segmentation of point clouds using profiling techniques" (extending Sithole
 * 2005).
 *
 * The cloud is sliced into thin contiguous profiles along each of several stack normals
 * (section 2.1, figure 3); every point lies in exactly one profile of every stack
 * (section 2.2, figure 4). The points of each profile are linked into chains by a
 * profile segmenter (section 4.1, figure 8): proximity chaining (4.1.1), a minimum
 * spanning tree cut at the proximity threshold (section 3), or curve fitting with model
 * selection by the Akaike information criterion and splits where the unit normal turns
 * sharply (4.1.2, figure 9), or the curve reconstruction the paper uses for its nested
 * spheres (section 5.2; profiles::crustEdges). The union of the edges of all profiles
 * of all stacks is a graph G(V, E); its connected components are the segments (section
 * 3, figure 5).
 *
 * Nothing searches neighbours over the whole cloud: each stack is a bucket sort of the
 * points by their coordinate along the stack normal, and each profile is segmented on
 * its own, in parallel (OpenMP; the result does not depend on the number of threads).
 *
 * Where pcl_ext departs from or makes the text precise:
 * - Stack normals are spread over the hemisphere (the paper's extension, figure 7) as
 * the best packings of lines for up to 6 stacks, turned off the coordinate axes; the
 * original horizontal half circle and a user list of normals are options.
 * - Profile width and proximity threshold default to 1.5x and 3x the average point
 * spacing (section 5.3: width "at least one and a half times", threshold "slightly
 * larger than the average point spacing"). The spacing is the square root of the
 * surface area per point, from the 6th-neighbour distance of a deterministic sample of
 * points found by a sweep along a sort (no tree; see profiles::estimatePointSpacing).
 * TLS density varies with range and scan lines are denser along than across, so the
 * threshold is 3x rather than less: a smaller one over-segments the far, sparse
 * surfaces.
 * - Proximity chaining links every point to its k nearest points in the profile (k = 4
 * by default: a point of a chain has a predecessor and a successor, and the profile's
 * width and noise make the chain a few points thick).
 * - Curve fitting: instead of fitting a whole chain and splitting it repeatedly, every
 * point is tested once: the chain's points within a window on either side of it are
 * fitted with polynomials of degree 1 to 3 (plus a term across the profile's width),
 * the model of lowest AIC is kept per side, and the point ends a curve when the unit
 * normals of the two sides differ by more than the maximum turn, or when a side is not
 * one curve (residual far above the noise). Testing every point finds every split the
 * repeated splitting would find. Two options for noisy scans, off by default (the
 * paper): the model chosen by AICc, the small-sample AIC (setCorrectedAic), and a turn
 * ending a curve only when it is also significant, more than z standard errors of the
 * fits (setTurnSignificance). Where the range noise is close to the point spacing the
 * paper's test marks many points as curve ends and cuts the surfaces apart; the two
 * options together, with profiles about 2.5 spacings wide (setProfileWidthFactor), keep
 * them whole. The curve ends (breakpoints) of all stacks are removed from the graph
 * before the components are taken, and then rejoin the segment of most of their
 * neighbours: a crease seen by one stack so also separates the profiles of the stacks
 * that run along it. Where curves cross or touch in a profile (the paper's entangled
 * curves: two surfaces crossing, a pipe on its support), the curve ends cut every curve
 * at the junction; the curves through it are then found by fitting the ends of the
 * arms that meet there in pairs, and followed across it (profiles::
 * joinCurvesAcrossJunctions), the paper's "repeated until no new curves are
 * detected".
 * - Two more options, off by default (the paper), for what one global spacing and one
 * frame per point miss: thresholds that follow the local point density
 * (setLocalThreshold: a TLS scan is sparser far from the scanner) and curve fits along
 * each side's own axis (setSideFrames: tight smooth bends such as a thin trunk cut
 * obliquely).
 * - The class keeps the paper's defaults; AutoProfileSegmentation chooses these
 * options from the cloud's noise, density variation and a first proximity run
 * (profile_auto.h), as pcl_ext_segment_profiles does by default.
 * - Points with non-finite coordinates are never segmented, whatever \c is_dense says.
 * - Curve fitting cuts a pipe where it rests on a support and a thin trunk where
 * branches leave it; CylinderSegmentJoin, a step after the segmentation, joins such
 * pieces again (the paper: "from the data structure it is possible to obtain the axes
 * ... in the pipes").
 * - Segments smaller than the minimum size are dropped (as pcl::RegionGrowing does);
 * the others are ordered by decreasing size.
 *
 * docs/sithole_mapurisa.md reports what each option measures on the generated scenes of
 * the paper's section 5.
 */
template <typename PointT>
class ProfileSegmentation : public pcl::PCLBase<PointT>, public ClusterSizeLimits {
public:
  using PointCloud = pcl::PointCloud<PointT>;
  using PointCloudConstPtr = typename PointCloud::ConstPtr;
  using Ptr = pcl::shared_ptr<ProfileSegmentation<PointT>>;
  using ConstPtr = pcl::shared_ptr<const ProfileSegmentation<PointT>>;
  using ProfileMethod = profiles::ProfileMethod;
  using StackDistribution = profiles::StackDistribution;

  /** \brief An edge of the profile graph, between two cloud indices. */
  struct Edge {
    pcl::index_t source;
    pcl::index_t target;
  };

  ProfileSegmentation() = default;

  /** \brief Number of stacks (the paper's stack count). Default 4; valid: >= 1 (the
   * paper uses 3 to 4; 1 stack cannot join profiles, so every segment is one profile's
   * chain). Ignored when stack normals are given. */
  void
  setNumberOfStacks (unsigned int count)
  {
    num_stacks_ = count;
  }
  unsigned int
  getNumberOfStacks () const
  {
    return num_stacks_;
  }

  /** \brief How the stack normals (phi) are spread. Default Hemisphere (section 4,
   * figure 7); HorizontalHalfCircle gives vertical profiles as in Sithole (2005). */
  void
  setStackDistribution (StackDistribution distribution)
  {
    distribution_ = distribution;
  }
  StackDistribution
  getStackDistribution () const
  {
    return distribution_;
  }

  /** \brief Explicit stack normals phi (normalised here). Default empty (use the number
   * of stacks and the distribution); each must be finite and non-zero. */
  void
  setStackNormals (const std::vector<Eigen::Vector3f>& normals)
  {
    user_normals_ = normals;
  }
  /** \brief The stack normals used by the last extract() (or given). */
  const std::vector<Eigen::Vector3f>&
  getStackNormals () const
  {
    return used_normals_.empty() ? user_normals_ : used_normals_;
  }

  /** \brief Profile width. Default 0: automatic, the width factor times the average
   * point spacing; valid: 0 or > 0 (finite). Larger than the cloud puts all points in
   * one profile per stack (valid, but the profiles then hold surfaces rather than
   * curves). */
  void
  setProfileWidth (double width)
  {
    width_ = width;
  }
  double
  getProfileWidth () const
  {
    return width_;
  }

  /** \brief Automatic width as a multiple of the average point spacing. Default 1.5
   * (section 5.3: "at least one and a half times"); valid: > 0. Figure 6: 0.5x
   * over-segments, larger widths under-segment. Curve fitting on noisy scans wants
   * about 2.5: the fits on either side of a point then hold about twice the points (the
   * fit's term across the profile absorbs the extra width), enough to tell a crease
   * from the noise. */
  void
  setProfileWidthFactor (double factor)
  {
    width_factor_ = factor;
  }
  double
  getProfileWidthFactor () const
  {
    return width_factor_;
  }

  /** \brief Proximity threshold: the longest link kept in a profile. Default 0:
   * automatic, the threshold factor times the average point spacing; valid: 0 or > 0
   * (finite). */
  void
  setDistanceThreshold (double threshold)
  {
    threshold_ = threshold;
  }
  double
  getDistanceThreshold () const
  {
    return threshold_;
  }

  /** \brief Automatic threshold as a multiple of the average point spacing.
   * Default 3.0; valid: > 0. */
  void
  setDistanceThresholdFactor (double factor)
  {
    threshold_factor_ = factor;
  }
  double
  getDistanceThresholdFactor () const
  {
    return threshold_factor_;
  }

  /** \brief Link thresholds that follow the local point density. Default false: one
   * threshold for the whole cloud, as in the paper (section 5.3).
   *
   * Not in the paper, for scans whose density varies (TLS density falls with the square
   * of the range): the one automatic spacing is set by the dense surfaces near the
   * scanners, and the profiles of far, sparse surfaces break into short chains. With
   * this option the paper's average spacing is in effect computed per neighbourhood:
   * every point gets the threshold scaled by the ratio of its local gap (the median
   * nearest-neighbour distance in its profile over the point and its 8 nearest,
   * profiles::localGaps) to the stack's mean local gap, never below the threshold nor
   * above the maximum threshold factor times it; a link must be within the thresholds
   * of both its ends (a sparse point does not reach into a dense surface), and the
   * curve window grows with the threshold.
   *
   * Not the default: proximity chaining takes longer (the gaps need a nearest-neighbour
   * search in every profile), and where creases matter the longer windows of the sparse
   * parts straddle them. */
  void
  setLocalThreshold (bool local)
  {
    local_threshold_ = local;
  }
  bool
  getLocalThreshold () const
  {
    return local_threshold_;
  }

  /** \brief Local thresholds: the longest, as a multiple of the distance threshold.
   * Default 4; valid: >= 1 (1: the local thresholds are all the distance threshold). */
  void
  setMaxThresholdFactor (double factor)
  {
    max_threshold_factor_ = factor;
  }
  double
  getMaxThresholdFactor () const
  {
    return max_threshold_factor_;
  }

  /** \brief Average point spacing used for the automatic width and threshold. Default
   * 0: estimated from the cloud; valid: 0 or > 0. */
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

  /** \brief The profile segmenter. Default Proximity; CurveReconstruction links each
   * point to its nearest and half neighbours (profiles::crustEdges). */
  void
  setProfileSegmentation (ProfileMethod method)
  {
    method_ = method;
  }
  ProfileMethod
  getProfileSegmentation () const
  {
    return method_;
  }

  /** \brief Proximity chaining: links per point to its nearest profile neighbours.
   * Default 4 (2 suffice on a clean curve; 4 keep a surface lying in a profile, or a
   * thick noisy curve, connected); valid: >= 1. */
  void
  setProximityNeighbours (unsigned int k)
  {
    proximity_k_ = k;
  }
  unsigned int
  getProximityNeighbours () const
  {
    return proximity_k_;
  }

  /** \brief Curve fitting: half length of the stretch of profile fitted on each side of
   * a point. Default 0: 2x the proximity threshold; valid: 0 or > 0. */
  void
  setCurveWindow (double window)
  {
    curve_window_ = window;
  }
  double
  getCurveWindow () const
  {
    return curve_window_;
  }

  /** \brief Curve fitting: the sharpest turn of the unit normal still inside one curve,
   * in radians. Default pi/6 (30 degrees); valid: (0, pi/2]. */
  void
  setMaxTurnAngle (double angle)
  {
    max_turn_ = angle;
  }
  double
  getMaxTurnAngle () const
  {
    return max_turn_;
  }

  /** \brief Curve fitting: a turn sharper than the maximum ends a curve only when it
   * also exceeds this many standard errors, propagated from the two sides' fits with
   * the stack's median residual as the noise. Default 0: the angle alone decides, as in
   * the paper; valid:
   * >= 0. Not in the paper, for scans whose noise is comparable to the point spacing
   * (the generated \c coaxial scene: 5 mm range noise, 7.7 mm spacing), where a 30
   * degree turn over a window of ten points a side is often noise and the false curve
   * ends cut surfaces apart; use 3 there, with setCorrectedAic (true) and a width
   * factor of 2.5. Not the default: the same dense curve ends that cut a surface also
   * cut objects from what they stand on, and on scans of objects (the generated \c
   * indoor scene) the option costs more than it gains. */
  void
  setTurnSignificance (double z)
  {
    turn_significance_ = z;
  }
  double
  getTurnSignificance () const
  {
    return turn_significance_;
  }

  /** \brief Curve fitting: select the polynomial by AICc, the small-sample corrected
   * AIC of Hurvich & Tsai (1989), rather than the paper's AIC. Default false (the
   * paper). A side holds about ten points, where plain AIC picks the cubic for noise
   * and the cubic's slope follows the noise; AICc tends to AIC as the sides grow. Its
   * correction is infinite where a model has as few as k + 1 points (k: its terms and
   * the noise variance): a parabola or a cubic is only fitted to more, and a side of 4
   * or 5 points keeps the line (see fitPolynomialAic). Use with setTurnSignificance. */
  void
  setCorrectedAic (bool corrected)
  {
    corrected_aic_ = corrected;
  }
  bool
  getCorrectedAic () const
  {
    return corrected_aic_;
  }

  /** \brief Curve fitting: fit each side of a point along the principal axis of that
   * side's own points, rather than along the curve's direction at the point. Default
   * false (one frame per point). Not in the paper, for tight smooth bends: where a
   * stack's plane cuts a thin cylinder obliquely the section is an ellipse whose radius
   * of curvature at the ends of its long axis (0.58 r for the default stacks, 55
   * degrees from the horizontal) is about the window, each side then turns by tens of
   * degrees, and a polynomial in the point's frame follows it poorly: residual and turn
   * tests both fire on a smooth surface (the generated \c tree scene: trunk radius 0.26
   * m at the foot, window 0.16 m). Not the default: a narrow face between two creases
   * (a flange face 10 cm wide on \c coaxial) can merge with its neighbour. */
  void
  setSideFrames (bool side_frames)
  {
    side_frames_ = side_frames;
  }
  bool
  getSideFrames () const
  {
    return side_frames_;
  }

  /** \brief Curve fitting: a side whose residual RMS exceeds this multiple of the
   * stack's median residual is not one curve (a junction). The RMS is over the fit's
   * residual degrees of freedom (n - p for p fitted terms), an unbiased noise estimate.
   * Default 3; valid: > 0. */
  void
  setResidualFactor (double factor)
  {
    residual_factor_ = factor;
  }
  double
  getResidualFactor () const
  {
    return residual_factor_;
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

  /** \brief Segment the cloud (the indices, if set).
   * \param[out] clusters one PointIndices per segment, largest first; empty on error
   * (with a PCL_ERROR). Virtual as in pcl::RegionGrowing: AutoProfileSegmentation
   * chooses the configuration first. */
  virtual void
  extract (std::vector<pcl::PointIndices>& clusters);

  /** \brief The input cloud coloured by segment (unsegmented points white), as
   * pcl::RegionGrowing::getColoredCloud; empty before a successful extract(). */
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr
  getColoredCloud () const;

  /** \brief Spacing, width and threshold used by the last extract(). */
  double
  getUsedPointSpacing () const
  {
    return used_spacing_;
  }
  double
  getUsedProfileWidth () const
  {
    return used_width_;
  }
  double
  getUsedDistanceThreshold () const
  {
    return used_threshold_;
  }

  /** \brief The profile graph of the last extract(): the edges E_phi of each stack
   * (section 2.1), as cloud indices. */
  const std::vector<std::vector<Edge>>&
  getStackEdges () const
  {
    return stack_edges_;
  }

  /** \brief For stack \a s, the profile of every point (cloud order; -1 for points not
   * segmented: outside the indices or not finite). Empty for an unknown stack. */
  std::vector<int>
  getProfileOfPoints (std::size_t s) const;

  /** \brief Curve fitting: the cloud indices of the curve ends (breakpoints). */
  const pcl::Indices&
  getBreakpoints () const
  {
    return breakpoints_;
  }

  /** \brief Curve fitting: how many curves were followed across a junction (edges of
   * getStackEdges, the last of their stack's). */
  std::size_t
  getJunctionJoins () const
  {
    return junction_joins_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Check parameters and gather the finite points; false (with PCL_ERROR) if
   * bad. */
  bool
  prepare (std::vector<Eigen::Vector3f>& xyz);

  /** \brief Prepare the points, resolve the settings and run the pipeline to \a stage
   * (ProfilePartSegmentation's stages: the frame and the given curve ends set by it).
   * \return false (PCL_ERROR, deinitCompute done) when the input or the settings are
   * not valid */
  bool
  runPipeline (profiles::PipelineStage stage, profiles::PipelineResult& result);

  /** \brief Resolve spacing, width and threshold into \a parameters. */
  bool
  resolveLengths (const std::vector<Eigen::Vector3f>& xyz,
                  profiles::PipelineParameters& parameters);

  unsigned int num_stacks_ = 4;
  StackDistribution distribution_ = StackDistribution::Hemisphere;
  std::vector<Eigen::Vector3f> user_normals_;
  double width_ = 0.0;
  double width_factor_ = 1.5;
  double threshold_ = 0.0;
  double threshold_factor_ = 3.0;
  double spacing_ = 0.0;
  bool local_threshold_ = false;
  double max_threshold_factor_ = 4.0;
  ProfileMethod method_ = ProfileMethod::Proximity;
  unsigned int proximity_k_ = 4;
  double curve_window_ = 0.0;
  double max_turn_ = M_PI / 6.0;
  double residual_factor_ = 3.0;
  double turn_significance_ = 0.0;
  bool corrected_aic_ = false;
  bool side_frames_ = false;
  unsigned int threads_ = 0;
  Eigen::Vector3d frame_centre_ =
      Eigen::Vector3d::Constant (std::numeric_limits<double>::quiet_NaN());
  std::vector<double> frame_origins_;
  std::vector<double> mean_gaps_;
  // The curve ends given to the stage CurveJoins, per input point.
  std::vector<std::vector<std::uint8_t>> given_ends_;
  std::vector<std::uint8_t> given_breakpoints_;
  std::vector<double> junction_tolerances_;

  // Results of the last extract().
  pcl::Indices points_; ///< cloud index of each segmented (finite) point
  std::vector<Eigen::Vector3f> used_normals_;
  std::vector<std::vector<Edge>> stack_edges_;
  std::vector<std::vector<std::uint32_t>>
      profile_of_point_; ///< per stack, per points_ entry
  pcl::Indices breakpoints_;
  std::size_t junction_joins_ = 0;
  std::vector<pcl::PointIndices> clusters_;
  double used_spacing_ = 0.0;
  double used_width_ = 0.0;
  double used_threshold_ = 0.0;
  double used_max_threshold_ = 0.0;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/profile_segmentation.hpp>
#endif
