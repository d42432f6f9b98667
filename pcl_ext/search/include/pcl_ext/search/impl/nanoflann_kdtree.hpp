/*
 * pcl_ext: NanoflannKdTree implementation.
 */
#pragma once

#include <pcl_ext/search/nanoflann_kdtree.h>
#include <pcl_ext/common/parallel.h>

#include <pcl/common/point_tests.h>

template <typename PointT>
pcl_ext::search::NanoflannKdTree<PointT>::NanoflannKdTree (bool sorted,
                                                           unsigned int leaf_size)
: pcl::search::Search<PointT> ("NanoflannKdTree", sorted), leaf_size_ (leaf_size)
{}

template <typename PointT>
void
pcl_ext::search::NanoflannKdTree<PointT>::setInputCloud (
    const PointCloudConstPtr& cloud, const IndicesConstPtr& indices)
{
  input_ = cloud;
  indices_ = indices;
  std::vector<float> xyz;
  std::vector<pcl::index_t> ids;
  if (cloud) {
    const std::size_t n = indices ? indices->size() : cloud->size();
    xyz.reserve (3 * n);
    ids.reserve (n);
    for (std::size_t i = 0; i < n; ++i) {
      const pcl::index_t idx = indices ? (*indices)[i] : static_cast<pcl::index_t> (i);
      if (idx < 0 || static_cast<std::size_t> (idx) >= cloud->size())
        continue;
      const PointT& p = (*cloud)[idx];
      if (!pcl::isFinite (p))
        continue;
      xyz.insert (xyz.end(), {p.x, p.y, p.z});
      ids.push_back (idx);
    }
  }
  tree_.build (
      std::move (xyz), std::move (ids), leaf_size_, resolveThreadCount (threads_));
}

template <typename PointT>
int
pcl_ext::search::NanoflannKdTree<PointT>::nearestKSearch (
    const PointT& point,
    int k,
    pcl::Indices& k_indices,
    std::vector<float>& k_sqr_distances) const
{
  k_indices.clear();
  k_sqr_distances.clear();
  if (k <= 0 || !pcl::isFinite (point))
    return 0;
  const std::size_t want =
      std::min<std::size_t> (static_cast<std::size_t> (k), tree_.size());
  k_indices.resize (want);
  k_sqr_distances.resize (want);
  const float q[3] = {point.x, point.y, point.z};
  const std::size_t found =
      tree_.nearestKSearch (q, want, k_indices.data(), k_sqr_distances.data());
  k_indices.resize (found);
  k_sqr_distances.resize (found);
  return static_cast<int> (found);
}

template <typename PointT>
int
pcl_ext::search::NanoflannKdTree<PointT>::radiusSearch (
    const PointT& point,
    double radius,
    pcl::Indices& k_indices,
    std::vector<float>& k_sqr_distances,
    unsigned int max_nn) const
{
  if (!pcl::isFinite (point)) {
    k_indices.clear();
    k_sqr_distances.clear();
    return 0;
  }
  const float q[3] = {point.x, point.y, point.z};
  return static_cast<int> (tree_.radiusSearch (
      q, radius, k_indices, k_sqr_distances, max_nn, sorted_results_));
}

#define PCL_EXT_INSTANTIATE_NanoflannKdTree(T)                                         \
  template class pcl_ext::search::NanoflannKdTree<T>;
