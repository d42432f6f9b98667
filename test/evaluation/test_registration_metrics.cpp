/*
 * Registration metrics with known transforms.
 */
#include <pcl_ext/evaluation/registration_metrics.h>

#include <pcl/point_types.h>

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

TEST (RegistrationMetrics, PlaneDistances)
{
  // Scan: a wall x = 0 (points with alternating +-0.2 m noise along x) and a floor z =
  // 0.
  pcl::PointCloud<pcl::PointXYZ> scan;
  std::vector<pcl::PointIndices> planes (2);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      planes[0].indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ ((i + j) % 2 ? 0.2f : -0.2f, 0.5f * i, 0.5f * j));
      planes[1].indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ (0.5f * i + 1.0f, 0.5f * j, 0.0f));
    }
  scan.push_back (pcl::PointXYZ (std::nanf (""), 0, 0)); // skipped
  planes[1].indices.push_back (static_cast<int> (scan.size() - 1));

  // The map is the scan moved by a known transform; its planes are (n, d), n . x + d =
  // 0.
  const Eigen::Matrix4d truth =
      makeTransform (40.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d (100, 200, 3));
  const Eigen::Matrix3d r = truth.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = truth.topRightCorner<3, 1>();
  std::vector<Eigen::Vector4d> map_planes;
  for (const Eigen::Vector3d n :
       {Eigen::Vector3d (1, 0, 0), Eigen::Vector3d (0, 0, 1)}) {
    const Eigen::Vector3d nm = r * n;
    // Scale the normal by 2 to check that it is normalised.
    map_planes.push_back (2.0 * Eigen::Vector4d (nm.x(), nm.y(), nm.z(), -nm.dot (t)));
  }
  map_planes.push_back (Eigen::Vector4d (0, 1, 0, 0)); // an unmatched map plane
  pcl::Correspondences matches = {pcl::Correspondence (0, 0, 0.f),
                                  pcl::Correspondence (1, 1, 0.f)};

  pcl_ext::PlaneDistanceMetrics m;
  ASSERT_TRUE (
      pcl_ext::computePlaneDistances (scan, planes, map_planes, matches, truth, m));
  ASSERT_EQ (m.pairs.size(), 2u);
  EXPECT_EQ (m.points, 200u);
  EXPECT_NEAR (m.pairs[0].mean, 0.2, 1e-6);
  EXPECT_NEAR (m.pairs[0].max, 0.2, 1e-6);
  EXPECT_NEAR (m.pairs[0].centroid_distance, 0.0, 1e-6);
  EXPECT_NEAR (m.pairs[1].mean, 0.0, 1e-6);
  EXPECT_EQ (m.pairs[1].points, 100u);
  EXPECT_NEAR (m.mean, 0.1, 1e-6);
  EXPECT_NEAR (m.max, 0.2, 1e-6);
  EXPECT_NEAR (m.mean_of_planes, 0.1, 1e-6);
  EXPECT_NEAR (m.max_angle_deg, 0.0, 1e-3);

  // Shift the estimate by 0.5 m along z: the floor is 0.5 m off, the wall unaffected.
  Eigen::Matrix4d shifted = truth;
  shifted (2, 3) += 0.5;
  ASSERT_TRUE (
      pcl_ext::computePlaneDistances (scan, planes, map_planes, matches, shifted, m));
  EXPECT_NEAR (m.pairs[1].mean, 0.5, 1e-6);
  EXPECT_NEAR (m.pairs[1].centroid_distance, 0.5, 1e-6);
  EXPECT_NEAR (m.pairs[0].mean, 0.2, 1e-6);
  EXPECT_NEAR (m.max, 0.5, 1e-6);

  // Tilt the estimate by 3 degrees about y: both planes tilt by 3 degrees.
  const Eigen::Matrix4d tilted =
      truth * makeTransform (3.0, Eigen::Vector3d::UnitY(), Eigen::Vector3d::Zero());
  ASSERT_TRUE (
      pcl_ext::computePlaneDistances (scan, planes, map_planes, matches, tilted, m));
  EXPECT_NEAR (m.pairs[1].angle_deg, 3.0, 1e-3);
  EXPECT_NEAR (m.max_angle_deg, 3.0, 1e-3);

  // A correspondence out of range is refused.
  matches.push_back (pcl::Correspondence (2, 0, 0.f));
  EXPECT_FALSE (
      pcl_ext::computePlaneDistances (scan, planes, map_planes, matches, truth, m));
  EXPECT_TRUE (m.pairs.empty());
}
