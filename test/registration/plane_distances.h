/*
 * The distances between the matched planes of a registration (Khoshelham & Gorte 2009,
 * Tables 1-2), measured by pcl_ext::evaluation on the registration's planes and match
 * set.
 */
#pragma once

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <vector>

namespace pcl_ext {
namespace test {
/** Mean and maximum distance of the matched scan planes' inliers (points of \a scan,
 * the registration's source) to their target planes after the final transform. */
template <typename PointT>
PlaneDistanceMetrics
planeDistances (const PlaneMatchingRegistration<PointT, PointT>& reg,
                const pcl::PointCloud<PointT>& scan)
{
  std::vector<pcl::PointIndices> inliers;
  for (const auto& plane : reg.getSourcePlanes())
    inliers.push_back (plane.inliers);
  std::vector<Eigen::Vector4d> coefficients;
  for (const auto& plane : reg.getTargetPlanes())
    coefficients.push_back (plane.coefficients());
  pcl::Correspondences matches;
  for (const auto& pair : reg.getMatchingResult().matches)
    matches.emplace_back (pair.scan, pair.map, 0.f);
  PlaneDistanceMetrics metrics;
  computePlaneDistances (scan,
                         inliers,
                         coefficients,
                         matches,
                         reg.getFinalTransformationDouble(),
                         metrics);
  return metrics;
}
} // namespace test
} // namespace pcl_ext
