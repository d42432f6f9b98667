/*
 * pcl_ext: Neighbourhoods implementation.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/search/nanoflann_kdtree.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcl_ext {
namespace detail {
/** Neighbour lists of a contiguous run of query rows, gathered before their final place
 * in the CSR arrays is known (radius searches return varying counts). */
struct NeighbourBlock {
  std::vector<std::size_t> rows;
  std::vector<std::size_t> counts;
  pcl::Indices indices;
  std::vector<float> sqr_distances;
};
} // namespace detail
} // namespace pcl_ext

template <typename PointT>
void
pcl_ext::Neighbourhoods<PointT>::clear()
{
  rows_ = 0;
  stride_ = 0;
  offsets_.clear();
  indices_flat_.clear();
  sqr_distances_.clear();
  row_of_point_.clear();
  searchable_ = 0;
  computed_cloud_.reset();
  computed_indices_.reset();
}

template <typename PointT>
bool
pcl_ext::Neighbourhoods<PointT>::validate()
{
  if (input_->empty()) {
    PCL_ERROR ("[pcl_ext::Neighbourhoods::compute] The input cloud is empty.\n");
    return false;
  }
  const bool use_k = k_ != 0;
  const bool use_radius = radius_ != 0.0;
  if (use_k == use_radius) {
    PCL_ERROR (
        "[pcl_ext::Neighbourhoods::compute] Set exactly one of k (setKSearch) and the "
        "radius (setRadiusSearch).\n");
    return false;
  }
  if (use_k && k_ < 1) {
    PCL_ERROR ("[pcl_ext::Neighbourhoods::compute] k = %d; it must be at least 1.\n",
               k_);
    return false;
  }
  if (use_radius && !(radius_ > 0.0 && std::isfinite (radius_))) {
    PCL_ERROR (
        "[pcl_ext::Neighbourhoods::compute] radius = %g; it must be positive and "
        "finite.\n",
        radius_);
    return false;
  }
  if (!(max_radius_ >= 0.0 && std::isfinite (max_radius_))) {
    PCL_ERROR (
        "[pcl_ext::Neighbourhoods::compute] maximum radius = %g; it must be finite and "
        ">= 0 (0: none).\n",
        max_radius_);
    return false;
  }
  return indicesInRange (
      *indices_, input_->size(), "[pcl_ext::Neighbourhoods::compute]");
}

template <typename PointT>
bool
pcl_ext::Neighbourhoods<PointT>::compute()
{
  clear();
  if (!initCompute())
    return false;
  if (!validate()) {
    deinitCompute();
    return false;
  }

  // The default search; a NanoflannKdTree (ours or the user's) is queried without
  // allocation. Ours is dropped after the search: the rows are what is kept (the tree
  // would add about 24 bytes a point to them).
  const bool own_search = !search_;
  if (own_search) {
    auto own = pcl::make_shared<search::NanoflannKdTree<PointT>>();
    own->setNumberOfThreads (threads_);
    search_ = own;
  }
  search_->setInputCloud (input_);
  const auto* tree =
      dynamic_cast<const search::NanoflannKdTree<PointT>*> (search_.get());

  searchable_ = 0;
  for (const auto& p : *input_)
    searchable_ += pcl::isFinite (p) ? 1 : 0;
  if (searchable_ == 0) {
    PCL_ERROR ("[pcl_ext::Neighbourhoods::compute] The cloud has no finite point.\n");
    if (own_search)
      search_.reset();
    clear();
    deinitCompute();
    return false;
  }
  if (k_ > 0 && static_cast<std::size_t> (k_) > searchable_) {
    PCL_ERROR ("[pcl_ext::Neighbourhoods::compute] k = %d is larger than the %zu "
               "finite points "
               "of the cloud.\n",
               k_,
               searchable_);
    if (own_search)
      search_.reset();
    clear();
    deinitCompute();
    return false;
  }

  if (tree && k_ > 0)
    searchWithTree();
  else
    searchWithSearchMethod();
  if (k_ > 0 && max_radius_ > 0.0)
    capRows();

  if (!fake_indices_) {
    row_of_point_.assign (input_->size(), -1);
    for (std::size_t r = 0; r < indices_->size(); ++r)
      if (row_of_point_[(*indices_)[r]] < 0)
        row_of_point_[(*indices_)[r]] = static_cast<std::ptrdiff_t> (r);
  }
  computed_cloud_ = input_;
  computed_indices_ = indices_;
  computed_fake_indices_ = fake_indices_;
  if (own_search)
    search_.reset();
  deinitCompute();
  return true;
}

template <typename PointT>
float
pcl_ext::Neighbourhoods<PointT>::getSquaredDistance (std::size_t row,
                                                     std::size_t i) const
{
  const std::size_t at = getRows().begin (row) + i;
  if (!sqr_distances_.empty())
    return sqr_distances_[at];
  // As the tree ranks its candidates: neighbour minus query, summed x, y, z.
  const PointT& q = (*computed_cloud_)[(*computed_indices_)[row]];
  const PointT& p = (*computed_cloud_)[indices_flat_[at]];
  const float dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
  return dx * dx + dy * dy + dz * dz;
}

template <typename PointT>
void
pcl_ext::Neighbourhoods<PointT>::capRows()
{
  // In place, front to back: a row only moves towards the front. The comparison is the
  // one a radius search makes (squared distance <= squared radius, in float). Rows of
  // k entries become rows with offsets.
  const float limit = static_cast<float> (max_radius_ * max_radius_);
  const NeighbourRowsView view = getRows();
  std::vector<std::size_t> offsets (rows_ + 1, 0);
  std::size_t out = 0;
  for (std::size_t r = 0; r < rows_; ++r) {
    const std::size_t begin = view.begin (r), count = view.size (r);
    offsets[r] = out;
    const PointT* q = count > 0 ? &(*input_)[(*indices_)[r]] : nullptr;
    for (std::size_t j = begin; j < begin + count; ++j, ++out) {
      float d2;
      if (store_sqr_distances_)
        d2 = sqr_distances_[j];
      else {
        const PointT& p = (*input_)[indices_flat_[j]];
        const float dx = p.x - q->x, dy = p.y - q->y, dz = p.z - q->z;
        d2 = dx * dx + dy * dy + dz * dz;
      }
      if (d2 > limit)
        break;
      indices_flat_[out] = indices_flat_[j];
      if (store_sqr_distances_)
        sqr_distances_[out] = d2;
    }
  }
  offsets[rows_] = out;
  offsets_.swap (offsets);
  stride_ = 0;
  indices_flat_.resize (out);
  indices_flat_.shrink_to_fit();
  if (store_sqr_distances_) {
    sqr_distances_.resize (out);
    sqr_distances_.shrink_to_fit();
  }
}

template <typename PointT>
void
pcl_ext::Neighbourhoods<PointT>::searchWithTree()
{
  const auto& tree =
      static_cast<const search::NanoflannKdTree<PointT>&> (*search_).getTree();
  const std::size_t rows = indices_->size();
  const std::size_t k = static_cast<std::size_t> (k_);

  // Every finite query gets exactly k neighbours (k <= finite points was checked), so
  // every row spans k entries and threads write straight into place; the rows of
  // points that are not finite hold -1s.
  rows_ = rows;
  stride_ = k;
  indices_flat_.assign (rows * k, -1);
  if (store_sqr_distances_)
    sqr_distances_.assign (rows * k, 0.0f);
  const bool store = store_sqr_distances_;

  const unsigned int threads = resolveThreadCount (threads_);
  // For the whole cloud, search leaf by leaf: the points of a leaf share most of their
  // neighbours, and the tree ranks one gathered set of candidates for all of them (see
  // KdTree3f::nearestKSearchOfPoints). Each point's result, ties included, does not
  // depend on the leaf or the thread it is searched in. Below about a leaf's worth of
  // neighbours the shared candidates are mostly other points' and one search per point
  // is faster (docs/shared_machinery.md has the timings).
  const bool whole_cloud = fake_indices_ && tree.size() == searchable_;
  if (whole_cloud && k >= kMinNeighboursPerLeafSearch) {
    const auto leaves = tree.leafRanges();
#pragma omp parallel num_threads(threads) default(none) shared(tree, k, leaves, store)
    {
      pcl::Indices nn;
      std::vector<float> d2;
#pragma omp for schedule(dynamic, 64)
      for (std::ptrdiff_t l = 0; l < static_cast<std::ptrdiff_t> (leaves.size()); ++l) {
        const std::size_t first = leaves[l].first, last = leaves[l].second;
        nn.resize ((last - first) * k);
        d2.resize (nn.size());
        tree.nearestKSearchOfPoints (first, last, k, nn.data(), d2.data());
        for (std::size_t pos = first; pos < last; ++pos) {
          const std::size_t at = static_cast<std::size_t> (tree.pointIndex (pos)) * k;
          std::copy_n (&nn[(pos - first) * k], k, &indices_flat_[at]);
          if (store)
            std::copy_n (&d2[(pos - first) * k], k, &sqr_distances_[at]);
        }
      }
    }
    return;
  }

  // One search per point, in the tree's leaf order (consecutive queries then walk the
  // same branches and leaves; for a subset of the cloud, its rows in the order of their
  // points in the tree). Each query's k-th distance bounds the next one's (|q' - x| <=
  // |q' - q| + |q - x|), so the search prunes from its first step. Work is split into
  // fixed runs of queries, each started without a bound, so the result (ties included)
  // is the same for any number of threads.
  std::vector<std::size_t> order;
  if (!whole_cloud)
    order = rowsInTreeOrder (tree);
  const std::size_t n = whole_cloud ? tree.size() : order.size();
  constexpr std::size_t run = 256;
  const std::ptrdiff_t num_runs = static_cast<std::ptrdiff_t> ((n + run - 1) / run);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1) default(none)       \
    shared(tree, k, n, num_runs, whole_cloud, store, order)
  for (std::ptrdiff_t r = 0; r < num_runs; ++r) {
    std::vector<float> scratch (store ? 0 : k);
    float previous[3] = {0, 0, 0};
    float previous_kth = -1.0f; // k-th distance of the previous query; < 0: none
    std::size_t previous_row = 0;
    const std::size_t last = std::min (n, static_cast<std::size_t> (r + 1) * run);
    for (std::size_t j = static_cast<std::size_t> (r) * run; j < last; ++j) {
      const std::size_t row =
          whole_cloud ? static_cast<std::size_t> (tree.pointIndex (j)) : order[j];
      float q[3];
      if (whole_cloud)
        std::copy_n (tree.point (j), 3, q);
      else {
        const PointT& p = (*input_)[(*indices_)[row]];
        q[0] = p.x;
        q[1] = p.y;
        q[2] = p.z;
      }
      float* d2 = store ? &sqr_distances_[row * k] : scratch.data();
      if (previous_kth == 0.0f && std::equal (q, q + 3, previous)) {
        // k or more copies of the previous query's point, and this query one of them:
        // the same k nearest (those of the smallest indices), without walking every
        // copy again (a stack of m copies would cost m^2).
        std::copy_n (&indices_flat_[previous_row * k], k, &indices_flat_[row * k]);
        if (store)
          std::copy_n (&sqr_distances_[previous_row * k], k, d2);
        previous_row = row;
        continue;
      }
      float bound = std::numeric_limits<float>::max();
      if (previous_kth >= 0.0f) {
        const float dx = q[0] - previous[0], dy = q[1] - previous[1],
                    dz = q[2] - previous[2];
        const float reach =
            std::sqrt (previous_kth) + std::sqrt (dx * dx + dy * dy + dz * dz);
        // Widened by a relative margin so float rounding never drops a true neighbour.
        bound = reach * reach * (1.0f + 1e-4f) + 1e-30f;
      }
      tree.nearestKSearch (q, k, &indices_flat_[row * k], d2, bound);
      std::copy_n (q, 3, previous);
      previous_kth = d2[k - 1];
      previous_row = row;
    }
  }
}

template <typename PointT>
std::vector<std::size_t>
pcl_ext::Neighbourhoods<PointT>::rowsInTreeOrder (const search::KdTree3f& tree) const
{
  // Each point's place in the tree, then the rows of finite points by it (a counting
  // sort: rows of one point keep their order).
  const std::size_t rows = indices_->size();
  std::vector<std::uint32_t> place (input_->size(), 0);
  for (std::size_t pos = 0; pos < tree.size(); ++pos)
    place[static_cast<std::size_t> (tree.pointIndex (pos))] =
        static_cast<std::uint32_t> (pos);
  std::vector<std::size_t> start (tree.size() + 1, 0);
  std::vector<char> finite (rows, 0);
  for (std::size_t row = 0; row < rows; ++row) {
    const pcl::index_t i = (*indices_)[row];
    finite[row] = pcl::isFinite ((*input_)[i]);
    if (finite[row])
      ++start[place[static_cast<std::size_t> (i)] + 1];
  }
  for (std::size_t pos = 0; pos < tree.size(); ++pos)
    start[pos + 1] += start[pos];
  std::vector<std::size_t> order (start.back());
  for (std::size_t row = 0; row < rows; ++row)
    if (finite[row])
      order[start[place[static_cast<std::size_t> ((*indices_)[row])]]++] = row;
  return order;
}

template <typename PointT>
void
pcl_ext::Neighbourhoods<PointT>::searchWithSearchMethod()
{
  // Counts vary (radius) or the search is opaque: gather fixed blocks of rows in
  // parallel, then lay them out in row order. The result does not depend on the thread
  // count.
  const std::size_t rows = indices_->size();
  constexpr std::size_t block_size = 1024;
  const std::size_t num_blocks = (rows + block_size - 1) / block_size;
  std::vector<detail::NeighbourBlock> blocks (num_blocks);
  const unsigned int threads = resolveThreadCount (threads_);

#pragma omp parallel num_threads(threads) default(none) shared(blocks, rows, num_blocks)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t> (num_blocks); ++b) {
      auto& block = blocks[b];
      const std::size_t first = static_cast<std::size_t> (b) * block_size;
      const std::size_t last = std::min (rows, first + block_size);
      for (std::size_t r = first; r < last; ++r) {
        const PointT& p = (*input_)[(*indices_)[r]];
        std::size_t found = 0;
        if (pcl::isFinite (p)) {
          if (k_ > 0)
            search_->nearestKSearch (p, k_, nn, d2);
          else
            search_->radiusSearch (p, radius_, nn, d2, max_nn_);
          // Drop anything a third-party search returns for non-finite points.
          for (std::size_t i = 0; i < nn.size(); ++i)
            if (nn[i] >= 0 && static_cast<std::size_t> (nn[i]) < input_->size() &&
                std::isfinite (d2[i])) {
              block.indices.push_back (nn[i]);
              if (store_sqr_distances_)
                block.sqr_distances.push_back (d2[i]);
              ++found;
            }
        }
        block.rows.push_back (r);
        block.counts.push_back (found);
      }
    }
  }

  offsets_.assign (rows + 1, 0);
  for (const auto& block : blocks)
    for (std::size_t i = 0; i < block.rows.size(); ++i)
      offsets_[block.rows[i] + 1] = block.counts[i];
  std::partial_sum (offsets_.begin(), offsets_.end(), offsets_.begin());
  rows_ = rows;
  indices_flat_.resize (offsets_[rows]);
  if (store_sqr_distances_)
    sqr_distances_.resize (offsets_[rows]);
#pragma omp parallel for num_threads(threads) schedule(static) default(none)           \
    shared(blocks, num_blocks)
  for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t> (num_blocks); ++b) {
    const auto& block = blocks[b];
    if (block.rows.empty())
      continue;
    const std::size_t start = offsets_[block.rows.front()];
    std::copy (
        block.indices.begin(), block.indices.end(), indices_flat_.begin() + start);
    if (!block.sqr_distances.empty())
      std::copy (block.sqr_distances.begin(),
                 block.sqr_distances.end(),
                 sqr_distances_.begin() + start);
  }
}

template <typename PointT>
std::ptrdiff_t
pcl_ext::Neighbourhoods<PointT>::getRowOfPoint (pcl::index_t point_index) const
{
  if (rows_ == 0 || point_index < 0)
    return -1;
  if (computed_fake_indices_)
    return static_cast<std::size_t> (point_index) < size() ? point_index : -1;
  if (static_cast<std::size_t> (point_index) >= row_of_point_.size())
    return -1;
  return row_of_point_[point_index];
}

template <typename PointT>
bool
pcl_ext::Neighbourhoods<PointT>::isComputedFor (
    const PointCloudConstPtr& cloud, const pcl::IndicesConstPtr& indices) const
{
  if (rows_ == 0 || cloud != computed_cloud_)
    return false;
  if (computed_fake_indices_) {
    // Computed for every point: accept no indices, or indices that name every point in
    // order.
    if (!indices)
      return true;
    if (indices->size() != cloud->size())
      return false;
    for (std::size_t i = 0; i < indices->size(); ++i)
      if ((*indices)[i] != static_cast<pcl::index_t> (i))
        return false;
    return true;
  }
  return indices && (indices == computed_indices_ || *indices == *computed_indices_);
}

#define PCL_EXT_INSTANTIATE_Neighbourhoods(T) template class pcl_ext::Neighbourhoods<T>;
