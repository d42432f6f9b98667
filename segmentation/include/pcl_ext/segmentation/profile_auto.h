/*
 * pcl_ext: what a cloud shows (spacing, noise, density variation) and the profile
 * segmentation's configuration chosen from it (Sithole & Mapurisa; not in the paper).
 */
#pragma once

#include <pcl_ext/segmentation/profile_stacks.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl_ext {
namespace profiles {
/** \brief Spacing, noise and density variation of a surface cloud, from a sample of
 * neighbourhoods. */
struct CloudStatistics {
  /** \brief Mean local spacing, sqrt(pi r6^2 / 6) as estimatePointSpacing. */
  double spacing = 0.0;
  /** \brief 90th over 10th percentile of the local spacings: 1 on a uniform grid, the
   * ratio of the sparse to the dense surfaces where the density varies (TLS). */
  double spacing_variation = 0.0;
  /** \brief Noise across the surface: the median over the neighbourhoods (a point and
   * its 16 nearest) of the RMS distance to their plane, sqrt(lambda_min n / (n - 3)).
   * The median keeps creases and edges, a minority of the neighbourhoods, out. */
  double noise = 0.0;
  std::size_t samples = 0; ///< neighbourhoods that had 16 distinct neighbours
};

/** \brief Estimate spacing, noise and spacing variation from up to \a samples points
 * evenly spread over \a xyz (deterministic; the same sweep along a sort as
 * estimatePointSpacing, no tree). All fields 0 when no sampled point has 16 distinct
 * neighbours. */
CloudStatistics
estimateCloudStatistics (const std::vector<Eigen::Vector3f>& xyz,
                         std::size_t samples = 2048);

/** \brief The statistics estimateCloudStatistics gives from sampled neighbourhoods
 * (profiles::sampleNeighbourhoods with k = 16; the samples with 16 nearest count). */
CloudStatistics
cloudStatisticsOf (const std::vector<SampledNeighbourhood>& neighbourhoods);

/** \brief The configuration chosen from the statistics (see chooseConfiguration). */
struct AutoConfiguration {
  bool curve_fitting = false;   ///< curve fitting rather than proximity chaining
  bool noisy = false;           ///< with it, AICc, turn significance 3, width 2.5x
  bool local_threshold = false; ///< thresholds that follow the local density
  bool side_frames = false;     ///< each side fitted along its own axis
  bool join_cylinders = false;  ///< CylinderSegmentJoin after the segmentation
};

/** \brief Share of the points in the largest proximity segment from which the
 * surfaces are taken to touch (objects on a floor or the ground, pipes on supports, a
 * trunk on the ground) and curve fitting is chosen. */
constexpr double kAutoTouchingShare = 0.5;
/** \brief Noise over spacing from which curve fitting is set for noisy scans. */
constexpr double kAutoNoiseRatio = 0.05;
/** \brief Spacing variation from which local thresholds are chosen. */
constexpr double kAutoLocalThresholdVariation = 3.0;

/** \brief The configuration for a cloud.
 *
 * Proximity chaining, the paper's default, separates objects that do not touch. When
 * its largest segment holds at least kAutoTouchingShare of the points (\a
 * largest_share), surfaces touch and only creases separate them: curve fitting, then
 * side frames (tight bends such as thin trunks) and the cylinder join (curve fitting
 * cuts pipes at their supports and trunks where branches leave). Where the noise is at
 * least kAutoNoiseRatio of the spacing, curve fitting is set for noisy scans (AICc,
 * turn significance 3, width 2.5 spacings): a side of about ten points cannot tell a
 * 30 degree turn from the noise. Local thresholds where the spacing varies by more than
 * kAutoLocalThresholdVariation (TLS: far surfaces are sparser). */
AutoConfiguration
chooseConfiguration (const CloudStatistics& statistics, double largest_share);

/** \brief One line describing the statistics and the choice, for -v output. */
std::string
describeConfiguration (const CloudStatistics& statistics,
                       double largest_share,
                       const AutoConfiguration& configuration);
} // namespace profiles
} // namespace pcl_ext
