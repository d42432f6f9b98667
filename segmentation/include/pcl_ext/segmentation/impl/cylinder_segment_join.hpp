/*
 * pcl_ext: joining the segments that lie on one cylinder, implementation.
 */
#pragma once

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/cylinder_segment_join.h>
#include <pcl_ext/segmentation/profile_stacks.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace pcl_ext {
template <typename PointT>
void
CylinderSegmentJoin<PointT>::join (std::vector<pcl::PointIndices>& segments)
{
  const char* name = "CylinderSegmentJoin::join";
  segments.clear();
  cylinders_.clear();
  used_spacing_ = 0.0;
  used_ = cylinder_join::JoinParameters();
  cylinder_join::JoinParameters p;
  if (!(spacing_ >= 0.0) || !std::isfinite (spacing_)) {
    PCL_ERROR ("[pcl_ext::%s] Invalid point spacing %g: need 0 (estimated) or > 0.\n",
               name,
               spacing_);
    return;
  }
  if (!initCompute()) {
    PCL_ERROR ("[pcl_ext::%s] No input cloud.\n", name);
    return;
  }
  const std::size_t cloud_size = input_->size();
  for (const auto& segment : segments_)
    for (const auto index : segment.indices)
      if (index < 0 || static_cast<std::size_t> (index) >= cloud_size) {
        PCL_ERROR ("[pcl_ext::%s] A segment holds index %d, outside the cloud of %zu "
                   "points.\n",
                   name,
                   static_cast<int> (index),
                   cloud_size);
        deinitCompute();
        return;
      }

  // The finite points of the segments, centred in double (georeferenced clouds keep
  // their precision); a point listed in several segments belongs to the first.
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> position (cloud_size, kUnset);
  std::vector<pcl::index_t> cloud_index;
  std::vector<std::vector<std::uint32_t>> by_position (segments_.size());
  std::vector<std::vector<pcl::index_t>> not_finite (segments_.size());
  std::vector<std::uint8_t> claimed (cloud_size, 0);
  bool repeated = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (std::size_t s = 0; s < segments_.size(); ++s)
    for (const auto index : segments_[s].indices) {
      if (claimed[index]) {
        repeated = true;
        continue;
      }
      claimed[index] = 1;
      if (!pcl::isXYZFinite ((*input_)[index])) {
        not_finite[s].push_back (index);
        continue;
      }
      position[index] = static_cast<std::uint32_t> (cloud_index.size());
      by_position[s].push_back (position[index]);
      cloud_index.push_back (index);
      centre += (*input_)[index].getVector3fMap().template cast<double>();
    }
  if (repeated)
    PCL_WARN ("[pcl_ext::%s] Some points are in several segments; each stays with the "
              "first.\n",
              name);
  if (!cloud_index.empty())
    centre /= static_cast<double> (cloud_index.size());
  std::vector<Eigen::Vector3d> xyz (cloud_index.size());
  for (std::size_t i = 0; i < cloud_index.size(); ++i)
    xyz[i] =
        (*input_)[cloud_index[i]].getVector3fMap().template cast<double>() - centre;

  if (!resolveLengths (xyz, p)) {
    PCL_ERROR ("[pcl_ext::%s] The point spacing cannot be estimated (fewer than 7 "
               "distinct points); set it, or the lengths.\n",
               name);
    deinitCompute();
    return;
  }
  if (!cylinder_join::validParameters (p)) {
    PCL_ERROR (
        "[pcl_ext::%s] Invalid parameters: need a distance tolerance > 0, 0 < minimum "
        "radius <= maximum radius, a neighbourhood radius > 0, at least one "
        "hypothesis, "
        "a minimum cylinder size >= 3, shares in [0, 1] (radius difference below 1), "
        "a maximum gap and axis offset >= 0, and 0 <= maximum axis angle < minimum "
        "elbow angle <= pi/2.\n",
        name);
    deinitCompute();
    return;
  }
  used_ = p;

  cylinder_join::JoinResult result;
  if (!cylinder_join::joinCylinderSegments (xyz, by_position, p, result)) {
    PCL_ERROR ("[pcl_ext::%s] Invalid input.\n", name);
    deinitCompute();
    return;
  }

  std::vector<pcl::PointIndices> joined (result.num_segments);
  for (std::size_t i = 0; i < cloud_index.size(); ++i)
    if (result.labels[i] != cylinder_join::kNoSegment)
      joined[result.labels[i]].indices.push_back (cloud_index[i]);
  // Points that cannot be fitted go where most of their segment went (or stay as it
  // was).
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    if (not_finite[s].empty())
      continue;
    std::vector<std::size_t> votes (result.num_segments, 0);
    for (const auto i : by_position[s])
      ++votes[result.labels[i]];
    const auto most = std::max_element (votes.begin(), votes.end());
    if (most == votes.end() || *most == 0) {
      joined.emplace_back();
      joined.back().indices = not_finite[s];
    }
    else {
      auto& target = joined[most - votes.begin()].indices;
      target.insert (target.end(), not_finite[s].begin(), not_finite[s].end());
    }
  }

  // Largest first, as the segmenters order theirs.
  for (auto& segment : joined) {
    std::sort (segment.indices.begin(), segment.indices.end());
    segment.header = input_->header;
  }
  std::vector<std::size_t> order (joined.size());
  std::iota (order.begin(), order.end(), 0);
  std::stable_sort (order.begin(), order.end(), [&] (std::size_t a, std::size_t b) {
    if (joined[a].indices.size() != joined[b].indices.size())
      return joined[a].indices.size() > joined[b].indices.size();
    return joined[a].indices.front() < joined[b].indices.front();
  });
  std::vector<int> rank (joined.size());
  segments.reserve (joined.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = static_cast<int> (k);
    segments.push_back (std::move (joined[order[k]]));
  }

  for (auto& piece : result.pieces) {
    for (auto& i : piece.cylinder.inliers)
      i = static_cast<std::uint32_t> (cloud_index[i]);
    piece.cylinder.point += centre;
    cylinders_.push_back (
        {std::move (piece.cylinder),
         piece.segment,
         piece.joined == cylinder_join::kNoSegment ? -1 : rank[piece.joined]});
  }
  deinitCompute();
}

template <typename PointT>
cylinder_join::JoinParameters
CylinderSegmentJoin<PointT>::getParameters (double spacing) const
{
  cylinder_join::JoinParameters p = parameters_;
  p.threads = resolveThreadCount (threads_);
  p.detection.distance_tolerance = tolerance_.value_or (tolerance_factor_ * spacing);
  p.detection.min_radius = min_radius_.value_or (min_radius_factor_ * spacing);
  p.detection.max_radius = max_radius_.value_or (max_radius_factor_ * spacing);
  p.detection.neighbourhood_radius =
      neighbourhood_radius_.value_or (neighbourhood_factor_ * spacing);
  p.max_gap = max_gap_.value_or (max_gap_factor_ * spacing);
  return p;
}

template <typename PointT>
bool
CylinderSegmentJoin<PointT>::resolveLengths (const std::vector<Eigen::Vector3d>& xyz,
                                             cylinder_join::JoinParameters& p)
{
  used_spacing_ = spacing_;
  if (getLengthsFollowSpacing() && !(used_spacing_ > 0.0)) {
    std::vector<Eigen::Vector3f> points (xyz.size());
    for (std::size_t i = 0; i < xyz.size(); ++i)
      points[i] = xyz[i].cast<float>();
    used_spacing_ = profiles::estimatePointSpacing (points);
    if (!(used_spacing_ > 0.0))
      return false;
  }
  p = getParameters (used_spacing_);
  return true;
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_CylinderSegmentJoin(T)                                     \
  template class pcl_ext::CylinderSegmentJoin<T>;
