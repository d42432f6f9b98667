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
      !indicesInRange (*indices_, n, name))
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
  if (min_size_ < 1) {
    PCL_ERROR ("%s minimum cluster size = 0; it must be at least 1.\n", name);
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
  if (n > static_cast<std::size_t> (UINT32_MAX)) {
    PCL_ERROR ("%s %zu points; at most %u.\n", name, n, UINT32_MAX);
    deinitCompute();
    return false;
  }
  // Whole-cloud rows: a point's neighbours need not be among the indices.
  const Neighbourhoods<PointT>* const nb = this->prepareNeighbourhoods (
      "LeftoverRegionGrowing::compute", input_, pcl::IndicesConstPtr());
  if (!nb) {
    deinitCompute();
    return false;
  }
  const auto row_of = [nb] (std::size_t i) {
    return nb->getRowOfPoint (static_cast<pcl::index_t> (i));
  };

  // The points that take part: indexed, finite, without a segment.
  std::vector<char> left (n, 0);
  for (const auto i : *indices_)
    if ((*segments_)[i].label == 0 && pcl::isFinite ((*input_)[i]) && !left[i]) {
      left[i] = 1;
      ++report_.examined;
    }

  // Each one's normal from its nearest normal_k_ neighbours (zero: none).
  std::vector<Eigen::Vector3f> normal (n, Eigen::Vector3f::Zero());
  std::vector<float> curvature (n, 0.0f);
  const std::size_t normal_k = static_cast<std::size_t> (normal_k_);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
#pragma omp parallel for num_threads(resolveThreadCount(this->threads_))               \
    schedule(dynamic, 256)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    if (!left[i])
      continue;
    const std::ptrdiff_t r = row_of (static_cast<std::size_t> (i));
    if (r < 0)
      continue;
    const auto row = (*nb)[static_cast<std::size_t> (r)];
    const std::size_t m = std::min (row.size(), normal_k);
    Eigen::Matrix3d covariance;
    Eigen::Vector3d centroid;
    EigenDecomposition eigen;
    if (m < 3 ||
        computeLocalCovariance (
            *input_, row.begin(), row.begin() + m, covariance, centroid) < 3 ||
        !computeEigenDecomposition (covariance, eigen) || !(eigen.values (2) > 0.0))
      continue;
    normal[i] = eigen.normal().template cast<float>();
    curvature[i] = static_cast<float> (surfaceVariance (eigen.values));
  }

  // Links both ways between smooth points without a segment whose normals agree; the
  // groups are the components, whatever the order of the links. A point on a crease
  // (its patch's surface variance above the maximum) links nothing, so that a chain of
  // normals turning a little from point to point cannot cross the crease; it joins the
  // group of its smooth neighbour of the closest normal within the angle.
  const float min_cos = static_cast<float> (std::cos (angle_));
  const auto smooth = [&] (std::size_t i) {
    return !normal[i].isZero() && !(curvature[i] > max_curvature_);
  };
  UnionFind groups (n);
  for (std::size_t i = 0; i < n; ++i) {
    // A point with a normal has a row.
    if (!left[i] || !smooth (i))
      continue;
    const auto row = (*nb)[static_cast<std::size_t> (row_of (i))];
    const std::size_t m = std::min (row.size(), normal_k);
    for (std::size_t k = 0; k < m; ++k) {
      const pcl::index_t j = row.begin()[k];
      if (j < 0 || static_cast<std::size_t> (j) == i || !left[j] || !smooth (j))
        continue;
      if (std::abs (normal[i].dot (normal[j])) >= min_cos)
        groups.unite (static_cast<std::uint32_t> (i), static_cast<std::uint32_t> (j));
    }
  }
  std::vector<std::int64_t> attach (n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (!left[i] || normal[i].isZero() || smooth (i))
      continue;
    const auto row = (*nb)[static_cast<std::size_t> (row_of (i))];
    const std::size_t m = std::min (row.size(), normal_k);
    float best = min_cos;
    for (std::size_t k = 0; k < m; ++k) {
      const pcl::index_t j = row.begin()[k];
      if (j < 0 || !left[j] || !smooth (j))
        continue;
      const float c = std::abs (normal[i].dot (normal[j]));
      if (c >= best) {
        best = c;
        attach[i] = j;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (attach[i] >= 0)
      groups.unite (static_cast<std::uint32_t> (i),
                    static_cast<std::uint32_t> (attach[i]));
  std::vector<std::uint32_t> size (n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (left[i])
      ++size[groups.find (static_cast<std::uint32_t> (i))];
  // Roots are the smallest index of their group, so this order breaks size ties by it.
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (size[i] >= min_size_)
      kept.push_back (static_cast<std::uint32_t> (i));
  std::stable_sort (
      kept.begin(), kept.end(), [&size] (std::uint32_t a, std::uint32_t b) {
        return size[a] > size[b];
      });

  std::uint32_t next = 0;
  for (const auto& l : *segments_)
    next = std::max (next, l.label);
  std::vector<std::uint32_t> id (n, 0);
  for (const auto root : kept)
    id[root] = ++next;
  output = *segments_;
  for (std::size_t i = 0; i < n; ++i) {
    if (!left[i])
      continue;
    const std::uint32_t l = id[groups.find (static_cast<std::uint32_t> (i))];
    if (l != 0) {
      output[i].label = l;
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
