/*
 * Scan levelling: the vertical of a tilted scan found from its planes (ground, or the
 * walls' common perpendicular), the transform that levels it, and a rigid estimate
 * turned about the vertical only.
 */
#include <pcl_ext/registration/scan_levelling.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace pcl_ext;

namespace {
constexpr double kDeg = M_PI / 180.0;

Plane
plane (const Eigen::Vector3d& n, std::size_t size, const Eigen::Matrix3d& tilt)
{
  Plane p = Plane::throughPoint (tilt * n, Eigen::Vector3d::Zero());
  p.size = size;
  return p;
}

TEST (ScanLevelling, FindsTheVerticalOfATiltedScan)
{
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd (8.0 * kDeg, Eigen::Vector3d (1, 2, 0).normalized())
          .toRotationMatrix();
  // Ground, four walls of two directions, and a sloping plane that must not count.
  std::vector<Plane> planes{plane (Eigen::Vector3d::UnitZ(), 5000, tilt),
                            plane (Eigen::Vector3d::UnitX(), 2000, tilt),
                            plane (Eigen::Vector3d::UnitY(), 1500, tilt),
                            plane (Eigen::Vector3d (1, 1, 0).normalized(), 800, tilt),
                            plane (Eigen::Vector3d (0, 1, 1).normalized(), 3000, tilt)};
  Eigen::Vector3d up;
  ASSERT_TRUE (estimateUpDirection (planes, up));
  EXPECT_LT (std::acos (std::min (1.0, up.dot (tilt * Eigen::Vector3d::UnitZ()))),
             1e-6);
  // Walls alone: their common perpendicular.
  planes.erase (planes.begin());
  ASSERT_TRUE (estimateUpDirection (planes, up));
  EXPECT_LT (std::acos (std::min (1.0, up.dot (tilt * Eigen::Vector3d::UnitZ()))),
             1e-6);
  // Walls of one direction leave the vertical free: no estimate, z kept.
  const std::vector<Plane> one_direction{plane (Eigen::Vector3d::UnitX(), 2000, tilt)};
  EXPECT_FALSE (estimateUpDirection (one_direction, up));
  EXPECT_TRUE (up.isApprox (Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE (
      (levellingTransform (tilt * Eigen::Vector3d::UnitZ()).topLeftCorner<3, 3>() *
       tilt * Eigen::Vector3d::UnitZ())
          .isApprox (Eigen::Vector3d::UnitZ()));
}

// The rigid estimate of a levelled scan keeps the levelling's vertical: a tilted
// estimate (as thin walls give it) becomes the rotation about z nearest to it, and the
// translation is re-fitted to the matched planes at the scan centroids.
TEST (ScanLevelling, RefineAboutVerticalKeepsTheVertical)
{
  const double yaw = 30.0 * kDeg;
  Eigen::Matrix4d truth = Eigen::Matrix4d::Identity();
  truth.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  truth.topRightCorner<3, 1>() = Eigen::Vector3d (5.0, -3.0, 1.0);
  // Map: floor and three walls of two directions; scan: the same, moved by truth^-1.
  std::vector<Plane> map{Plane::throughPoint (Eigen::Vector3d::UnitZ(), {0, 0, 0}),
                         Plane::throughPoint (Eigen::Vector3d::UnitX(), {10, 0, 0}),
                         Plane::throughPoint (Eigen::Vector3d::UnitY(), {0, 8, 0}),
                         Plane::throughPoint (-Eigen::Vector3d::UnitX(), {-6, 0, 0})};
  const Eigen::Vector3d centres[] = {{1, 2, 0}, {10, 3, 2}, {4, 8, 3}, {-6, 1, 2}};
  std::vector<Plane> scan;
  std::vector<PlanePair> pairs;
  const Eigen::Matrix4d inverse = truth.inverse();
  for (int i = 0; i < 4; ++i) {
    scan.push_back (
        Plane::throughPoint (inverse.topLeftCorner<3, 3>() * map[i].normal,
                             (inverse * centres[i].homogeneous()).head<3>()));
    scan.back().centroid = (inverse * centres[i].homogeneous()).head<3>();
    pairs.push_back (PlanePair{i, i, 1});
  }
  // The estimate: the truth tilted by 1.5 degrees about x and shifted by 0.2 m.
  PlaneTransformationResult estimate;
  estimate.valid = true;
  estimate.transformation = truth;
  estimate.transformation.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (1.5 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix() *
      truth.topLeftCorner<3, 3>();
  estimate.transformation (0, 3) += 0.2;
  ASSERT_TRUE (refineAboutVertical (scan, map, pairs, estimate));
  EXPECT_TRUE (estimate.transformation.isApprox (truth, 1e-6))
      << estimate.transformation;
  ASSERT_EQ (estimate.angle_residuals.size(), 4u);
  EXPECT_LT (estimate.max_angle, 1e-9);
  EXPECT_LT (estimate.max_distance, 1e-6);
  // A similarity, an invalid estimate or a pair out of range: left as it is.
  PlaneTransformationResult scaled = estimate;
  scaled.scale = 1.1;
  EXPECT_FALSE (refineAboutVertical (scan, map, pairs, scaled));
  pairs.push_back (PlanePair{7, 0, 1});
  EXPECT_FALSE (refineAboutVertical (scan, map, pairs, estimate));
}
} // namespace
