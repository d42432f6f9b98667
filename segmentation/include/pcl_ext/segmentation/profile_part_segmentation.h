/*
 * pcl_ext: Sithole & Mapurisa's profile segmentation of a part of a cloud that holds
 * whole profiles, as the whole cloud's would be (a run split by profiles).
 */
#pragma once

#include <pcl_ext/segmentation/profile_segmentation.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_ext {
/** \brief ProfileSegmentation of a part of a larger cloud, for runs split by profiles
 * (pcl_ext_tiles segment_profiles): given the whole cloud's frame, a part that holds
 * each of its profiles whole gets the whole cloud's profile edges among its points.
 *
 * A profile's chains (Sithole & Mapurisa, section 4.1) depend on the profile's points
 * alone, but on all of them. What depends on more is handed in from outside, computed
 * over all the parts:
 * - the frame: the whole cloud's centre, about which the points are computed in float,
 *   each stack's origin (where profile 0 starts), and the spacing (setPointSpacing);
 * - with local thresholds, each stack's mean local gap (computeLocalGaps on every part,
 *   then their mean below getUsedMaxThreshold(), summed in the points' order);
 * - with curve fitting (section 4.1.2), three runs: computeCurveScores gives each
 *   point's scores and the chains; the stack's medians over every part give its
 *   getCurveEndRule and each point's own curve ends (profiles::isCurveEnd), a point
 *   ending a curve in any stack is a breakpoint; computeCurveJoins, given them, follows
 *   the curves across junctions; the segments are then profiles::labelSegments of all
 *   the parts' edges and breakpoints.
 *
 * extract() on a part gives the components of its own edges (curve fitting: not
 * meaningful, the curve ends need every part). */
template <typename PointT>
class ProfilePartSegmentation : public ProfileSegmentation<PointT> {
public:
  using Edge = typename ProfileSegmentation<PointT>::Edge;

  /** \brief The whole cloud's frame: \a centre, the mean of its finite points (in the
   * input's frame), and \a origins, where profile 0 of each stack starts
   * (profiles::PipelineParameters::origins, one per stack). Default: a NaN centre and
   * no origins, the input's own. */
  void
  setCloudFrame (const Eigen::Vector3d& centre, const std::vector<double>& origins)
  {
    this->frame_centre_ = centre;
    this->frame_origins_ = origins;
  }
  const Eigen::Vector3d&
  getCloudCentre () const
  {
    return this->frame_centre_;
  }
  const std::vector<double>&
  getStackOrigins () const
  {
    return this->frame_origins_;
  }

  /** \brief With local thresholds, each stack's mean local gap over the whole cloud,
   * one per stack (profiles::PipelineParameters::mean_gaps). Default: none, the
   * input's own. */
  void
  setStackMeanGaps (const std::vector<double>& mean_gaps)
  {
    this->mean_gaps_ = mean_gaps;
  }
  const std::vector<double>&
  getStackMeanGaps () const
  {
    return this->mean_gaps_;
  }

  /** \brief With local thresholds: the local gap of every input point in every stack
   * (profiles::localGaps; NaN for a point that is not finite or not in the indices),
   * without segmenting. \return false (PCL_ERROR) when the settings are not valid or
   * local thresholds are off */
  bool
  computeLocalGaps (std::vector<std::vector<float>>& gaps);

  /** \brief The longest local threshold of the last run: the maximum threshold factor
   * times the threshold (a stack's mean gap leaves out the gaps at it). */
  double
  getUsedMaxThreshold () const
  {
    return this->used_max_threshold_;
  }

  /** \brief Curve fitting, first run: the scores of every input point in every stack
   * (not evaluated for a point that is not segmented) and each stack's chains, in
   * input indices. \return false (PCL_ERROR) when the settings are not valid or the
   * method is not curve fitting */
  bool
  computeCurveScores (std::vector<profiles::CurveScores>& scores,
                      std::vector<std::vector<Edge>>& chains);

  /** \brief The curve end rule of a stack whose evaluated points have the medians \a
   * median_rms and \a median_noise over the whole cloud, with the settings of the last
   * run, or before any, with the settings and the spacing given (setPointSpacing)
   * (profiles::curveEndRule). */
  profiles::CurveEndRule
  getCurveEndRule (double median_rms, double median_noise) const;

  /** \brief Curve fitting, last run: with the curve ends of the whole cloud given, one
   * flag per input point (\a own_ends: each stack's own; \a breakpoints: in any stack)
   * and each stack's junction tolerance (CurveEndRule::junction_tolerance), \a edges
   * gets each stack's chains and curves followed across junctions and \a
   * breakpoints_out the breakpoints with the points those joins absorb, in input
   * indices. \return false (PCL_ERROR) when the settings or the sizes are not valid */
  bool
  computeCurveJoins (const std::vector<std::vector<std::uint8_t>>& own_ends,
                     const std::vector<std::uint8_t>& breakpoints,
                     const std::vector<double>& junction_tolerances,
                     std::vector<std::vector<Edge>>& edges,
                     std::vector<std::uint8_t>& breakpoints_out);
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/profile_part_segmentation.hpp>
#endif
