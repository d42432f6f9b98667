/*
 * pcl_ext: the profile segmentation configured from the cloud (Sithole & Mapurisa).
 */
#pragma once

#include <pcl_ext/segmentation/cylinder_segment_join.h>
#include <pcl_ext/segmentation/profile_auto.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include <vector>

namespace pcl_ext {
/** \brief ProfileSegmentation with the configuration chosen from the cloud: the same
 * defaults for every scene, as pcl_ext_segment_profiles runs it.
 *
 * G. Sithole and W.T. Mapurisa, "3D object segmentation of point clouds using profiling
 * techniques": proximity chaining (section 4.1.1) separates objects that do not touch;
 * curve fitting (section 4.1.2) separates touching surfaces at their creases. The paper
 * chooses per scene; extract() chooses from the data (profiles::chooseConfiguration,
 * not in the paper):
 * 1. proximity chaining with the settings given;
 * 2. the cloud's spacing, noise and density variation
 * (profiles::estimateCloudStatistics) and the share of the points in the largest
 * segment of step 1;
 * 3. where that share is at least profiles::kAutoTouchingShare, curve fitting with
 *    curve fits along each side's own axis (setSideFrames); where the noise is at least
 *    profiles::kAutoNoiseRatio spacings, also the corrected AIC, a turn significance of
 *    3 and profiles 2.5 spacings wide (each only where it was left at the paper's
 *    value); where the spacing varies by more than
 *    profiles::kAutoLocalThresholdVariation, local thresholds;
 * 4. with curve fitting, CylinderSegmentJoin (the settings of setCylinderJoin) joins
 *    the pieces curve fitting cuts from pipes and trunks.
 *
 * The profile segmenter set with setProfileSegmentation is not used: step 1 runs
 * proximity chaining and step 3 decides. The other settings (stacks, width, threshold,
 * neighbours, sizes, threads) apply to both runs. The settings of the base class are
 * as the caller left them after extract(); getConfiguration() tells what was chosen.
 */
template <typename PointT>
class AutoProfileSegmentation : public ProfileSegmentation<PointT> {
public:
  using Base = ProfileSegmentation<PointT>;
  using Ptr = pcl::shared_ptr<AutoProfileSegmentation<PointT>>;
  using ConstPtr = pcl::shared_ptr<const AutoProfileSegmentation<PointT>>;

  AutoProfileSegmentation() = default;

  /** \brief The cylinder join run after curve fitting, with its settings (its input
   * cloud, segments and thread count are set by extract()). Default: a
   * CylinderSegmentJoin with its defaults, in units of the point spacing. */
  void
  setCylinderJoin (const CylinderSegmentJoin<PointT>& join)
  {
    join_ = join;
  }
  /** \brief The join's settings and, after extract(), its cylinders. */
  const CylinderSegmentJoin<PointT>&
  getCylinderJoin () const
  {
    return join_;
  }

  /** \brief Choose the configuration, segment, and join cylinders where chosen.
   * \param[out] clusters one PointIndices per segment, largest first; empty on error
   * (with a PCL_ERROR). */
  void
  extract (std::vector<pcl::PointIndices>& clusters) override;

  /** \brief What the last extract() chose. */
  const profiles::AutoConfiguration&
  getConfiguration () const
  {
    return configuration_;
  }
  /** \brief The cloud statistics the last extract() chose from. */
  const profiles::CloudStatistics&
  getCloudStatistics () const
  {
    return statistics_;
  }
  /** \brief The share of the segmented points in the largest segment of the last
   * extract()'s proximity run. */
  double
  getLargestProximityShare () const
  {
    return largest_share_;
  }
  /** \brief Whether the last extract() joined cylinders. */
  bool
  getCylindersJoined () const
  {
    return joined_;
  }

protected:
  using Base::input_;
  using Base::points_;

  CylinderSegmentJoin<PointT> join_;
  profiles::AutoConfiguration configuration_;
  profiles::CloudStatistics statistics_;
  double largest_share_ = 0.0;
  bool joined_ = false;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/auto_profile_segmentation.hpp>
#endif
