/*
 * pcl_ext: where a feature or classifier gets its neighbourhoods: shared, or searched
 * itself.
 */
#pragma once

#include <pcl_ext/search/neighbourhoods.h>

#include <pcl/console/print.h>

#include <memory>
#include <string>

namespace pcl_ext {
/** \brief The neighbourhoods a class works on: the shared ones given through
 * setNeighbourhoods() when they were computed for the same cloud and indices, else its
 * own search with its k or radius.
 *
 * Used by every pcl_ext feature and classifier so that a pipeline searches the cloud
 * once: compute one pcl_ext::Neighbourhoods and hand it to each class.
 */
template <typename PointT>
class NeighbourhoodSource {
public:
  using NeighbourhoodsT = Neighbourhoods<PointT>;
  using NeighbourhoodsConstPtr = typename NeighbourhoodsT::ConstPtr;
  using SearchPtr = typename NeighbourhoodsT::SearchPtr;

  void
  setShared (const NeighbourhoodsConstPtr& neighbourhoods)
  {
    shared_ = neighbourhoods;
  }

  NeighbourhoodsConstPtr
  getShared () const
  {
    return shared_;
  }

  /** \brief The neighbourhoods to use for \a cloud and \a indices (null: every point).
   *
   * Shared neighbourhoods computed for this cloud and these indices win (k and radius
   * are then theirs). Otherwise a search runs with exactly one of \a k, \a radius set
   * (the other 0). \param[in] caller "Class::method", for messages \param[in]
   * max_radius with \a k: keep only the neighbours within this distance (the k nearest
   * within it); 0: no such cap \return null after a PCL_ERROR when neither is possible
   */
  const NeighbourhoodsT*
  prepare (const std::string& caller,
           const typename NeighbourhoodsT::PointCloudConstPtr& cloud,
           const pcl::IndicesConstPtr& indices,
           int k,
           double radius,
           const SearchPtr& search,
           unsigned int threads,
           double max_radius = 0.0)
  {
    own_.reset();
    if (shared_) {
      if (shared_->isComputedFor (cloud, indices))
        return shared_.get();
      PCL_WARN ("[pcl_ext::%s] The shared neighbourhoods were not computed for this "
                "cloud and "
                "these indices; searching again.\n",
                caller.c_str());
    }
    if ((k != 0) == (radius != 0.0)) {
      PCL_ERROR (
          "[pcl_ext::%s] Set exactly one of k (setKSearch) and the radius "
          "(setRadiusSearch), or give shared neighbourhoods (setNeighbourhoods).\n",
          caller.c_str());
      return nullptr;
    }
    own_.reset (new NeighbourhoodsT);
    own_->setInputCloud (cloud);
    own_->setStoreSquaredDistances (false); // computed when read: half the memory
    if (indices)
      own_->setIndices (indices);
    if (k != 0) {
      own_->setKSearch (k);
      own_->setMaxRadius (max_radius);
    }
    else
      own_->setRadiusSearch (radius);
    if (search)
      own_->setSearchMethod (search);
    own_->setNumberOfThreads (threads);
    if (!own_->compute()) {
      PCL_ERROR ("[pcl_ext::%s] The neighbourhood search failed.\n", caller.c_str());
      own_.reset();
      return nullptr;
    }
    return own_.get();
  }

  /** \brief As prepare() for every point of \a cloud, except that shared
   * neighbourhoods of \a cloud computed for only some of its points are used when they
   * have a row for each of \a needed: a caller that reads the rows of those points
   * alone (and finds its neighbours among all points) needs no more. */
  const NeighbourhoodsT*
  prepareCovering (const std::string& caller,
                   const typename NeighbourhoodsT::PointCloudConstPtr& cloud,
                   const std::vector<pcl::index_t>& needed,
                   int k,
                   double radius,
                   const SearchPtr& search,
                   unsigned int threads,
                   double max_radius = 0.0)
  {
    if (shared_ && !shared_->empty() && shared_->getInputCloud() == cloud) {
      bool covered = true;
      for (std::size_t i = 0; i < needed.size() && covered; ++i)
        covered = shared_->getRowOfPoint (needed[i]) >= 0;
      if (covered) {
        own_.reset();
        return shared_.get();
      }
    }
    return prepare (
        caller, cloud, pcl::IndicesConstPtr(), k, radius, search, threads, max_radius);
  }

  /** \brief Free a search of our own (the rows can be large). */
  void
  release ()
  {
    own_.reset();
  }

private:
  NeighbourhoodsConstPtr shared_;
  std::unique_ptr<NeighbourhoodsT> own_;
};
} // namespace pcl_ext
