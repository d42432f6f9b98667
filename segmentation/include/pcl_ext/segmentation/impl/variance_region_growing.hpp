/*
 * pcl_ext: VarianceRegionGrowing implementation.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/features/local_variance.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/common/segment_colours.h>
#include <pcl_ext/segmentation/impl/local_planes.hpp>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <numeric>

template <typename PointT>
bool
pcl_ext::VarianceRegionGrowing<PointT>::checkParameters() const
{
  const char* const name = "[pcl_ext::VarianceRegionGrowing::extract]";
  if (!(max_distance_ >= 0.0) || !std::isfinite (max_distance_)) {
    PCL_ERROR ("%s maximum distance = %g; it must be finite and >= 0 (0: no limit).\n",
               name,
               max_distance_);
    return false;
  }
  if (!(max_distance_factor_ >= 0.0) || !std::isfinite (max_distance_factor_)) {
    PCL_ERROR (
        "%s maximum distance factor = %g; it must be finite and >= 0 (0: none).\n",
        name,
        max_distance_factor_);
    return false;
  }
  if (!validClusterSizes()) {
    PCL_ERROR ("%s Need 1 <= minimum cluster size (%u) <= maximum cluster size (%u).\n",
               name,
               static_cast<unsigned int> (min_size_),
               static_cast<unsigned int> (max_size_));
    return false;
  }
  return this->checkNeighbourhoodOptions (name, static_cast<int> (kMinNeighbours));
}

template <typename PointT>
bool
pcl_ext::VarianceRegionGrowing<PointT>::checkClasses() const
{
  if (!classes_) {
    PCL_ERROR ("[pcl_ext::VarianceRegionGrowing::extract] No point classes: give the "
               "output of "
               "LocalVarianceClassification::classify with setInputClasses.\n");
    return false;
  }
  if (classes_->size() != indices_->size()) {
    PCL_ERROR (
        "[pcl_ext::VarianceRegionGrowing::extract] %zu class labels for %zu points; "
        "give one per index (LocalVarianceClassification::classify).\n",
        static_cast<std::size_t> (classes_->size()),
        indices_->size());
    return false;
  }
  return true;
}

template <typename PointT>
void
pcl_ext::VarianceRegionGrowing<PointT>::extract (
    std::vector<pcl::PointIndices>& clusters)
{
  const char* const name = "[pcl_ext::VarianceRegionGrowing::extract]";
  clusters.clear();
  clusters_.clear();
  planes_.clear();
  if (!checkParameters())
    return;
  if (!initCompute()) {
    PCL_ERROR ("%s No input cloud.\n", name);
    return;
  }
  if (input_->empty() || indices_->empty()) {
    PCL_ERROR ("%s Nothing to segment: the %s empty.\n",
               name,
               input_->empty() ? "input cloud is" : "indices are");
    deinitCompute();
    return;
  }
  if (!checkClasses()) {
    deinitCompute();
    return;
  }
  const Neighbourhoods<PointT>* const nb =
      this->prepareNeighbourhoods ("VarianceRegionGrowing::extract",
                                   input_,
                                   fake_indices_ ? pcl::IndicesConstPtr() : indices_);
  if (!nb) {
    deinitCompute();
    return;
  }

  // The class of every point taking part; -1 for points outside the indices.
  std::vector<std::int8_t> class_of_point (input_->size(), -1);
  std::size_t surface = 0;
  for (std::size_t r = 0; r < indices_->size(); ++r) {
    const std::uint32_t c = (*classes_)[r].label;
    class_of_point[(*indices_)[r]] =
        static_cast<std::int8_t> (c < kNumPointClasses ? c : 0);
    surface += c == static_cast<std::uint32_t> (PointClass::Surface);
  }
  if (surface == 0) {
    PCL_ERROR (
        "%s No surface point among the %zu points: nothing to grow from (are the "
        "classification thresholds right for this cloud?).\n",
        name,
        indices_->size());
    this->releaseNeighbourhoods();
    deinitCompute();
    return;
  }

  // Per row, how many of its neighbours lie within the seed's distance limit: the
  // smaller of the fixed limit and the factor times the seed's local spacing
  // s = r_m sqrt(pi / m), m half its neighbours (the row holds the seed first). A row
  // that is not a seed's links nothing.
  std::vector<std::uint32_t> reach;
  const bool limited = max_distance_ > 0.0 || max_distance_factor_ > 0.0 || seeds_;
  if (limited) {
    std::vector<char> seed;
    if (seeds_) {
      seed.assign (input_->size(), 0);
      for (const auto i : *seeds_)
        if (i >= 0 && static_cast<std::size_t> (i) < seed.size())
          seed[i] = 1;
    }
    const float max_sqr = max_distance_ > 0.0
                              ? static_cast<float> (max_distance_ * max_distance_)
                              : std::numeric_limits<float>::infinity();
    const double f2 = max_distance_factor_ * max_distance_factor_;
    const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
    reach.assign (indices_->size(), 0);
#pragma omp parallel for num_threads(resolveThreadCount(threads_)) schedule(static)
    for (std::ptrdiff_t r = 0; r < rows; ++r) {
      if (!seed.empty() && !seed[(*indices_)[r]])
        continue;
      // A point without neighbourhood (NaN, or none found) has an empty row.
      const std::size_t row_size = (*nb)[r].size();
      float limit = max_sqr;
      const std::size_t m = row_size > 0 ? (row_size - 1) / 2 : 0;
      if (max_distance_factor_ > 0.0 && m >= kMinSpacingNeighbour)
        limit = std::min (
            max_sqr,
            static_cast<float> (f2 * 3.141592653589793 / static_cast<double> (m)) *
                nb->getSquaredDistance (r, m));
      // The row is sorted by distance, so those within the limit are a prefix: its
      // length by bisection.
      std::size_t within = 0, beyond = row_size;
      while (within < beyond) {
        const std::size_t middle = within + (beyond - within) / 2;
        if (nb->getSquaredDistance (r, middle) > limit)
          beyond = middle;
        else
          within = middle + 1;
      }
      reach[r] = static_cast<std::uint32_t> (within);
    }
  }
  std::vector<std::int32_t> root;
  growSurfaceSegments (nb->getRows(), *indices_, class_of_point, reach, threads_, root);

  // Segments from the roots, within the size limits, largest first.
  std::vector<std::uint32_t> size (input_->size(), 0);
  for (const auto r : root)
    if (r >= 0)
      ++size[r];
  std::vector<std::int32_t> slot (input_->size(), -1);
  std::vector<pcl::index_t> kept;
  for (std::size_t i = 0; i < input_->size(); ++i)
    if (keepsClusterSize (size[i]) && size[i] > 0)
      kept.push_back (static_cast<pcl::index_t> (i));
  // Roots are the smallest index of their segment, so this order breaks size ties by
  // it.
  std::stable_sort (kept.begin(), kept.end(), [&size] (pcl::index_t a, pcl::index_t b) {
    return size[a] > size[b];
  });
  clusters_.resize (kept.size());
  for (std::size_t c = 0; c < kept.size(); ++c) {
    slot[kept[c]] = static_cast<std::int32_t> (c);
    clusters_[c].indices.reserve (size[kept[c]]);
    clusters_[c].header = input_->header;
  }
  for (std::size_t i = 0; i < input_->size(); ++i)
    if (root[i] >= 0 && slot[root[i]] >= 0)
      clusters_[slot[root[i]]].indices.push_back (static_cast<pcl::index_t> (i));

  if (fit_planes_) {
    planes_.resize (clusters_.size());
    const Eigen::Vector3d viewpoint =
        input_->sensor_origin_.template head<3>().template cast<double>();
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (clusters_.size());
#pragma omp parallel for num_threads(resolveThreadCount(threads_))                     \
    schedule(dynamic, 1) default(none) shared(n, viewpoint)
    for (std::ptrdiff_t c = 0; c < n; ++c)
      planes_[c] = fitSegmentPlane (*input_, clusters_[c].indices, viewpoint);
  }
  this->releaseNeighbourhoods();
  clusters = clusters_;
  deinitCompute();
}

template <typename PointT>
void
pcl_ext::VarianceRegionGrowing<PointT>::getSegmentLabels (LabelCloud& labels) const
{
  labels.clear();
  labels.width = labels.height = 0;
  if (!input_ || clusters_.empty())
    return;
  labels.resize (input_->size());
  labels.width = input_->width;
  labels.height = input_->height;
  labels.header = input_->header;
  labels.is_dense = true;
  for (auto& l : labels)
    l.label = 0;
  for (std::size_t c = 0; c < clusters_.size(); ++c)
    for (const auto i : clusters_[c].indices)
      labels[i].label = static_cast<std::uint32_t> (c + 1);
}

template <typename PointT>
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
pcl_ext::VarianceRegionGrowing<PointT>::getColoredCloud() const
{
  if (!input_)
    return pcl::PointCloud<pcl::PointXYZRGB>::Ptr (
        new pcl::PointCloud<pcl::PointXYZRGB>);
  return colourBySegment (*input_, clusters_);
}

#define PCL_EXT_INSTANTIATE_VarianceRegionGrowing(T)                                   \
  template class pcl_ext::VarianceRegionGrowing<T>;
