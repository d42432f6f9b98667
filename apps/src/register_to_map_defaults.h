/*
 * pcl_ext_register_to_map: settings derived from the scan when they are not given.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl_ext {
namespace apps {
/** \brief The wall extraction's RANSAC settings. */
struct WallExtractionSettings {
  double inlier_distance; ///< metres
  int min_inliers;        ///< least points of a plane
};

/** \brief The wall extraction's settings from the scan, as pcl_ext::estimateCloudNoise
 * finds its noise sigma and point spacing s: the inlier distance three sigmas, at least
 * s / 2 (a noise-free scan); the least points of a plane those of 1.25 m^2 at that
 * spacing (1.25 / s^2), at least 50. \a fallback's values where the scan does not let
 * them be estimated (too few points, noise as large as the neighbourhoods). Only the
 * settings \a derive_distance and \a derive_min_inliers say are derived; the others
 * are \a fallback's. Prints what it chose and why. */
WallExtractionSettings
wallExtractionSettings (const pcl::PointCloud<pcl::PointXYZ>& scan,
                        unsigned int threads,
                        const WallExtractionSettings& fallback,
                        bool derive_distance,
                        bool derive_min_inliers);
} // namespace apps
} // namespace pcl_ext
