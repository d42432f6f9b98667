/*
 * pcl_ext: non-template Belton & Lichti kernels.
 */
#include <pcl_ext/features/local_variance.h>

#include <cmath>
#include <limits>

bool
pcl_ext::hasTangentPlane (const Eigen::Vector3d& ascending_values, std::size_t size)
{
  return size >= kMinNeighbours && ascending_values.allFinite() &&
         ascending_values[2] > 0.0 &&
         ascending_values[1] > kMinPlanarRatio * ascending_values[2];
}

double
pcl_ext::chiSquaredQuantile2 (double confidence)
{
  if (!(confidence > 0.0 && confidence < 1.0))
    return std::numeric_limits<double>::quiet_NaN();
  return -2.0 * std::log1p (-confidence);
}

pcl_ext::ProjectedNormalAccumulator::ProjectedNormalAccumulator (
    const Eigen::Vector3d& normal)
: normal_ (normal.normalized())
{
  // Any orthonormal basis of the tangent plane: start from the axis least aligned with
  // n.
  Eigen::Vector3d::Index axis;
  normal_.cwiseAbs().minCoeff (&axis);
  axis_a_ = normal_.cross (Eigen::Vector3d::Unit (axis)).normalized();
  axis_b_ = normal_.cross (axis_a_);
}

bool
pcl_ext::ProjectedNormalAccumulator::compute (ProjectedNormalDirections& result) const
{
  if (count_ < 2 || !normal_.allFinite())
    return false;
  // Both n_j and -n_j contribute p p^T, so the mean of the projections is 0 and the
  // covariance of the 2 m projected points is the plain second moment over the m
  // normals.
  const double inv = 1.0 / static_cast<double> (count_);
  const double a = aa_ * inv, b = ab_ * inv, c = bb_ * inv;
  const double half_trace = 0.5 * (a + c);
  const double root = std::sqrt (0.25 * (a - c) * (a - c) + b * b);
  result.max_change = half_trace + root;
  result.min_change = std::max (0.0, half_trace - root);
  // Eigenvector of the larger eigenvalue, in the tangent basis; any direction when
  // isotropic.
  Eigen::Vector2d v;
  if (root <= 1e-15 * std::max (1e-300, half_trace))
    v = Eigen::Vector2d (1.0, 0.0);
  else if (a >= c)
    v = Eigen::Vector2d (result.max_change - c, b);
  else
    v = Eigen::Vector2d (b, result.max_change - a);
  v.normalize();
  result.max_direction = v.x() * axis_a_ + v.y() * axis_b_;
  result.min_direction = normal_.cross (result.max_direction);
  return result.max_direction.allFinite();
}
