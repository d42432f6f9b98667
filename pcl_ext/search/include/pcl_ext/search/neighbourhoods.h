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
/** \brief The k nearest or radius neighbours of every point of a cloud (or of the
 * points named by setIndices), computed once, in parallel, and stored compactly.
 *
 * A pipeline of pcl_ext classes (features, classifiers, segmenters) accepts one
 * Neighbourhoods object through setNeighbourhoods(), so the cloud is searched once for
 * all of them.
 *
 * Storage is compressed sparse rows: row r holds the neighbours of point
 * getIndices()[r], closest first, as offsets into one array of point indices and one of
 * squared distances. Rows include the query point itself at distance 0, as PCL's
 * searches do. Neighbours are searched among all finite points of the input cloud, not
 * only the indexed ones (PCL's Feature does the same when no search surface is set).
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

  /** \brief A read-only view of one row: the neighbours of one point, closest first. */
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
    return offsets_.empty() ? 0 : offsets_.size() - 1;
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
    return Row{indices_flat_.data() + offsets_[row],
               sqr_distances_.data() + offsets_[row],
               offsets_[row + 1] - offsets_[row]};
  }

  /** \brief Row of point \a point_index, or -1 when the point was not a query. */
  std::ptrdiff_t
  getRowOfPoint (pcl::index_t point_index) const;

  /** \brief True when the rows were computed for exactly this cloud and these indices
   * (a null \a indices means every point); features use it to accept shared
   * neighbourhoods. */
  bool
  isComputedFor (const PointCloudConstPtr& cloud,
                 const pcl::IndicesConstPtr& indices) const;

  /** \brief CSR arrays: row r spans [offsets[r], offsets[r+1]) of the other two. */
  const std::vector<std::size_t>&
  getOffsets () const
  {
    return offsets_;
  }

  const pcl::Indices&
  getNeighbourIndices () const
  {
    return indices_flat_;
  }

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

  void
  searchWithSearchMethod ();

  void
  searchRadiusBlocked ();

  /** \brief Cut every row at the maximum radius (rows are sorted by distance). */
  void
  capRows ();

  unsigned int max_nn_ = 0;
  unsigned int threads_ = 0;

  std::size_t searchable_ = 0;
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
