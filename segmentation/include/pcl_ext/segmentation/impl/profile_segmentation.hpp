/*
 * pcl_ext: profile-intersection segmentation (Sithole & Mapurisa), implementation.
 */
#pragma once

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/common/segment_colours.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
template <typename PointT>
bool
ProfileSegmentation<PointT>::prepare (std::vector<Eigen::Vector3f>& xyz)
{
  const char* name = "ProfileSegmentation::extract";
  const auto bad_length = [] (double value) {
    return !(value >= 0.0) || !std::isfinite (value);
  };
  if (user_normals_.empty() && num_stacks_ == 0) {
    PCL_ERROR ("[pcl_ext::%s] The number of stacks must be at least 1.\n", name);
    return false;
  }
  for (const auto& n : user_normals_)
    if (!n.allFinite() || n.norm() < 1e-6f) {
      PCL_ERROR ("[pcl_ext::%s] Stack normals must be finite and non-zero.\n", name);
      return false;
    }
  if (bad_length (width_) || bad_length (threshold_) || bad_length (spacing_) ||
      bad_length (curve_window_)) {
    PCL_ERROR (
        "[pcl_ext::%s] Width, threshold, spacing and curve window must be finite and "
        ">= 0 (0: automatic).\n",
        name);
    return false;
  }
  if (!(width_factor_ > 0.0) || !std::isfinite (width_factor_) ||
      !(threshold_factor_ > 0.0) || !std::isfinite (threshold_factor_)) {
    PCL_ERROR ("[pcl_ext::%s] Width and threshold factors must be finite and > 0.\n",
               name);
    return false;
  }
  if (!(max_threshold_factor_ >= 1.0) || !std::isfinite (max_threshold_factor_)) {
    PCL_ERROR ("[pcl_ext::%s] The maximum threshold factor must be finite and >= 1.\n",
               name);
    return false;
  }
  if (proximity_k_ == 0 || !(max_turn_ > 0.0) || !(max_turn_ <= M_PI / 2) ||
      !(residual_factor_ > 0.0) || !std::isfinite (residual_factor_) ||
      !(turn_significance_ >= 0.0) || !std::isfinite (turn_significance_)) {
    PCL_ERROR (
        "[pcl_ext::%s] Need proximity neighbours >= 1, a maximum turn in (0, pi/2], "
        "a residual factor > 0 and a turn significance >= 0.\n",
        name);
    return false;
  }
  if (!frame_centre_.allFinite() && !frame_centre_.array().isNaN().all()) {
    PCL_ERROR ("[pcl_ext::%s] The cloud centre must be finite (or all NaN: the "
               "input's).\n",
               name);
    return false;
  }
  if (!validClusterSizes()) {
    PCL_ERROR (
        "[pcl_ext::%s] Need 1 <= minimum cluster size <= maximum cluster size.\n",
        name);
    return false;
  }
  if (!initCompute()) {
    PCL_ERROR ("[pcl_ext::%s] No input cloud.\n", name);
    return false;
  }
  if (user_normals_.empty() && num_stacks_ == 1)
    PCL_WARN (
        "[pcl_ext::%s] One stack cannot join profiles: every segment is one profile's "
        "chain.\n",
        name);

  // Centre in double: the float offsets then keep full precision for georeferenced
  // clouds.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  points_.clear();
  points_.reserve (indices_->size());
  for (const auto index : *indices_)
    if (index >= 0 && static_cast<std::size_t> (index) < input_->size() &&
        pcl::isXYZFinite ((*input_)[index])) {
      points_.push_back (index);
      centre += (*input_)[index].getVector3fMap().template cast<double>();
    }
  if (!points_.empty())
    centre /= static_cast<double> (points_.size());
  if (frame_centre_.allFinite())
    centre = frame_centre_;
  xyz.resize (points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i)
    xyz[i] = ((*input_)[points_[i]].getVector3fMap().template cast<double>() - centre)
                 .template cast<float>();
  return true;
}

template <typename PointT>
bool
ProfileSegmentation<PointT>::resolveLengths (const std::vector<Eigen::Vector3f>& xyz,
                                             profiles::PipelineParameters& p)
{
  used_spacing_ = spacing_;
  const bool need_spacing = width_ == 0.0 || threshold_ == 0.0;
  if (need_spacing && used_spacing_ == 0.0)
    used_spacing_ = profiles::estimatePointSpacing (xyz);
  if (need_spacing && !(used_spacing_ > 0.0)) {
    PCL_ERROR (
        "[pcl_ext::ProfileSegmentation::extract] Cannot estimate the point spacing "
        "(fewer than two distinct finite points); set the profile width and distance "
        "threshold.\n");
    return false;
  }
  used_width_ = width_ > 0.0 ? width_ : width_factor_ * used_spacing_;
  used_threshold_ = threshold_ > 0.0 ? threshold_ : threshold_factor_ * used_spacing_;
  p.width = used_width_;
  p.threshold = used_threshold_;
  p.curve_window = curve_window_ > 0.0 ? curve_window_ : 2.0 * used_threshold_;
  p.tangent_radius = 0.5 * p.curve_window;
  p.min_residual = 0.1 * used_threshold_;
  return true;
}

template <typename PointT>
bool
ProfileSegmentation<PointT>::runPipeline (profiles::PipelineStage stage,
                                          profiles::PipelineResult& result)
{
  std::vector<Eigen::Vector3f> xyz;
  if (!prepare (xyz))
    return false;
  profiles::PipelineParameters p;
  p.normals = user_normals_.empty()
                  ? profiles::makeStackNormals (num_stacks_, distribution_)
                  : user_normals_;
  for (auto& n : p.normals)
    n.normalize();
  used_normals_ = p.normals;
  p.origins = frame_origins_;
  if (xyz.empty()) {
    PCL_ERROR ("[pcl_ext::ProfileSegmentation::extract] No finite point to segment.\n");
    deinitCompute();
    return false;
  }
  if (!resolveLengths (xyz, p)) {
    deinitCompute();
    return false;
  }
  p.method = method_;
  p.proximity_neighbours = proximity_k_;
  p.local_threshold = local_threshold_;
  p.max_threshold = max_threshold_factor_ * used_threshold_;
  used_max_threshold_ = p.max_threshold;
  p.mean_gaps = mean_gaps_;
  p.stage = stage;
  if (stage == profiles::PipelineStage::CurveJoins) {
    // The given curve ends, per input point, for the segmented points.
    p.given_ends.assign (given_ends_.size(), std::vector<std::uint8_t> (xyz.size(), 0));
    p.given_breakpoints.assign (xyz.size(), 0);
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const auto index = static_cast<std::size_t> (points_[i]);
      for (std::size_t s = 0; s < given_ends_.size(); ++s)
        if (index < given_ends_[s].size())
          p.given_ends[s][i] = given_ends_[s][index];
      if (index < given_breakpoints_.size())
        p.given_breakpoints[i] = given_breakpoints_[index];
    }
    p.junction_tolerances = junction_tolerances_;
  }
  p.max_turn = max_turn_;
  p.turn_significance = turn_significance_;
  p.corrected_aic = corrected_aic_;
  p.side_frames = side_frames_;
  p.residual_factor = residual_factor_;
  p.threads = resolveThreadCount (threads_);
  if ((!p.origins.empty() && p.origins.size() != p.normals.size()) ||
      (!p.mean_gaps.empty() && p.mean_gaps.size() != p.normals.size())) {
    PCL_ERROR ("[pcl_ext::ProfileSegmentation::extract] %zu stack origins and %zu "
               "mean gaps for %zu stacks.\n",
               p.origins.size(),
               p.mean_gaps.size(),
               p.normals.size());
    deinitCompute();
    return false;
  }
  if (!profiles::runProfileSegmentation (xyz, p, result)) {
    PCL_ERROR ("[pcl_ext::ProfileSegmentation::extract] Invalid parameters (or a "
               "point below its stack's given origin).\n");
    deinitCompute();
    return false;
  }
  return true;
}

template <typename PointT>
void
ProfileSegmentation<PointT>::extract (std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  clusters_.clear();
  stack_edges_.clear();
  profile_of_point_.clear();
  breakpoints_.clear();
  junction_joins_ = 0;
  used_normals_.clear();
  used_spacing_ = used_width_ = used_threshold_ = used_max_threshold_ = 0.0;
  points_.clear();

  profiles::PipelineResult result;
  if (!runPipeline (profiles::PipelineStage::Segments, result))
    return;

  // The graph, in cloud indices.
  stack_edges_.resize (result.edges.size());
  profile_of_point_.resize (result.stacks.size());
  for (std::size_t s = 0; s < result.edges.size(); ++s) {
    stack_edges_[s].reserve (result.edges[s].size());
    for (const auto& e : result.edges[s])
      stack_edges_[s].push_back ({points_[e.source], points_[e.target]});
    profile_of_point_[s] = std::move (result.stacks[s].profile_of_point);
  }
  for (std::size_t i = 0; i < result.breakpoints.size(); ++i)
    if (result.breakpoints[i])
      breakpoints_.push_back (points_[i]);
  junction_joins_ = result.junction_joins;

  // Segments: the connected components within the size limits, largest first.
  std::vector<pcl::PointIndices> all (result.num_segments);
  for (std::size_t i = 0; i < points_.size(); ++i)
    all[result.labels[i]].indices.push_back (points_[i]);
  for (auto& segment : all)
    if (keepsClusterSize (segment.indices.size())) {
      std::sort (segment.indices.begin(), segment.indices.end());
      clusters_.push_back (std::move (segment));
    }
  std::stable_sort (clusters_.begin(),
                    clusters_.end(),
                    [] (const pcl::PointIndices& a, const pcl::PointIndices& b) {
                      if (a.indices.size() != b.indices.size())
                        return a.indices.size() > b.indices.size();
                      return a.indices.front() < b.indices.front();
                    });
  for (auto& segment : clusters_)
    segment.header = input_->header;
  clusters = clusters_;
  deinitCompute();
}

template <typename PointT>
std::vector<int>
ProfileSegmentation<PointT>::getProfileOfPoints (std::size_t s) const
{
  std::vector<int> profile;
  if (s >= profile_of_point_.size() || !input_)
    return profile;
  profile.assign (input_->size(), -1);
  for (std::size_t i = 0; i < points_.size(); ++i)
    profile[points_[i]] = static_cast<int> (profile_of_point_[s][i]);
  return profile;
}

template <typename PointT>
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
ProfileSegmentation<PointT>::getColoredCloud() const
{
  if (!input_)
    return pcl::PointCloud<pcl::PointXYZRGB>::Ptr (
        new pcl::PointCloud<pcl::PointXYZRGB>);
  return colourBySegment (*input_, clusters_);
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_ProfileSegmentation(T)                                     \
  template class pcl_ext::ProfileSegmentation<T>;
