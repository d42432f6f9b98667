/*
 * pcl_ext apps: the option that narrows Belton & Lichti's edges to their creases
 * (pcl_ext::EdgeLocalisation), shared by pcl_ext_classify_variance and pcl_ext_tiles.
 */
#pragma once

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/classification/edge_localisation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <iostream>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief -wide_edges: keep every edge of eq. 5 (a band about a neighbourhood wide
 * along each crease) rather than only those within a point spacing of it. On by
 * default, off with -preset paper. */
struct EdgeLocalisationOption {
  bool wide_edges = false;

  void
  addTo (CommandLine& cl)
  {
    cl.addSwitch ("wide_edges",
                  wide_edges,
                  "keep every edge point of eq. 5, a band about a neighbourhood wide "
                  "(default: only those within a point spacing of the crease their "
                  "neighbourhood spans; -preset paper keeps them all too)");
  }

  /** \brief Whether the edges are narrowed, given the classification's preset. A
   * range camera's cloud too: the narrowing's faces may fit within the local noise. */
  bool
  localises (const std::string& preset) const
  {
    return !wide_edges && preset != "paper";
  }

  /** \brief Narrow the edges of \a classes (one per point of \a cloud, classified on
   * \a nb) in place; prints the error and returns false on failure. */
  template <typename PointT>
  static bool
  localise (const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
            const typename Neighbourhoods<PointT>::ConstPtr& nb,
            unsigned int threads,
            pcl::PointCloud<pcl::Label>& classes)
  {
    EdgeLocalisation<PointT> localisation;
    localisation.setInputCloud (cloud);
    localisation.setNeighbourhoods (nb);
    localisation.setNumberOfThreads (threads);
    localisation.setPointClasses (
        pcl::make_shared<pcl::PointCloud<pcl::Label>> (classes));
    pcl::PointCloud<pcl::Label> narrowed;
    if (!localisation.localise (narrowed)) {
      std::cerr << "Error: narrowing the edges failed (see the message above).\n";
      return false;
    }
    classes.swap (narrowed);
    return true;
  }
};
} // namespace apps
} // namespace pcl_ext
