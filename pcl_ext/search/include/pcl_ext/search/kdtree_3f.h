/*
 * pcl_ext: a compact 3D k-d tree over float coordinates (nanoflann inside).
 */
#pragma once

#include <pcl/types.h>

#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace search {
/** \brief A k-d tree over 3D float points, independent of the point type.
 *
 * Holds its own copy of the coordinates, stored in the tree's leaf order so that the
 * points of one leaf are contiguous in memory (a query touches few cache lines). Built
 * on nanoflann; nanoflann stays an implementation detail. NanoflannKdTree<PointT> wraps
 * it as a pcl::search::Search; Neighbourhoods, when its search is a NanoflannKdTree
 * (the default), queries the tree underneath (NanoflannKdTree::getTree()) directly.
 *
 * Tree positions (0 .. size()-1) enumerate the points in spatial order, leaf after leaf
 * (leafRanges()); point() gives the coordinates at a position and pointIndex() the
 * index the point was given with to build(). Searches return those point indices.
 */
class KdTree3f {
public:
  KdTree3f();
  ~KdTree3f();
  KdTree3f (const KdTree3f&) = delete;
  KdTree3f&
  operator= (const KdTree3f&) = delete;

  /** \brief Build over \a xyz (3 floats per point, all finite) with the given point
   * indices. \param[in] leaf_size the maximum number of points in a leaf (nanoflann's
   * leaf_max_size) \param[in] threads threads for the build (the tree is the same for
   * any number) */
  void
  build (std::vector<float> xyz,
         std::vector<pcl::index_t> point_indices,
         unsigned int leaf_size = 24,
         unsigned int threads = 1);

  /** \brief Number of points in the tree. */
  std::size_t
  size () const;

  /** \brief Up to \a k nearest neighbours of \a query, closest first.
   * \param[out] indices point indices (as given to build)
   * \param[out] sqr_distances squared distances
   * \param[in] sqr_bound a squared distance within which at least k points are known to
   * lie (it prunes the search from the start; the result does not depend on it) \return
   * the number found (min(k, size())) */
  std::size_t
  nearestKSearch (const float* query,
                  std::size_t k,
                  pcl::index_t* indices,
                  float* sqr_distances,
                  float sqr_bound = std::numeric_limits<float>::max()) const;

  /** \brief Position ranges [first, last) of the tree's leaves, in position order. Each
   * holds at most the leaf size of points lying close together. */
  std::vector<std::pair<std::size_t, std::size_t>>
  leafRanges () const;

  /** \brief The k nearest neighbours of each tree point at positions [first, last),
   * closest first, equal distances in tree-position order.
   *
   * Exact, and the same for a point whatever range it is searched in. Meant for a run
   * of nearby points such as a leaf: the exact k-th distance of one of them bounds
   * every other's (triangle inequality), so the candidates of all are gathered by one
   * radius search and each point only ranks those, instead of walking the tree again.
   * \param[out] indices (last - first) * k point indices (as given to build), k per
   * point in position order \param[out] sqr_distances squared distances, the same
   * layout \return the k used, min(k, size()) */
  std::size_t
  nearestKSearchOfPoints (std::size_t first,
                          std::size_t last,
                          std::size_t k,
                          pcl::index_t* indices,
                          float* sqr_distances) const;

  /** \brief All neighbours within \a radius of \a query.
   * \param[in] max_nn keep only the max_nn closest (0: all)
   * \param[in] sorted sort by distance (always done when max_nn limits the result)
   * \return the number found (0 for a radius that is not positive) */
  std::size_t
  radiusSearch (const float* query,
                double radius,
                pcl::Indices& indices,
                std::vector<float>& sqr_distances,
                std::size_t max_nn = 0,
                bool sorted = true) const;

  /** \brief Coordinates of the point at tree position \a pos. */
  const float*
  point (std::size_t pos) const;

  /** \brief Point index of the point at tree position \a pos. */
  pcl::index_t
  pointIndex (std::size_t pos) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace search
} // namespace pcl_ext
