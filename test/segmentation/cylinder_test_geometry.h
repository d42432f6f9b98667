/*
 * Geometry the cylinder tests measure their results with.
 */
#pragma once

#include <pcl_ext/segmentation/local_planes.h>

#include <Eigen/Core>

#include <cmath>

namespace pcl_ext {
namespace test {
/** Angle between two axes, ignoring their sense, in degrees. */
inline double
axisAngleDegrees (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return normalAngle (a.normalized(), b.normalized()) * 180.0 / M_PI;
}

/** Distance of \a q from the line through \a point along \a axis. */
inline double
lineDistance (const Eigen::Vector3d& q,
              const Eigen::Vector3d& point,
              const Eigen::Vector3d& axis)
{
  const Eigen::Vector3d w = q - point, d = axis.normalized();
  return (w - w.dot (d) * d).norm();
}
} // namespace test
} // namespace pcl_ext
