/*
 * pcl_ext: non-template local plane kernels, and the segment plane fit precompiled for
 * the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/local_planes.hpp>
#include <pcl_ext/segmentation/local_planes.h>

#include <algorithm>
#include <cmath>

bool
pcl_ext::fitLocalPlane (const CovarianceSums& sums,
                        const Eigen::Vector3d* normal,
                        LocalPlane& plane)
{
  Eigen::Matrix3d covariance;
  plane.size = sums.finish (covariance, plane.centroid);
  if (plane.size < 3)
    return false;
  EigenDecomposition eigen;
  if (!computeEigenDecomposition (covariance, eigen))
    return false;
  const Eigen::Vector3d& l = eigen.values;
  // Coincident or collinear points have no plane (same bound as the classifier's).
  if (!(l[2] > 0.0) || !(l[1] > 1e-8 * l[2]))
    return false;
  plane.axis1 = eigen.vectors.col (1);
  plane.axis2 = eigen.vectors.col (2);
  plane.variance1 = l[1];
  plane.variance2 = l[2];
  if (normal) {
    const double length = normal->norm();
    if (!(length > 0.0) || !std::isfinite (length))
      return false;
    plane.normal = *normal / length;
    plane.d = -plane.normal.dot (plane.centroid);
    plane.rms =
        std::sqrt (std::max (0.0, plane.normal.dot (covariance * plane.normal)));
    return true;
  }
  plane.normal = eigen.normal();
  plane.d = -plane.normal.dot (plane.centroid);
  plane.rms = std::sqrt (l[0]);
  return true;
}

double
pcl_ext::normalAngle (const Eigen::Vector3d& n1, const Eigen::Vector3d& n2)
{
  // atan2 of |n1 x n2| and |n1 . n2| keeps its accuracy near 0, where arccos of a dot
  // product close to 1 loses half the digits (the parallel test works at small angles).
  return std::atan2 (n1.cross (n2).norm(), std::abs (n1.dot (n2)));
}

bool
pcl_ext::intersectLocalPlanes (const Plane& plane1,
                               const Plane& plane2,
                               const Eigen::Vector3d& p1,
                               const Eigen::Vector3d& p2,
                               Eigen::Vector3d& point,
                               Eigen::Vector3d& direction)
{
  const Eigen::Vector3d& n1 = plane1.normal;
  const Eigen::Vector3d& n2 = plane2.normal;
  const Eigen::Vector3d a = n1.cross (n2);
  const double det = a.squaredNorm(); // 1 - c^2 = sin^2(theta) for unit normals
  if (!(det > 0.0) || !std::isfinite (det))
    return false;
  const Eigen::Vector3d m = 0.5 * (p1 + p2);
  const double c = n1.dot (n2);
  const double r1 = plane1.signedDistance (m);
  const double r2 = plane2.signedDistance (m);
  const double alpha = (-r1 + c * r2) / det;
  const double beta = (-r2 + c * r1) / det;
  point = m + alpha * n1 + beta * n2;
  direction = a / std::sqrt (det);
  return point.allFinite();
}

PCL_EXT_INSTANTIATE (fitSegmentPlane, PCL_EXT_XYZ_POINT_TYPES)
