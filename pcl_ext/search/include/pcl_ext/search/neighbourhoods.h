/*
 * pcl_ext: the neighbourhoods of every point of a cloud, searched once and shared.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_search_options.h>

#include <pcl/pcl_base.h>
#include <pcl/search/search.h>

#include <cstddef>
#include <vector>

namespace pcl_ext {
namespace search {
class KdTree3f;
} // namespace search

/** \brief Where each row of a pcl_ext::Neighbourhoods lies in its array of neighbour
 * indices, for code that is not a template over the point type. */
struct NeighbourRowsView {
  const pcl::index_t* indices = nullptr;
  /** Row r spans [offsets[r], offsets[r + 1]); null: every row spans \a stride entries,
   * starting with -1 when the row is empty. */
  const std::size_t* offsets = nullptr;
  std::size_t stride = 0;
  std::size_t rows = 0;

  std::size_t
  begin (std::size_t row) const
  {
    return offsets ? offsets[row] : row * stride;
  }

  std::size_t
  size (std::size_t row) const
  {
    if (offsets)
      return offsets[row + 1] - offsets[row];
    return stride > 0 && indices[row * stride] >= 0 ? stride : 0;
  }
};

/** \brief The k nearest or radius neighbours of every point of a cloud (or of the
 * points named by setIndices), computed once, in parallel, and stored compactly.
 *
 * A pipeline of pcl_ext classes (features, classifiers, segmenters) accepts one
 * Neighbourhoods object through setNeighbourhoods(), so the cloud is searched once for
 * all of them.
 *
 * Storage is one array of point indices: row r holds the neighbours of point
 * getIndices()[r], closest first. With k neighbours (and no maximum radius) every row
 * spans k entries, a point without neighbourhood's holding -1s; otherwise rows are
 * compressed sparse rows with offsets. Rows include the query point itself at distance
 * 0, as PCL's searches do. Neighbours are searched among all finite points of the input
 * cloud, not only the indexed ones (PCL's Feature does the same when no search surface
 * is set).
 *
 * The squared distances are stored too unless setStoreSquaredDistances (false) says
 * otherwise; getSquaredDistance() then computes them from the coordinates, in the same
 * float arithmetic as the default search, so the values are the same. At k = 50 the
 * rows then take 200 bytes per point instead of 408 (the methods' own searches store no
 * distances).
 *
 * The default search is pcl_ext::search::NanoflannKdTree; any pcl::search::Search works
 * through setSearchMethod(). With the default and k >= 24 neighbours of the whole
 * cloud, the pass searches the tree leaf by leaf (KdTree3f::nearestKSearchOfPoints),
 * which shares one gathering of candidates among a leaf's points; otherwise it searches
 * point by point in the tree's spatial order, each query bounded by the previous one's
 * k-th distance. Either way every row is the same for any number of threads.
 *
 * Errors (PCL_ERROR, empty result, compute() returns false): no input, an empty cloud,
 * no finite point, neither or both of k and radius set, k < 1, k larger than the number
 * of finite points, a radius that is not positive and finite, indices out of range.
 * Points with NaN or Inf coordinates get an empty row and are never anyone's neighbour.
 *
 * \code
 * pcl_ext::Neighbourhoods<pcl::PointXYZ> nb;
 * nb.setInputCloud (cloud);
 * nb.setKSearch (50);
 * nb.compute ();
 * for (const auto j : nb[0]) { ... }  // the 50 neighbours of point 0
 * \endcode
 */
template <typename PointT>
class Neighbourhoods : public pcl::PCLBase<PointT>,
                       public NeighbourhoodSearchOptions<PointT> {
public:
  using Ptr = pcl::shared_ptr<Neighbourhoods<PointT>>;
  using ConstPtr = pcl::shared_ptr<const Neighbourhoods<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using PointCloudConstPtr = typename PointCloud::ConstPtr;
  using SearchPtr = typename NeighbourhoodSearchOptions<PointT>::SearchPtr;

  /** \brief A read-only view of one row: the neighbours of one point, closest first
   * (\a sqr_distances is null when the distances are not stored). */
  struct Row {
    const pcl::index_t* indices;
    const float* sqr_distances;
    std::size_t count;

    std::size_t
    size () const
    {
      return count;
    }
    bool
    empty () const
    {
      return count == 0;
    }
    const pcl::index_t*
    begin () const
    {
      return indices;
    }
    const pcl::index_t*
    end () const
    {
      return indices + count;
    }
    pcl::index_t
    operator[] (std::size_t i) const
    {
      return indices[i];
    }
  };

  Neighbourhoods() = default;

  /** \brief With a radius, keep at most this many closest neighbours (0, the default:
   * all). */
  void
  setMaxNeighbours (unsigned int max_nn)
  {
    max_nn_ = max_nn;
  }

  unsigned int
  getMaxNeighbours () const
  {
    return max_nn_;
  }

  /** \brief Keep the squared distance of every neighbour (default: true). Without
   * them the rows take half the memory at k neighbours; getSquaredDistance() computes
   * them from the coordinates, and Row::sqr_distances and getSquaredDistances() are
   * empty. */
  void
  setStoreSquaredDistances (bool store)
  {
    store_sqr_distances_ = store;
  }

  bool
  getStoreSquaredDistances () const
  {
    return store_sqr_distances_;
  }

  /** \brief Threads for the search (0, the default: all cores). Results do not depend
   * on it. */
  void
  setNumberOfThreads (unsigned int nr_threads = 0)
  {
    threads_ = nr_threads;
  }

  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

  /** \brief Search the neighbourhoods of every indexed point.
   * \return false (with PCL_ERROR and an empty result) on bad input or parameters */
  bool
  compute ();

  /** \brief Number of rows: the number of indexed points after compute(), 0 before. */
  std::size_t
  size () const
  {
    return rows_;
  }

  bool
  empty () const
  {
    return size() == 0;
  }

  /** \brief The neighbours of the point in row \a row (getIndices()[row]). */
  Row
  operator[] (std::size_t row) const
  {
    const NeighbourRowsView view = getRows();
    const std::size_t begin = view.begin (row);
    return Row{indices_flat_.data() + begin,
               sqr_distances_.empty() ? nullptr : sqr_distances_.data() + begin,
               view.size (row)};
  }

  /** \brief The rows as a view that does not depend on the point type. */
  NeighbourRowsView
  getRows () const
  {
    return NeighbourRowsView{indices_flat_.data(),
                             stride_ > 0 || offsets_.empty() ? nullptr
                                                             : offsets_.data(),
                             stride_,
                             rows_};
  }

  /** \brief The squared distance between the point of row \a row and its \a i-th
   * neighbour: the stored value, or one computed from the coordinates as the default
   * search computes it. */
  float
  getSquaredDistance (std::size_t row, std::size_t i) const;

  /** \brief Row of point \a point_index, or -1 when the point was not a query. */
  std::ptrdiff_t
  getRowOfPoint (pcl::index_t point_index) const;

  /** \brief True when the rows were computed for exactly this cloud and these indices
   * (a null \a indices means every point); features use it to accept shared
   * neighbourhoods. */
  bool
  isComputedFor (const PointCloudConstPtr& cloud,
                 const pcl::IndicesConstPtr& indices) const;

  /** \brief Every row's neighbours, one row after another (getRows() says where each
   * starts). */
  const pcl::Indices&
  getNeighbourIndices () const
  {
    return indices_flat_;
  }

  /** \brief The squared distances along getNeighbourIndices(); empty when they are not
   * stored. */
  const std::vector<float>&
  getSquaredDistances () const
  {
    return sqr_distances_;
  }

  /** \brief Number of finite points the search ran over. */
  std::size_t
  getNumberOfSearchablePoints () const
  {
    return searchable_;
  }

  using pcl::PCLBase<PointT>::getIndices;
  using pcl::PCLBase<PointT>::getInputCloud;

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;
  using NeighbourhoodSearchOptions<PointT>::k_;
  using NeighbourhoodSearchOptions<PointT>::radius_;
  using NeighbourhoodSearchOptions<PointT>::max_radius_;
  using NeighbourhoodSearchOptions<PointT>::search_;

  void
  clear ();

  bool
  validate ();

  /** \brief The smallest k for which the whole-cloud pass searches leaf by leaf. */
  static constexpr std::size_t kMinNeighboursPerLeafSearch = 24;

  void
  searchWithTree ();

  /** \brief The rows of finite points, in the order of their points in \a tree. */
  std::vector<std::size_t>
  rowsInTreeOrder (const search::KdTree3f& tree) const;

  void
  searchWithSearchMethod ();

  void
  searchRadiusBlocked ();

  /** \brief Cut every row at the maximum radius (rows are sorted by distance). */
  void
  capRows ();

  unsigned int max_nn_ = 0;
  unsigned int threads_ = 0;
  bool store_sqr_distances_ = true;

  std::size_t searchable_ = 0;
  std::size_t rows_ = 0;
  std::size_t stride_ = 0; // > 0: every row spans stride_ entries, offsets_ is empty
  std::vector<std::size_t> offsets_;
  pcl::Indices indices_flat_;
  std::vector<float> sqr_distances_;
  std::vector<std::ptrdiff_t>
      row_of_point_; // only when indices are not the whole cloud
  PointCloudConstPtr computed_cloud_;
  pcl::IndicesConstPtr computed_indices_;
  bool computed_fake_indices_ = true;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/search/impl/neighbourhoods.hpp>
#endif
