/*
 * pcl_ext_register_to_map: settings derived from the scan when they are not given.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl_ext {
namespace apps {
/** \brief The RANSAC inlier distance of the wall extraction from the scan: three noise
 * sigmas, at least half the point spacing (a noise-free scan), as
 * pcl_ext::estimateCloudNoise finds them; \a fallback when the scan does not let them
 * be estimated (too few points, noise as large as the neighbourhoods). Prints what it
 * chose and why. */
double
ransacInlierDistance (const pcl::PointCloud<pcl::PointXYZ>& scan,
                      unsigned int threads,
                      double fallback);
} // namespace apps
} // namespace pcl_ext
