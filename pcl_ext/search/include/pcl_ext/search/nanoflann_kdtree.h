/*
 * pcl_ext: a pcl::search::Search implementation over nanoflann.
 */
#pragma once

#include <pcl_ext/search/kdtree_3f.h>

#include <pcl/search/search.h>

#include <string>

namespace pcl_ext {
namespace search {
/** \brief pcl::search::Search over a nanoflann k-d tree: a drop-in replacement for
 * pcl::search::KdTree<PointT> that stock PCL classes accept through setSearchMethod().
 *
 * The tree holds a compact copy of the finite points, in leaf order (see KdTree3f);
 * points with NaN or Inf coordinates are left out, so they are never returned, whatever
 * the cloud's is_dense flag says. Queries with non-finite coordinates return no
 * neighbours.
 *
 * k nearest neighbour results are always sorted by distance; radius results are sorted
 * when the object was constructed with \a sorted = true (the default) or when max_nn
 * limits them.
 *
 * \code
 * pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
 * ne.setSearchMethod (pcl_ext::search::NanoflannKdTree<pcl::PointXYZ>::Ptr (
 *     new pcl_ext::search::NanoflannKdTree<pcl::PointXYZ>));
 * \endcode
 */
template <typename PointT>
class NanoflannKdTree : public pcl::search::Search<PointT> {
public:
  using Ptr = pcl::shared_ptr<NanoflannKdTree<PointT>>;
  using ConstPtr = pcl::shared_ptr<const NanoflannKdTree<PointT>>;
  using PointCloud = typename pcl::search::Search<PointT>::PointCloud;
  using PointCloudConstPtr = typename pcl::search::Search<PointT>::PointCloudConstPtr;
  using IndicesConstPtr = pcl::IndicesConstPtr;
  using pcl::search::Search<PointT>::nearestKSearch;
  using pcl::search::Search<PointT>::radiusSearch;

  /** \param[in] sorted sort radius search results by distance (kNN results always are)
   * \param[in] leaf_size maximum points per leaf, default 24 (fastest for k around 50
   * in the whole-cloud neighbourhood pass; PCL's FLANN tree uses 15) */
  explicit NanoflannKdTree (bool sorted = true, unsigned int leaf_size = 24);

  /** \brief Build the tree over the finite points of \a cloud (restricted to \a
   * indices). */
  void
  setInputCloud (const PointCloudConstPtr& cloud,
                 const IndicesConstPtr& indices = IndicesConstPtr()) override;

  int
  nearestKSearch (const PointT& point,
                  int k,
                  pcl::Indices& k_indices,
                  std::vector<float>& k_sqr_distances) const override;

  int
  radiusSearch (const PointT& point,
                double radius,
                pcl::Indices& k_indices,
                std::vector<float>& k_sqr_distances,
                unsigned int max_nn = 0) const override;

  /** \brief The underlying tree, for allocation-free queries. */
  const KdTree3f&
  getTree () const
  {
    return tree_;
  }

  /** \brief Threads for building the tree in setInputCloud (default 1; 0: all cores).
   * The tree and every search result are the same for any number. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }

  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

  /** \brief Maximum points per leaf. */
  unsigned int
  getLeafSize () const
  {
    return leaf_size_;
  }

protected:
  using pcl::search::Search<PointT>::input_;
  using pcl::search::Search<PointT>::indices_;
  using pcl::search::Search<PointT>::sorted_results_;

  KdTree3f tree_;
  unsigned int leaf_size_;
  unsigned int threads_ = 1;
};
} // namespace search
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/search/impl/nanoflann_kdtree.hpp>
#endif
