/*
 * pcl_ext: KdTree3f's searches around one query point, k nearest and within a radius.
 */
#include "kdtree_3f_impl.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pcl_ext {
namespace search {
namespace {
/** nanoflann's sorted k-nearest result set, with an optional starting bound on the
 * distance, ordering points by (squared distance, point index).
 *
 * nanoflann cannot prune until k candidates are found, so every query first walks whole
 * sibling subtrees. A caller that knows at least k points lie within some distance (for
 * instance from the previous, nearby query) passes it as \a bound, and pruning starts
 * at once. The result is the same: points beyond the bound cannot be among the k
 * nearest.
 *
 * Points at equal distance are ranked by their index in the cloud, whatever the order
 * the tree visits them in: the k nearest are then the same for any tree over the same
 * points (a tile of a cloud whose points keep their order, e.g.).
 */
class BoundedKnnResultSet {
public:
  BoundedKnnResultSet (std::uint32_t* positions,
                       float* dists,
                       std::size_t capacity,
                       float bound,
                       const pcl::index_t* point_indices)
  : positions_ (positions)
  , dists_ (dists)
  , capacity_ (capacity)
  , bound_ (bound)
  , point_indices_ (point_indices)
  {}

  std::size_t
  size () const
  {
    return count_;
  }
  bool
  full () const
  {
    return count_ == capacity_;
  }

  /** The distance below which a point is offered: just above the k-th, so that a point
   * tied with it is offered too (nanoflann offers only points strictly closer). */
  float
  worstDist () const
  {
    if (count_ < capacity_)
      return bound_;
    return std::min (
        bound_,
        std::nextafter (dists_[capacity_ - 1], std::numeric_limits<float>::infinity()));
  }

  bool
  addPoint (float dist, std::uint32_t pos)
  {
    if (count_ == capacity_ && !before (dist, pos, capacity_ - 1))
      return true;
    std::size_t i = count_;
    for (; i > 0 && before (dist, pos, i - 1); --i)
      if (i < capacity_) {
        dists_[i] = dists_[i - 1];
        positions_[i] = positions_[i - 1];
      }
    if (i < capacity_) {
      dists_[i] = dist;
      positions_[i] = pos;
    }
    if (count_ < capacity_)
      ++count_;
    return true;
  }

private:
  /** Whether (dist, pos) ranks before entry \a i. */
  bool
  before (float dist, std::uint32_t pos, std::size_t i) const
  {
    return dist < dists_[i] ||
           (dist == dists_[i] && point_indices_[pos] < point_indices_[positions_[i]]);
  }

  std::uint32_t* positions_;
  float* dists_;
  std::size_t capacity_;
  float bound_;
  const pcl::index_t* point_indices_;
  std::size_t count_ = 0;
};
} // namespace

std::size_t
KdTree3f::nearestKSearch (const float* query,
                          std::size_t k,
                          pcl::index_t* indices,
                          float* sqr_distances,
                          float bound) const
{
  if (!impl_->tree || k == 0)
    return 0;
  k = std::min (k, size());
  // nanoflann writes tree positions; map them to point indices in place.
  static_assert (sizeof (pcl::index_t) == sizeof (std::uint32_t), "index width");
  auto* positions = reinterpret_cast<std::uint32_t*> (indices);
  BoundedKnnResultSet result (
      positions, sqr_distances, k, bound, impl_->point_indices.data());
  impl_->tree->findNeighbors (result, query, nanoflann::SearchParams());
  std::size_t found = result.size();
  if (found < k && bound < std::numeric_limits<float>::max()) {
    // The caller's bound was wrong (fewer than k points inside it): search again
    // without it.
    BoundedKnnResultSet unbounded (positions,
                                   sqr_distances,
                                   k,
                                   std::numeric_limits<float>::max(),
                                   impl_->point_indices.data());
    impl_->tree->findNeighbors (unbounded, query, nanoflann::SearchParams());
    found = unbounded.size();
  }
  for (std::size_t i = 0; i < found; ++i)
    indices[i] = impl_->point_indices[positions[i]];
  return found;
}

std::size_t
KdTree3f::radiusSearch (const float* query,
                        double radius,
                        pcl::Indices& indices,
                        std::vector<float>& sqr_distances,
                        std::size_t max_nn,
                        bool sorted) const
{
  indices.clear();
  sqr_distances.clear();
  if (!impl_->tree || !(radius > 0.0))
    return 0;
  // Reused by the thread's next query: a query returns hundreds of points, and
  // allocating their buffer anew each time costs as much as a part of the search.
  thread_local std::vector<std::pair<std::uint32_t, float>> matches;
  matches.clear();
  nanoflann::SearchParams params;
  params.sorted = sorted || max_nn > 0;
  impl_->tree->radiusSearch (
      query, static_cast<float> (radius * radius), matches, params);
  if (max_nn > 0 && matches.size() > max_nn)
    matches.resize (max_nn);
  indices.resize (matches.size());
  sqr_distances.resize (matches.size());
  for (std::size_t i = 0; i < matches.size(); ++i) {
    indices[i] = impl_->point_indices[matches[i].first];
    sqr_distances[i] = matches[i].second;
  }
  return matches.size();
}
} // namespace search
} // namespace pcl_ext
