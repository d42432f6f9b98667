/*
 * pcl_ext: registration accuracy.
 */
#include <pcl_ext/evaluation/registration_metrics.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>

namespace {
/** Nearest rotation to \a m (polar decomposition) and the mean singular value (the
 * scale). */
Eigen::Matrix3d
nearestRotation (const Eigen::Matrix3d& m, double* scale = nullptr)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd (
      m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  // A reflection is not a rotation: flip the weakest direction instead.
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0)
    d (2, 2) = -1.0;
  if (scale)
    *scale = svd.singularValues().mean();
  return svd.matrixU() * d * svd.matrixV().transpose();
}
} // namespace

double
pcl_ext::rotationAngleDegrees (const Eigen::Matrix3d& rotation)
{
  const Eigen::Matrix3d r = nearestRotation (rotation);
  const Eigen::Vector3d vee (
      r (2, 1) - r (1, 2), r (0, 2) - r (2, 0), r (1, 0) - r (0, 1));
  const double angle = std::atan2 (0.5 * vee.norm(), 0.5 * (r.trace() - 1.0));
  return angle * 180.0 / M_PI;
}

pcl_ext::TransformationError
pcl_ext::computeTransformationError (const Eigen::Matrix4d& estimated,
                                     const Eigen::Matrix4d& truth,
                                     const Eigen::Vector3d& reference)
{
  TransformationError error;
  double scale_estimated = 1.0, scale_truth = 1.0;
  const Eigen::Matrix3d r_estimated =
      nearestRotation (estimated.topLeftCorner<3, 3>(), &scale_estimated);
  const Eigen::Matrix3d r_truth =
      nearestRotation (truth.topLeftCorner<3, 3>(), &scale_truth);
  error.rotation_deg = rotationAngleDegrees (r_estimated * r_truth.transpose());
  const Eigen::Vector3d p_estimated =
      estimated.topLeftCorner<3, 3>() * reference + estimated.topRightCorner<3, 1>();
  const Eigen::Vector3d p_truth =
      truth.topLeftCorner<3, 3>() * reference + truth.topRightCorner<3, 1>();
  error.translation = (p_estimated - p_truth).norm();
  error.scale_ratio = scale_truth > 0.0 ? scale_estimated / scale_truth : 0.0;
  return error;
}
