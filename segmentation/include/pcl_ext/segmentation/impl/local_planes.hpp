/*
 * pcl_ext: the least-squares plane of a whole segment.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/features/local_variance.h>
#include <pcl_ext/segmentation/local_planes.h>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>

template <typename PointT>
pcl_ext::Plane
pcl_ext::fitSegmentPlane (const pcl::PointCloud<PointT>& cloud,
                          const pcl::Indices& indices,
                          const Eigen::Vector3d& viewpoint)
{
  Plane plane;
  Eigen::Matrix3d covariance;
  plane.size = computeLocalCovariance (cloud, indices, covariance, plane.centroid);
  EigenDecomposition eigen;
  if (plane.size < kMinNeighbours || !computeEigenDecomposition (covariance, eigen) ||
      !hasTangentPlane (eigen.values, plane.size))
    return plane;
  Eigen::Vector3d n = eigen.normal();
  if (n.dot (viewpoint - plane.centroid) < 0.0)
    n = -n;
  double sum = 0.0, largest = 0.0;
  for (const auto i : indices) {
    const PointT& p = cloud[i];
    if (!pcl::isXYZFinite (p))
      continue;
    // Offsets from the centroid in double: exact enough at any coordinate magnitude.
    const double r =
        std::abs (n.dot (Eigen::Vector3d (p.x, p.y, p.z) - plane.centroid));
    sum += r * r;
    largest = std::max (largest, r);
  }
  plane.normal = n;
  plane.d = -n.dot (plane.centroid);
  plane.rms = std::sqrt (sum / static_cast<double> (plane.size));
  plane.max_residual = largest;
  return plane;
}

#define PCL_EXT_INSTANTIATE_fitSegmentPlane(T)                                         \
  template pcl_ext::Plane pcl_ext::fitSegmentPlane<T> (                                \
      const pcl::PointCloud<T>&, const pcl::Indices&, const Eigen::Vector3d&);
