/*
 * pcl_ext: the neighbourhood options of a class that searches its input's
 * neighbourhoods once or takes shared ones.
 */
#pragma once

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
 * thread count, one set/get pair each, and the search they configure.
 *
 * A mixin, derived from next to pcl::PCLBase (as pcl::FeatureFromNormals adds normals
 * to pcl::Feature): pcl_ext::LocalVarianceClassification,
 * pcl_ext::VarianceRegionGrowing and pcl_ext::LocalSurfaceIntersection. The
 * neighbourhoods are searched once per call of the class's verb
 * (pcl_ext::Neighbourhoods), or taken from setNeighbourhoods when those were computed
 * for the same cloud and indices.
 */
template <typename PointT>
class NeighbourhoodOptions : public SharedNeighbourhoodsOption<PointT> {
public:
  using SearchPtr = typename Neighbourhoods<PointT>::SearchPtr;

  /** \brief Number of neighbours k, the point included. Default 50 (Belton & Lichti's
   * k); valid: 3 .. number of finite points. Clears the radius. */
  void
  setKSearch (int k)
  {
    k_ = k;
    radius_ = 0.0;
  }

  int
  getKSearch () const
  {
    return k_;
  }

  /** \brief Neighbourhood radius instead of k, in the cloud's units. Default 0 (k is
   * used); valid: > 0. Clears k. */
  void
  setRadiusSearch (double radius)
  {
    radius_ = radius;
    k_ = 0;
  }

  double
  getRadiusSearch () const
  {
    return radius_;
  }

  /** \brief With k: keep only the neighbours within this distance, in the cloud's units
   * (the k nearest within it). Default 0: no cap, the k nearest. Valid: finite, >= 0;
   * ignored with a radius or shared neighbourhoods (give those
   * pcl_ext::Neighbourhoods::setMaxRadius instead). A TLS scan's spacing varies with
   * range and incidence, so k neighbours of a far or grazing surface can reach a second
   * surface; the cap bounds that reach. */
  void
  setMaxRadius (double radius)
  {
    max_radius_ = radius;
  }

  double
  getMaxRadius () const
  {
    return max_radius_;
  }

  /** \brief Search for the neighbourhoods. Default null:
   * pcl_ext::search::NanoflannKdTree. */
  void
  setSearchMethod (const SearchPtr& search)
  {
    search_ = search;
  }

  SearchPtr
  getSearchMethod () const
  {
    return search_;
  }

protected:
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

  /** \brief Free a search of our own (the rows can be large). */
  void
  releaseNeighbourhoods ()
  {
    this->source_.release();
  }

  int k_ = 50;
  double radius_ = 0.0;
  double max_radius_ = 0.0;
  SearchPtr search_;
};
} // namespace pcl_ext
