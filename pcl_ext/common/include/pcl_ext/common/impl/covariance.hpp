/*
 * pcl_ext: template part of the covariance kernel.
 */
#pragma once

#include <pcl_ext/common/covariance.h>

#include <pcl/common/point_tests.h>

template <typename PointT, typename IndexIterator>
pcl_ext::CovarianceSums
pcl_ext::sumFinitePoints (const pcl::PointCloud<PointT>& cloud,
                          IndexIterator begin,
                          IndexIterator end)
{
  CovarianceSums sums;
  for (IndexIterator it = begin; it != end; ++it) {
    const PointT& p = cloud[static_cast<std::size_t> (*it)];
    if (pcl::isFinite (p))
      sums.add (Eigen::Vector3d (p.x, p.y, p.z));
  }
  return sums;
}

template <typename PointT, typename IndexIterator>
std::size_t
pcl_ext::computeLocalCovariance (const pcl::PointCloud<PointT>& cloud,
                                 IndexIterator begin,
                                 IndexIterator end,
                                 Eigen::Matrix3d& covariance,
                                 Eigen::Vector3d& centroid)
{
  // Shift by the first finite point: sums of squares of small numbers keep full
  // precision even for georeferenced coordinates, where a single-pass float formula
  // cancels catastrophically.
  return sumFinitePoints (cloud, begin, end).finish (covariance, centroid);
}

template <typename PointT, typename IndexIterator>
bool
pcl_ext::fitPatchNormal (const pcl::PointCloud<PointT>& cloud,
                         IndexIterator begin,
                         IndexIterator end,
                         Eigen::Vector3f& normal,
                         float& curvature,
                         float* smallest_variance)
{
  Eigen::Matrix3d covariance;
  Eigen::Vector3d centroid;
  EigenDecomposition eigen;
  if (computeLocalCovariance (cloud, begin, end, covariance, centroid) < 3 ||
      !computeEigenDecomposition (covariance, eigen) || !(eigen.values (2) > 0.0))
    return false;
  normal = eigen.normal().template cast<float>();
  curvature = static_cast<float> (surfaceVariance (eigen.values));
  if (smallest_variance)
    *smallest_variance = static_cast<float> (std::max (eigen.values (0), 0.0));
  return true;
}
