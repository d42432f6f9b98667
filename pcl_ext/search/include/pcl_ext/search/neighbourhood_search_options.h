/*
 * pcl_ext: k or a radius, a maximum radius for k and the search method of a
 * neighbourhood search.
 */
#pragma once

#include <pcl/search/search.h>

namespace pcl_ext {
/** \brief What a neighbourhood search looks for: k nearest neighbours or the neighbours
 * within a radius, a maximum radius for k, and the search method; one set/get pair
 * each.
 *
 * A base of pcl_ext::Neighbourhoods (the search itself; k unset by default) and of
 * pcl_ext::NeighbourhoodOptions (the classifiers and segmenters that search or take
 * shared neighbourhoods; k = 50 by default), so that both are set the same way.
 */
template <typename PointT>
class NeighbourhoodSearchOptions {
public:
  using SearchPtr = typename pcl::search::Search<PointT>::Ptr;

  /** \brief Number of nearest neighbours k per point (PCL's k), the point included.
   * Clears the radius. Default and valid range: the deriving class's
   * (pcl_ext::Neighbourhoods: 0, unset, and 1 .. number of finite points; the
   * classifiers and segmenters: 50, Belton & Lichti's k, and 3 .. number of finite
   * points). */
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

  /** \brief Neighbourhood radius instead of k, in the cloud's units. Default 0 (unset:
   * k is used); valid: > 0. Clears k. */
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

  /** \brief With k: keep only the neighbours within this distance, in the cloud's
   * units, so each row holds the k nearest within it (the same rows as a radius search
   * limited to k, found at the cost of the k search). Default 0: no cap, the k nearest.
   * Valid: finite, >= 0; ignored with a radius (and by a class given shared
   * neighbourhoods: give those pcl_ext::Neighbourhoods::setMaxRadius instead). A TLS
   * scan's spacing varies with range and incidence, so k neighbours of a far or grazing
   * surface can reach a second surface; the cap bounds that reach. */
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

  /** \brief Search method. Default null: a pcl_ext::search::NanoflannKdTree is built.
   */
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
  /** \brief \a k: the default number of neighbours (0: unset). */
  explicit NeighbourhoodSearchOptions (int k = 0) : k_ (k) {}

  int k_;
  double radius_ = 0.0;
  double max_radius_ = 0.0;
  SearchPtr search_;
};
} // namespace pcl_ext
