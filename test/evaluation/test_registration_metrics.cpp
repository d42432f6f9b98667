/*
 * Registration metrics with known transforms.
 */
#include <pcl_ext/evaluation/registration_metrics.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace {
Eigen::Matrix4d
makeTransform (double angle_deg, const Eigen::Vector3d& axis, const Eigen::Vector3d& t)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (angle_deg * M_PI / 180.0, axis.normalized())
          .toRotationMatrix();
  m.topRightCorner<3, 1>() = t;
  return m;
}
} // namespace

TEST (RegistrationMetrics, RotationAngle)
{
  for (const double angle : {0.0, 1e-4, 0.5, 30.0, 90.0, 179.0, 179.999, 180.0})
    EXPECT_NEAR (
        pcl_ext::rotationAngleDegrees (
            makeTransform (angle, Eigen::Vector3d (1, -2, 0.5), Eigen::Vector3d::Zero())
                .topLeftCorner<3, 3>()),
        angle,
        1e-7)
        << angle;
}

TEST (RegistrationMetrics, KnownTransformError)
{
  const Eigen::Matrix4d truth =
      makeTransform (30.0, Eigen::Vector3d (1, 1, 1), Eigen::Vector3d (1, 2, 3));
  // The estimate is off by 2 degrees about z (applied after) and by (0.3, 0, 0.4) m.
  Eigen::Matrix4d estimated =
      makeTransform (2.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero()) * truth;
  estimated.topRightCorner<3, 1>() =
      truth.topRightCorner<3, 1>() + Eigen::Vector3d (0.3, 0, 0.4);
  const auto e = pcl_ext::computeTransformationError (estimated, truth);
  EXPECT_NEAR (e.rotation_deg, 2.0, 1e-9);
  EXPECT_NEAR (e.translation, 0.5, 1e-12);
  EXPECT_NEAR (e.scale_ratio, 1.0, 1e-12);

  // Identity.
  const auto zero = pcl_ext::computeTransformationError (truth, truth);
  EXPECT_NEAR (zero.rotation_deg, 0.0, 1e-9);
  EXPECT_NEAR (zero.translation, 0.0, 1e-12);

  // A pure rotation error of 90 degrees about z seen from a reference point 10 m out
  // along x: the point moves by 10 sqrt(2).
  const Eigen::Matrix4d rz =
      makeTransform (90.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero());
  const auto lever = pcl_ext::computeTransformationError (
      rz, Eigen::Matrix4d::Identity(), Eigen::Vector3d (10, 0, 0));
  EXPECT_NEAR (lever.rotation_deg, 90.0, 1e-9);
  EXPECT_NEAR (lever.translation, 10.0 * std::sqrt (2.0), 1e-9);
}

TEST (RegistrationMetrics, ScaleDoesNotLeakIntoRotation)
{
  const Eigen::Matrix4d truth =
      makeTransform (10.0, Eigen::Vector3d (0, 1, 0), Eigen::Vector3d (5, 0, 0));
  Eigen::Matrix4d scaled = truth;
  scaled.topLeftCorner<3, 3>() *= 1.5;
  const auto e = pcl_ext::computeTransformationError (scaled, truth);
  EXPECT_NEAR (e.rotation_deg, 0.0, 1e-9);
  EXPECT_NEAR (e.scale_ratio, 1.5, 1e-12);
}
