/*
 * pcl_ext: the profile segmentation configured from the cloud, implementation.
 */
#pragma once

#include <pcl_ext/segmentation/auto_profile_segmentation.h>

#include <pcl/console/print.h>

namespace pcl_ext {
template <typename PointT>
void
AutoProfileSegmentation<PointT>::extract (std::vector<pcl::PointIndices>& clusters)
{
  configuration_ = profiles::AutoConfiguration();
  statistics_ = profiles::CloudStatistics();
  largest_share_ = 0.0;
  joined_ = false;

  // The caller's settings, restored at the end: the choice is per extract().
  const auto method = this->method_;
  const double width_factor = this->width_factor_;
  const double turn_significance = this->turn_significance_;
  const bool corrected_aic = this->corrected_aic_;
  const bool side_frames = this->side_frames_;
  const bool local_threshold = this->local_threshold_;
  const auto restore = [&] {
    this->method_ = method;
    this->width_factor_ = width_factor;
    this->turn_significance_ = turn_significance;
    this->corrected_aic_ = corrected_aic;
    this->side_frames_ = side_frames;
    this->local_threshold_ = local_threshold;
  };

  this->method_ = profiles::ProfileMethod::Proximity;
  Base::extract (clusters);
  if (clusters.empty() || points_.empty()) {
    restore();
    return;
  }

  // The statistics of the segmented points, centred in double (georeferenced clouds).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto i : points_)
    centre += (*input_)[i].getVector3fMap().template cast<double>();
  centre /= static_cast<double> (points_.size());
  std::vector<Eigen::Vector3f> xyz;
  xyz.reserve (points_.size());
  for (const auto i : points_)
    xyz.push_back (((*input_)[i].getVector3fMap().template cast<double>() - centre)
                       .template cast<float>());
  statistics_ = profiles::estimateCloudStatistics (xyz);
  largest_share_ = static_cast<double> (clusters.front().indices.size()) /
                   static_cast<double> (points_.size());
  configuration_ = profiles::chooseConfiguration (statistics_, largest_share_);

  bool rerun = false;
  if (configuration_.curve_fitting) {
    this->method_ = profiles::ProfileMethod::CurveFitting;
    rerun = true;
  }
  if (configuration_.noisy) {
    // The noisy-scan settings where the caller left the paper's values.
    this->corrected_aic_ = true;
    if (turn_significance == 0.0)
      this->turn_significance_ = 3.0;
    if (width_factor == 1.5)
      this->width_factor_ = 2.5;
  }
  this->side_frames_ = side_frames || configuration_.side_frames;
  if (configuration_.local_threshold && !local_threshold) {
    this->local_threshold_ = true;
    rerun = true;
  }
  if (rerun)
    Base::extract (clusters);
  restore();
  if (clusters.empty() || !configuration_.join_cylinders)
    return;

  join_.setInputCloud (input_);
  join_.setInputSegments (clusters);
  join_.setNumberOfThreads (this->threads_);
  join_.join (clusters);
  if (clusters.empty()) {
    PCL_ERROR ("[pcl_ext::AutoProfileSegmentation::extract] Joining the cylinders "
               "failed.\n");
    return;
  }
  joined_ = true;
  this->clusters_ = clusters;
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_AutoProfileSegmentation(T)                                 \
  template class pcl_ext::AutoProfileSegmentation<T>;
