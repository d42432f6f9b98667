/*
 * pcl_ext_register_to_map: settings derived from the scan when they are not given.
 */
#include "register_to_map_defaults.h"

#include <pcl_ext/search/cloud_noise.h>

#include <algorithm>
#include <cstdio>

namespace pcl_ext {
namespace apps {
double
ransacInlierDistance (const pcl::PointCloud<pcl::PointXYZ>& scan,
                      unsigned int threads,
                      double fallback)
{
  const NoiseEstimate noise = estimateCloudNoise (scan, 50, threads);
  if (!noise.valid) {
    std::printf ("RANSAC inlier distance %.3g m (the scan's noise could not be "
                 "estimated: %s)\n",
                 fallback,
                 noise.reason.c_str());
    return fallback;
  }
  const double distance = std::max (3.0 * noise.sigma, 0.5 * noise.spacing);
  std::printf (
      "RANSAC inlier distance %.3g m (from the scan: noise sigma %.3g m, point "
      "spacing %.3g m)\n",
      distance,
      noise.sigma,
      noise.spacing);
  return distance;
}
} // namespace apps
} // namespace pcl_ext
