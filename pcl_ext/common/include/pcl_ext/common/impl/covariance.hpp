/*
 * pcl_ext: template part of the covariance kernel.
 */
#pragma once

#include <pcl_ext/common/covariance.h>

#include <pcl/common/point_tests.h>

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
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  bool have_centre = false;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
  std::size_t n = 0;
  for (IndexIterator it = begin; it != end; ++it) {
    const PointT& p = cloud[static_cast<std::size_t> (*it)];
    if (!pcl::isFinite (p))
      continue;
    if (!have_centre) {
      centre = Eigen::Vector3d (p.x, p.y, p.z);
      have_centre = true;
    }
    const double x = static_cast<double> (p.x) - centre.x();
    const double y = static_cast<double> (p.y) - centre.y();
    const double z = static_cast<double> (p.z) - centre.z();
    sum += Eigen::Vector3d (x, y, z);
    xx += x * x;
    xy += x * y;
    xz += x * z;
    yy += y * y;
    yz += y * z;
    zz += z * z;
    ++n;
  }
  if (n == 0)
    return 0;
  const double inv_n = 1.0 / static_cast<double> (n);
  const Eigen::Vector3d mean = sum * inv_n;
  covariance (0, 0) = xx * inv_n - mean.x() * mean.x();
  covariance (0, 1) = xy * inv_n - mean.x() * mean.y();
  covariance (0, 2) = xz * inv_n - mean.x() * mean.z();
  covariance (1, 1) = yy * inv_n - mean.y() * mean.y();
  covariance (1, 2) = yz * inv_n - mean.y() * mean.z();
  covariance (2, 2) = zz * inv_n - mean.z() * mean.z();
  covariance (1, 0) = covariance (0, 1);
  covariance (2, 0) = covariance (0, 2);
  covariance (2, 1) = covariance (1, 2);
  centroid = centre + mean;
  return n;
}

template <typename PointT, typename IndexIterator>
bool
pcl_ext::fitPatchNormal (const pcl::PointCloud<PointT>& cloud,
                         IndexIterator begin,
                         IndexIterator end,
                         Eigen::Vector3f& normal,
                         float& curvature)
{
  Eigen::Matrix3d covariance;
  Eigen::Vector3d centroid;
  EigenDecomposition eigen;
  if (computeLocalCovariance (cloud, begin, end, covariance, centroid) < 3 ||
      !computeEigenDecomposition (covariance, eigen) || !(eigen.values (2) > 0.0))
    return false;
  normal = eigen.normal().template cast<float>();
  curvature = static_cast<float> (surfaceVariance (eigen.values));
  return true;
}
