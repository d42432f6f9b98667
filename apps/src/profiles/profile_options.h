/*
 * pcl_ext: the options of pcl_ext_segment_profiles and the set-up of its segmentation,
 * shared with pcl_ext_tiles segment_profiles (which runs it on parts of a cloud).
 */
#pragma once

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/segmentation/cylinder_segment_join.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include <pcl/point_types.h>

#include <cmath>
#include <iostream>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Options of Sithole & Mapurisa's segmentation as pcl_ext_segment_profiles
 * takes them, with its defaults. */
struct ProfileOptions {
  using Segmentation = ProfileSegmentation<pcl::PointXYZ>;

  std::string method_name = "auto";
  std::string distribution = "hemisphere";
  unsigned int stacks = 4;
  unsigned int neighbours = 4;
  double width = 0.0, width_factor = 1.5, threshold = 0.0, threshold_factor = 3.0;
  double max_turn_deg = 30.0, window = 0.0, residual_factor = 3.0;
  double turn_significance = 0.0, max_threshold_factor = 4.0;
  bool aicc = false, local_threshold = false, side_frames = false,
       join_cylinders = false;
  /** Cylinder join lengths: negative follows the point spacing. */
  double cylinder_tolerance = -1.0, cylinder_min_radius = -1.0,
         cylinder_max_radius = -1.0, cylinder_max_gap = -1.0, cylinder_patch = -1.0;
  int min_size = 1;
  /** After valid(): the profile segmenter (when not automatic). */
  Segmentation::ProfileMethod method = Segmentation::ProfileMethod::Proximity;

  void
  addTo (CommandLine& cl)
  {
    cl.addOption ("stacks", stacks, "number of stacks (stack normals spread evenly)");
    cl.addOption ("distribution",
                  distribution,
                  "stack normals over the 'hemisphere' or a 'horizontal' half circle");
    cl.addOption (
        "width", width, "profile width (0: width_factor * average point spacing)");
    cl.addOption (
        "width_factor",
        width_factor,
        "profile width as a multiple of the spacing (curve fitting, noisy scans: 2.5)");
    cl.addOption (
        "method",
        method_name,
        "profile segmenter: proximity, mst, curve or crust (curve reconstruction, "
        "section 5.2); auto: chosen from the "
        "cloud's noise and density variation (see -v), with the join, side "
        "frames and local thresholds; the options given still apply");
    cl.addOption ("threshold",
                  threshold,
                  "proximity threshold (0: threshold_factor * average point spacing)");
    cl.addOption (
        "threshold_factor", threshold_factor, "threshold as a multiple of the spacing");
    cl.addSwitch (
        "local_threshold",
        local_threshold,
        "thresholds that follow the local density (the threshold times the local gap "
        "in the profile over the mean gap), for clouds whose density varies (TLS: far "
        "surfaces are sparser); not in the paper");
    cl.addOption ("max_threshold_factor",
                  max_threshold_factor,
                  "local thresholds: the longest, as a multiple of the threshold");
    cl.addOption ("k", neighbours, "proximity chaining: links per point");
    cl.addOption (
        "max_turn", max_turn_deg, "curve fitting: sharpest turn within a curve (deg)");
    cl.addOption (
        "window",
        window,
        "curve fitting: half length of the stretch fitted on each side of a point "
        "(0: 2 x threshold)");
    cl.addOption (
        "residual_factor",
        residual_factor,
        "curve fitting: a stretch whose residual exceeds this multiple of the median "
        "is not one curve");
    cl.addOption (
        "turn_significance",
        turn_significance,
        "curve fitting: a sharp turn must also exceed this many standard errors of the "
        "fits (0: the angle alone, as in the paper; noisy scans: 3)");
    cl.addSwitch (
        "aicc",
        aicc,
        "curve fitting: select the polynomial by the small-sample AICc, not the "
        "paper's AIC (noisy scans)");
    cl.addSwitch (
        "side_frames",
        side_frames,
        "curve fitting: fit each side of a point along its own axis (tight bends, "
        "such as thin trunks cut obliquely); not in the paper");
    cl.addSwitch (
        "join_cylinders",
        join_cylinders,
        "then join the segments that lie on one cylinder: the spans of a pipe cut at "
        "its supports, the legs of an elbow (pcl_ext::CylinderSegmentJoin); not in the "
        "paper");
    cl.addOption (
        "cylinder_tolerance",
        cylinder_tolerance,
        "joining cylinders: inlier band around a cylinder's surface (negative: 0.6 x "
        "the average point spacing of the segments)");
    cl.addOption (
        "cylinder_min_radius",
        cylinder_min_radius,
        "joining cylinders: smallest radius (negative, with -cylinder_max_radius: "
        "0.8 x the point spacing)");
    cl.addOption (
        "cylinder_max_radius",
        cylinder_max_radius,
        "joining cylinders: largest radius (negative, with -cylinder_min_radius: 24 "
        "x the point spacing)");
    cl.addOption ("cylinder_max_gap",
                  cylinder_max_gap,
                  "joining cylinders: longest gap bridged along an axis or to an elbow "
                  "(negative: 80 x the point spacing)");
    cl.addOption (
        "cylinder_patch",
        cylinder_patch,
        "joining cylinders: radius of the patch a cylinder hypothesis is drawn "
        "from, at least twice the largest radius (negative: 24 x the point spacing)");
    cl.addOption ("min_size", min_size, "smallest segment kept");
  }

  /** \brief Whether -method is auto. */
  bool
  automatic () const
  {
    return method_name == "auto";
  }

  /** \brief Check the options and resolve the method (message printed when they are
   * not valid). */
  bool
  valid ()
  {
    if (!automatic() && !parseMethod()) {
      std::cerr << "Error: -method must be auto, proximity, mst, curve or crust (got '"
                << method_name << "').\n";
      return false;
    }
    if (distribution != "hemisphere" && distribution != "horizontal") {
      std::cerr << "Error: -distribution must be hemisphere or horizontal.\n";
      return false;
    }
    if (min_size < 1) {
      std::cerr << "Error: -min_size must be at least 1.\n";
      return false;
    }
    if ((join_cylinders || automatic()) &&
        (cylinder_tolerance == 0.0 || !std::isfinite (cylinder_tolerance) ||
         !(radiiFromSpacing() ||
           (cylinder_min_radius > 0.0 && cylinder_max_radius >= cylinder_min_radius)) ||
         !std::isfinite (cylinder_max_radius) || !std::isfinite (cylinder_max_gap) ||
         cylinder_patch == 0.0 || !std::isfinite (cylinder_patch))) {
      std::cerr << "Error: joining cylinders needs -cylinder_tolerance and "
                   "-cylinder_patch not 0, -cylinder_min_radius and "
                   "-cylinder_max_radius both negative or 0 < min <= max, all "
                   "finite.\n";
      return false;
    }
    return true;
  }

  /** \brief The stack distribution of -distribution. */
  Segmentation::StackDistribution
  stackDistribution () const
  {
    return distribution == "hemisphere"
               ? Segmentation::StackDistribution::Hemisphere
               : Segmentation::StackDistribution::HorizontalHalfCircle;
  }

  /** \brief Set \a seg up as the options say (after valid()). */
  void
  apply (Segmentation& seg, unsigned int threads) const
  {
    seg.setNumberOfStacks (stacks);
    seg.setStackDistribution (stackDistribution());
    seg.setProfileWidth (width);
    seg.setDistanceThreshold (threshold);
    seg.setDistanceThresholdFactor (threshold_factor);
    seg.setMaxThresholdFactor (max_threshold_factor);
    seg.setProximityNeighbours (neighbours);
    seg.setMaxTurnAngle (max_turn_deg * M_PI / 180.0);
    seg.setCurveWindow (window);
    seg.setResidualFactor (residual_factor);
    seg.setMinClusterSize (static_cast<pcl::uindex_t> (min_size));
    seg.setNumberOfThreads (threads);
    seg.setProfileWidthFactor (width_factor);
    seg.setProfileSegmentation (method);
    seg.setLocalThreshold (local_threshold);
    seg.setTurnSignificance (turn_significance);
    seg.setCorrectedAic (aicc);
    seg.setSideFrames (side_frames);
  }

  /** \brief The cylinder join as the options say. */
  CylinderSegmentJoin<pcl::PointXYZ>
  makeJoin () const
  {
    CylinderSegmentJoin<pcl::PointXYZ> join;
    if (cylinder_tolerance > 0.0)
      join.setDistanceTolerance (cylinder_tolerance);
    if (!radiiFromSpacing())
      join.setRadiusLimits (cylinder_min_radius, cylinder_max_radius);
    if (cylinder_max_gap >= 0.0)
      join.setMaxGap (cylinder_max_gap);
    if (cylinder_patch > 0.0)
      join.setNeighbourhoodRadius (cylinder_patch);
    return join;
  }

private:
  bool
  radiiFromSpacing () const
  {
    return cylinder_min_radius < 0.0 && cylinder_max_radius < 0.0;
  }

  bool
  parseMethod ()
  {
    if (method_name == "proximity")
      method = Segmentation::ProfileMethod::Proximity;
    else if (method_name == "mst")
      method = Segmentation::ProfileMethod::MinimumSpanningTree;
    else if (method_name == "curve")
      method = Segmentation::ProfileMethod::CurveFitting;
    else if (method_name == "crust")
      method = Segmentation::ProfileMethod::CurveReconstruction;
    else
      return false;
    return true;
  }
};
} // namespace apps
} // namespace pcl_ext
