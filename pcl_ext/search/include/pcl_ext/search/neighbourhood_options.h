/*
 * pcl_ext: the neighbourhood options of a class that searches its input's
 * neighbourhoods once or takes shared ones.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_search_options.h>
#include <pcl_ext/search/neighbourhood_source.h>

#include <pcl/console/print.h>

#include <cmath>
#include <string>

namespace pcl_ext {
/** \brief Shared neighbourhoods and the thread count of a class that searches its
 * input's neighbourhoods: setNeighbourhoods takes pcl_ext::Neighbourhoods computed once
 * and used by several classes (taken when computed for the same cloud and indices). A
 * mixin of NeighbourhoodOptions and of the features' base,
 * pcl_ext::NeighbourhoodFeature, whose k and radius are pcl::Feature's own.
 */
template <typename PointT>
class SharedNeighbourhoodsOption {
public:
  using NeighbourhoodsConstPtr = typename Neighbourhoods<PointT>::ConstPtr;

  /** \brief Shared neighbourhoods, computed for the same cloud and indices (then k,
   * radius and maximum radius are theirs). Default: none, the class searches itself. */
  void
  setNeighbourhoods (const NeighbourhoodsConstPtr& neighbourhoods)
  {
    source_.setShared (neighbourhoods);
  }

  NeighbourhoodsConstPtr
  getNeighbourhoods () const
  {
    return source_.getShared();
  }

  /** \brief OpenMP threads, for the search and the computation. Default 0: all cores.
   * Results do not depend on it. */
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

protected:
  unsigned int threads_ = 0;
  NeighbourhoodSource<PointT> source_;
};

/** \brief The neighbourhood options shared by pcl_ext's classifiers and segmenters: k
 * or a radius, a maximum radius for k, the search method, shared neighbourhoods and the
 * thread count, one set/get pair each (the first four those of
 * pcl_ext::NeighbourhoodSearchOptions, as for pcl_ext::Neighbourhoods), and the search
 * they configure.
 *
 * A mixin, derived from next to pcl::PCLBase (as pcl::FeatureFromNormals adds normals
 * to pcl::Feature): pcl_ext::LocalVarianceClassification,
 * pcl_ext::VarianceRegionGrowing and pcl_ext::LocalSurfaceIntersection. The
 * neighbourhoods are searched once per call of the class's verb
 * (pcl_ext::Neighbourhoods), or taken from setNeighbourhoods when those were computed
 * for the same cloud and indices.
 */
template <typename PointT>
class NeighbourhoodOptions : public SharedNeighbourhoodsOption<PointT>,
                             public NeighbourhoodSearchOptions<PointT> {
public:
  using SearchPtr = typename NeighbourhoodSearchOptions<PointT>::SearchPtr;

  /** \brief k = 50 neighbours (Belton & Lichti's k), no radius, no maximum radius,
   * the default search. */
  NeighbourhoodOptions() : NeighbourhoodSearchOptions<PointT> (50) {}

protected:
  using NeighbourhoodSearchOptions<PointT>::k_;
  using NeighbourhoodSearchOptions<PointT>::radius_;
  using NeighbourhoodSearchOptions<PointT>::max_radius_;
  using NeighbourhoodSearchOptions<PointT>::search_;

  /** \brief PCL_ERROR (prefixed by \a caller) and false when k is below \a min_k, k and
   * the radius are negative or not finite, or the maximum radius is negative or not
   * finite. */
  bool
  checkNeighbourhoodOptions (const char* caller, int min_k) const
  {
    if (!(max_radius_ >= 0.0) || !std::isfinite (max_radius_)) {
      PCL_ERROR ("%s maximum radius = %g; it must be finite and >= 0 (0: none).\n",
                 caller,
                 max_radius_);
      return false;
    }
    if (k_ != 0 && k_ < min_k) {
      PCL_ERROR ("%s k = %d; a tangent plane needs at least %d neighbours.\n",
                 caller,
                 k_,
                 min_k);
      return false;
    }
    if (k_ < 0 || !(radius_ >= 0.0) || !std::isfinite (radius_)) {
      PCL_ERROR ("%s k = %d, radius = %g; give k >= %d or a finite radius > 0.\n",
                 caller,
                 k_,
                 radius_,
                 min_k);
      return false;
    }
    return true;
  }

  /** \brief The neighbourhoods of \a cloud and \a indices (null: every point): the
   * shared ones when computed for them, else a search of our own with these options.
   * Null after a PCL_ERROR naming \a caller. */
  const Neighbourhoods<PointT>*
  prepareNeighbourhoods (
      const std::string& caller,
      const typename Neighbourhoods<PointT>::PointCloudConstPtr& cloud,
      const pcl::IndicesConstPtr& indices)
  {
    return this->source_.prepare (
        caller, cloud, indices, k_, radius_, search_, this->threads_, max_radius_);
  }

  /** \brief NeighbourhoodSource::prepareCovering with these options. */
  const Neighbourhoods<PointT>*
  prepareNeighbourhoodsCovering (
      const std::string& caller,
      const typename Neighbourhoods<PointT>::PointCloudConstPtr& cloud,
      const std::vector<pcl::index_t>& needed)
  {
    return this->source_.prepareCovering (
        caller, cloud, needed, k_, radius_, search_, this->threads_, max_radius_);
  }

  /** \brief Free a search of our own (the rows can be large). */
  void
  releaseNeighbourhoods ()
  {
    this->source_.release();
  }
};
} // namespace pcl_ext
