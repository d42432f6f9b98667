/*
 * pcl_ext: LeftoverRegionGrowing implementation.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/common/union_find.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

template <typename PointT>
bool
pcl_ext::LeftoverRegionGrowing<PointT>::checkInputs (const char* name) const
{
  const std::size_t n = input_->size();
  if (n == 0) {
    PCL_ERROR ("%s The input cloud is empty.\n", name);
    return false;
  }
  if (!onePerPoint (segments_.get(), n, name, "segment label", "setSegmentLabels") ||
      !indicesInRange (*indices_, n, name) ||
      (linking_ && !indicesInRange (*linking_, n, name)))
    return false;
  if (!this->checkNeighbourhoodOptions (name, 3))
    return false;
  if (!(angle_ >= 0.0 && angle_ <= 0.5 * M_PI)) {
    PCL_ERROR ("%s angle threshold = %g rad; valid: 0 .. pi/2.\n", name, angle_);
    return false;
  }
  if (!(max_curvature_ >= 0.0) || !std::isfinite (max_curvature_)) {
    PCL_ERROR ("%s maximum curvature = %g; it must be finite and >= 0.\n",
               name,
               max_curvature_);
    return false;
  }
  if (normal_k_ < 3) {
    PCL_ERROR (
        "%s normal k = %d; a normal needs at least 3 points.\n", name, normal_k_);
    return false;
  }
  if (!validClusterSizes()) {
    PCL_ERROR ("%s Need 1 <= minimum cluster size (%u) <= maximum cluster size (%u).\n",
               name,
               static_cast<unsigned int> (min_size_),
               static_cast<unsigned int> (max_size_));
    return false;
  }
  return true;
}

template <typename PointT>
bool
pcl_ext::LeftoverRegionGrowing<PointT>::compute (LabelCloud& output)
{
  const char* const name = "[pcl_ext::LeftoverRegionGrowing::compute]";
  output.clear();
  output.width = output.height = 0;
  report_ = Report();
  if (!initCompute()) {
    PCL_ERROR ("%s No input cloud.\n", name);
    return false;
  }
  if (!checkInputs (name)) {
    deinitCompute();
    return false;
  }
  const std::size_t n = input_->size();
  if (n > static_cast<std::size_t> (INT32_MAX)) {
    PCL_ERROR ("%s %zu points; at most %d.\n", name, n, INT32_MAX);
    deinitCompute();
    return false;
  }
  // The points that take part (indexed, finite, without a segment, with a row), in
  // index order; per-point arrays hold only their slot, the rest is per taking part.
  std::vector<std::int32_t> slot (n, -1);
  std::vector<pcl::index_t> point;
  std::vector<std::ptrdiff_t> row_of_slot;
  for (const auto i : *indices_)
    if ((*segments_)[i].label == 0 && pcl::isFinite ((*input_)[i]))
      slot[static_cast<std::size_t> (i)] = 0;
  // Whole-cloud rows (a point's neighbours need not be among the indices), of those
  // points alone: shared rows of only them will do.
  std::vector<pcl::index_t> candidates;
  for (std::size_t i = 0; i < n; ++i)
    if (slot[i] == 0)
      candidates.push_back (static_cast<pcl::index_t> (i));
  const Neighbourhoods<PointT>* const nb = this->prepareNeighbourhoodsCovering (
      "LeftoverRegionGrowing::compute", input_, candidates);
  candidates = std::vector<pcl::index_t>();
  if (!nb) {
    deinitCompute();
    return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (slot[i] < 0)
      continue;
    ++report_.examined;
    const std::ptrdiff_t r = nb->getRowOfPoint (static_cast<pcl::index_t> (i));
    if (r < 0) {
      slot[i] = -1;
      continue;
    }
    slot[i] = static_cast<std::int32_t> (point.size());
    point.push_back (static_cast<pcl::index_t> (i));
    row_of_slot.push_back (r);
  }
  const std::size_t m_points = point.size();

  // Each one's normal and surface variance from its nearest normal_k_ neighbours
  // (normal zero: none).
  std::vector<Eigen::Vector3f> normal (m_points, Eigen::Vector3f::Zero());
  std::vector<float> curvature (m_points, 0.0f);
  const std::size_t normal_k = static_cast<std::size_t> (normal_k_);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (m_points);
#pragma omp parallel for num_threads(resolveThreadCount(this->threads_))               \
    schedule(dynamic, 256)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const auto row = (*nb)[static_cast<std::size_t> (row_of_slot[s])];
    const std::size_t m = std::min (row.size(), normal_k);
    if (m >= 3)
      fitPatchNormal (*input_, row.begin(), row.begin() + m, normal[s], curvature[s]);
  }

  // Links both ways between smooth points without a segment whose normals agree; the
  // groups are the components, whatever the order of the links. A point on a crease
  // (its patch's surface variance above the maximum) links nothing, so that a chain of
  // normals turning a little from point to point cannot cross the crease; it joins the
  // group of its smooth neighbour of the closest normal within the angle.
  const float min_cos = static_cast<float> (std::cos (angle_));
  const auto smooth = [&] (std::int32_t s) {
    return !normal[s].isZero() && !(curvature[s] > max_curvature_);
  };
  // The slot of a neighbour that takes part, or -1.
  const auto slotOf = [&slot] (pcl::index_t j) {
    return j < 0 ? -1 : slot[static_cast<std::size_t> (j)];
  };
  // Which of them make links of their own (setLinkingIndices).
  std::vector<char> links (m_points, linking_ ? 0 : 1);
  if (linking_)
    for (const auto i : *linking_)
      if (slot[static_cast<std::size_t> (i)] >= 0)
        links[static_cast<std::size_t> (slot[static_cast<std::size_t> (i)])] = 1;
  UnionFind groups (m_points);
  std::vector<std::int32_t> attach (m_points, -1);
  for (std::size_t s = 0; s < m_points; ++s) {
    if (normal[s].isZero() || !links[s])
      continue;
    const auto row = (*nb)[static_cast<std::size_t> (row_of_slot[s])];
    const std::size_t m = std::min (row.size(), normal_k);
    const bool linking = smooth (static_cast<std::int32_t> (s));
    float best = min_cos;
    for (std::size_t k = 0; k < m; ++k) {
      const std::int32_t t = slotOf (row.begin()[k]);
      if (t < 0 || static_cast<std::size_t> (t) == s || !smooth (t))
        continue;
      const float c = std::abs (normal[s].dot (normal[t]));
      if (linking) {
        if (c >= min_cos)
          groups.unite (static_cast<std::uint32_t> (s), static_cast<std::uint32_t> (t));
      }
      else if (c >= best) {
        best = c;
        attach[s] = t;
      }
    }
  }
  for (std::size_t s = 0; s < m_points; ++s)
    if (attach[s] >= 0)
      groups.unite (static_cast<std::uint32_t> (s),
                    static_cast<std::uint32_t> (attach[s]));
  std::vector<std::uint32_t> size (m_points, 0);
  for (std::size_t s = 0; s < m_points; ++s)
    ++size[groups.find (static_cast<std::uint32_t> (s))];
  // Roots are the smallest slot of their group, slots follow the point indices, so this
  // order breaks size ties by the smallest point index.
  std::vector<std::uint32_t> kept;
  for (std::size_t s = 0; s < m_points; ++s)
    if (size[s] > 0 && keepsClusterSize (size[s]))
      kept.push_back (static_cast<std::uint32_t> (s));
  std::stable_sort (
      kept.begin(), kept.end(), [&size] (std::uint32_t a, std::uint32_t b) {
        return size[a] > size[b];
      });

  std::uint32_t next = 0;
  for (const auto& l : *segments_)
    next = std::max (next, l.label);
  std::vector<std::uint32_t> id (m_points, 0);
  for (const auto root : kept)
    id[root] = ++next;
  output = *segments_;
  for (std::size_t s = 0; s < m_points; ++s) {
    const std::uint32_t l = id[groups.find (static_cast<std::uint32_t> (s))];
    if (l != 0) {
      output[static_cast<std::size_t> (point[s])].label = l;
      ++report_.segmented;
    }
  }
  report_.segments = kept.size();
  this->releaseNeighbourhoods();
  deinitCompute();
  return true;
}

#define PCL_EXT_INSTANTIATE_LeftoverRegionGrowing(T)                                   \
  template class pcl_ext::LeftoverRegionGrowing<T>;
