/*
 * pcl_ext_register_to_map: settings derived from the scan when they are not given.
 */
#include "register_to_map_defaults.h"

#include <pcl_ext/search/cloud_noise.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pcl_ext {
namespace apps {
WallExtractionSettings
wallExtractionSettings (const pcl::PointCloud<pcl::PointXYZ>& scan,
                        unsigned int threads,
                        const WallExtractionSettings& fallback,
                        bool derive_distance,
                        bool derive_min_inliers)
{
  WallExtractionSettings settings = fallback;
  if (!derive_distance && !derive_min_inliers)
    return settings;
  const NoiseEstimate noise = estimateCloudNoise (scan, 50, threads);
  if (!noise.valid) {
    std::printf ("RANSAC inlier distance %.3g m, planes of at least %d points (the "
                 "scan's noise and spacing could not be estimated: %s)\n",
                 settings.inlier_distance,
                 settings.min_inliers,
                 noise.reason.c_str());
    return settings;
  }
  if (derive_distance)
    settings.inlier_distance = std::max (3.0 * noise.sigma, 0.5 * noise.spacing);
  if (derive_min_inliers) {
    // 1.25 m^2 of a wall at the scan's spacing: a plane is a piece of wall, not a
    // number of points, whatever the scanner's resolution.
    const double points = 1.25 / (noise.spacing * noise.spacing);
    settings.min_inliers =
        static_cast<int> (std::min (std::max (std::round (points), 50.0), 1e8));
  }
  std::printf ("RANSAC inlier distance %.3g m, planes of at least %d points (from the "
               "scan: noise sigma %.3g m, point spacing %.3g m)\n",
               settings.inlier_distance,
               settings.min_inliers,
               noise.sigma,
               noise.spacing);
  return settings;
}
} // namespace apps
} // namespace pcl_ext
