/*
 * pcl_ext: the options of pcl_ext_segment_variance and the set-up of its segmentation
 * on one cloud, shared with pcl_ext_tiles segment_variance (which runs it on every
 * tile).
 */
#pragma once

#include "variance_options.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <cmath>
#include <iostream>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Options of Belton & Lichti's segmentation (sections 2-4) as
 * pcl_ext_segment_variance takes them, with its defaults. */
struct SegmentVarianceOptions {
  int k = 50;
  int min_size = 50;
  double max_radius = 0.0;
  double max_distance = 0.0;
  double max_distance_factor = 3.0;
  double parallel_angle = 10.0; ///< degrees
  std::string intersections_path;
  bool reintegrate =
      false; ///< after valid(): on unless -no_reintegrate or -preset paper
  bool keep_out = false;
  bool leftovers = false; ///< after valid(): on with section 4 unless -no_leftovers
  bool no_leftovers = false;
  double leftover_angle = 25.0; ///< degrees
  bool merge = false;           ///< after valid(): on with section 4 unless -no_merge
  bool no_merge = false;
  bool assign = false; ///< after valid(): on with section 4 unless -no_assign
  bool no_assign = false;
  VarianceClassificationOptions classification;

  void
  addTo (CommandLine& cl)
  {
    cl.addOption ("k", k, "neighbours per point (the paper's k)");
    cl.addOption (
        "max_radius",
        max_radius,
        "keep only the k neighbours within this distance (0: no cap, the paper's)");
    classification.addTo (cl);
    cl.addOption ("max_distance",
                  max_distance,
                  "longest link from a seed to a neighbour (0: no limit beyond the k "
                  "neighbours)");
    cl.addOption (
        "max_distance_factor",
        max_distance_factor,
        "longest link from a seed as a multiple of its local point spacing (0: none)");
    cl.addOption ("min_size", min_size, "smallest segment kept");
    cl.addOption (
        "intersections",
        intersections_path,
        "also write the local intersection points of the segments (section 4) to this "
        "file (.pcd, .ply or .las; input's frame): x y z, segment_a, segment_b and the "
        "two surface points index_a, index_b");
    cl.addSwitch ("reintegrate",
                  reintegrate,
                  "with -preset paper: still put the edge and boundary points into the "
                  "segment whose local plane they fit (section 4, which runs by "
                  "default)");
    cl.addSwitch ("no_reintegrate",
                  keep_out,
                  "leave the edge and boundary points out of the segments (section 3 "
                  "alone, as -preset paper)");
    cl.addSwitch ("leftovers",
                  leftovers,
                  "grow new segments among the points still without one (beyond the "
                  "paper; on by default with section 4)");
    cl.addSwitch ("no_leftovers", no_leftovers, "leave those points unsegmented");
    cl.addOption (
        "leftover_angle",
        leftover_angle,
        "the largest angle (degrees) between the normals of two linked "
        "points without a segment, each fitted to its 12 nearest points (CGAL's "
        "default for its region growing)");
    cl.addSwitch ("merge",
                  merge,
                  "merge the segments that are interleaved pieces of one plane (beyond "
                  "the paper; on by default with section 4)");
    cl.addSwitch ("no_merge", no_merge, "keep those pieces apart");
    cl.addSwitch (
        "assign",
        assign,
        "last, put each point still without a segment into the neighbouring "
        "segment whose local plane it lies on, within 3 RMS residuals (beyond "
        "the paper; on by default with section 4)");
    cl.addSwitch ("no_assign", no_assign, "leave those points unsegmented");
    cl.addOption (
        "parallel_angle",
        parallel_angle,
        "with -intersections or -reintegrate: segments whose normals differ by less "
        "(degrees) are parallel, not intersected (eq. 9)");
  }

  /** \brief Check the options (the error printed) and settle -reintegrate. */
  bool
  valid (const CommandLine& cl)
  {
    if (!classification.valid (cl))
      return false;
    if (k < 3) {
      std::cerr << "Error: -k must be at least 3.\n";
      return false;
    }
    if (min_size < 1) {
      std::cerr << "Error: -min_size must be at least 1.\n";
      return false;
    }
    if (!(max_radius >= 0.0) || !std::isfinite (max_radius)) {
      std::cerr << "Error: -max_radius must be finite and >= 0.\n";
      return false;
    }
    if (!(max_distance >= 0.0)) {
      std::cerr << "Error: -max_distance must be >= 0.\n";
      return false;
    }
    if (!(max_distance_factor >= 0.0) || !std::isfinite (max_distance_factor)) {
      std::cerr << "Error: -max_distance_factor must be finite and >= 0.\n";
      return false;
    }
    if (!(parallel_angle >= 0.0 && parallel_angle <= 90.0)) {
      std::cerr << "Error: -parallel_angle must lie between 0 and 90 degrees.\n";
      return false;
    }
    if (reintegrate && keep_out) {
      std::cerr << "Error: give -reintegrate or -no_reintegrate, not both.\n";
      return false;
    }
    // Section 4's re-integration unless the paper's settings are asked for: it keeps in
    // the segments the crease and border bands the classification leaves out
    // (docs/belton_lichti.md has the figures).
    reintegrate = reintegrate || (!keep_out && classification.preset != "paper");
    if (leftovers && no_leftovers) {
      std::cerr << "Error: give -leftovers or -no_leftovers, not both.\n";
      return false;
    }
    if (!(leftover_angle > 0.0 && leftover_angle <= 90.0)) {
      std::cerr << "Error: -leftover_angle must lie in (0, 90] degrees.\n";
      return false;
    }
    // New segments among what sections 3 and 4 leave out, with section 4 by default:
    // pipes, door jambs and narrow faces have no surface point to grow from
    // (docs/belton_lichti.md).
    leftovers = leftovers || (reintegrate && !no_leftovers);
    if ((merge && no_merge) || (assign && no_assign)) {
      std::cerr
          << "Error: give -merge or -no_merge, -assign or -no_assign, not both.\n";
      return false;
    }
    // The interleaved pieces of sparse planes merged and the points left over put
    // where they fit, with section 4 by default (docs/belton_lichti.md).
    merge = merge || (reintegrate && !no_merge);
    assign = assign || (reintegrate && !no_assign);
    return true;
  }

  /** \brief Whether section 4 runs (intersection points or re-integration). */
  bool
  intersects () const
  {
    return !intersections_path.empty() || reintegrate;
  }

  /** \brief Neighbourhoods of \a cloud as the segmentation searches them (k nearest,
   * capped at max_radius), not yet computed. */
  Neighbourhoods<pcl::PointXYZ>::Ptr
  makeNeighbourhoods (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                      unsigned int threads) const
  {
    auto nb = pcl::make_shared<Neighbourhoods<pcl::PointXYZ>>();
    nb->setInputCloud (cloud);
    nb->setKSearch (k);
    nb->setMaxRadius (max_radius);
    nb->setNumberOfThreads (threads);
    nb->setStoreSquaredDistances (false);
    return nb;
  }

  /** \brief Set up the classification (section 2) and the region growing (section 3) of
   * \a cloud on its computed neighbourhoods \a nb; pcl_ext::segmentByLocalVariance
   * then segments it. */
  void
  configure (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const Neighbourhoods<pcl::PointXYZ>::Ptr& nb,
             unsigned int threads,
             LocalVarianceClassification<pcl::PointXYZ>& classifier,
             VarianceRegionGrowing<pcl::PointXYZ>& rg) const
  {
    classification.applyTo (classifier);
    classifier.setNumberOfThreads (threads);
    rg.setInputCloud (cloud);
    rg.setNeighbourhoods (nb);
    rg.setMaxDistance (max_distance);
    rg.setMaxDistanceFactor (max_distance_factor);
    rg.setMinClusterSize (static_cast<pcl::uindex_t> (min_size));
    rg.setNumberOfThreads (threads);
  }

  /** \brief Set up section 4 (the local intersections and the re-integration) of
   * \a cloud on its computed neighbourhoods \a nb; segment labels and classes are the
   * caller's. */
  void
  configure (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const Neighbourhoods<pcl::PointXYZ>::Ptr& nb,
             unsigned int threads,
             LocalSurfaceIntersection<pcl::PointXYZ>& lsi) const
  {
    lsi.setInputCloud (cloud);
    lsi.setNeighbourhoods (nb);
    lsi.setParallelAngleThreshold (parallel_angle * M_PI / 180.0);
    lsi.setNumberOfThreads (threads);
  }

  /** \brief Set up the growing of new segments among the points left out of \a cloud
   * on its computed neighbourhoods \a nb; the segment labels are the caller's. */
  void
  configure (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const Neighbourhoods<pcl::PointXYZ>::Ptr& nb,
             unsigned int threads,
             LeftoverRegionGrowing<pcl::PointXYZ>& growing) const
  {
    growing.setInputCloud (cloud);
    growing.setNeighbourhoods (nb);
    growing.setAngleThreshold (leftover_angle * M_PI / 180.0);
    growing.setMinClusterSize (static_cast<pcl::uindex_t> (min_size));
    growing.setNumberOfThreads (threads);
  }

  /** \brief Set up the merging of interleaved coplanar segments of \a cloud on its
   * computed neighbourhoods \a nb; the segment labels are the caller's. */
  void
  configure (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const Neighbourhoods<pcl::PointXYZ>::Ptr& nb,
             unsigned int threads,
             CoplanarSegmentMerging<pcl::PointXYZ>& merging) const
  {
    merging.setInputCloud (cloud);
    merging.setNeighbourhoods (nb);
    merging.setNumberOfThreads (threads);
  }

  /** \brief Set up the assignment of the points left over of \a cloud on its computed
   * neighbourhoods \a nb; the segment labels are the caller's. */
  void
  configure (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const Neighbourhoods<pcl::PointXYZ>::Ptr& nb,
             unsigned int threads,
             LeftoverPlaneAssignment<pcl::PointXYZ>& assignment) const
  {
    assignment.setInputCloud (cloud);
    assignment.setNeighbourhoods (nb);
    assignment.setNumberOfThreads (threads);
  }
};
} // namespace apps
} // namespace pcl_ext
