/*
 * Scan levelling: the vertical of a tilted scan found from its planes (ground, or the
 * walls' common perpendicular), the transform that levels it, and a rigid estimate
 * turned about the vertical only.
 */
#include <pcl_ext/registration/scan_levelling.h>

#include <Eigen/Eigenvalues>

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

namespace {
// The least-squares normal of \a points (the smallest eigenvector), z >= 0.
Eigen::Vector3d
fittedNormal (const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<double> (points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  Eigen::Vector3d n = solver.eigenvectors().col (0);
  return n.z() < 0.0 ? -n : n;
}

double
angleDeg (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::acos (std::min (1.0, a.normalized().dot (b.normalized()))) / kDeg;
}
} // namespace

// A town's ground: level terraces 10 m deep, each 15 cm above the last (kerbs, steps),
// 1 cm of noise. One plane through it leans by what the steps add up to; its flat
// patches are level.
TEST (FlatPatchNormal, StepsDoNotLeanTheGround)
{
  std::vector<Eigen::Vector3d> points;
  unsigned state = 1;
  auto jitter = [&state] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) % 2001) / 100000.0 - 0.01; // [-1, 1] cm
  };
  for (double x = 0.0; x < 100.0; x += 0.5)
    for (double y = 0.0; y < 60.0; y += 0.5)
      points.emplace_back (x, y, 0.15 * std::floor (x / 10.0) + jitter());
  const Eigen::Vector3d fitted = fittedNormal (points);
  ASSERT_GT (angleDeg (fitted, Eigen::Vector3d::UnitZ()), 0.7);
  Eigen::Vector3d normal;
  ASSERT_TRUE (estimateFlatPatchNormal (points, fitted, normal));
  EXPECT_LT (angleDeg (normal, Eigen::Vector3d::UnitZ()), 0.05);
  // The same ground turned by 2 degrees about a horizontal axis: the patches turn with
  // it.
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd (2.0 * kDeg, Eigen::Vector3d (1, -1, 0).normalized())
          .toRotationMatrix();
  for (auto& p : points)
    p = tilt * p;
  ASSERT_TRUE (estimateFlatPatchNormal (points, fittedNormal (points), normal));
  EXPECT_LT (angleDeg (normal, tilt * Eigen::Vector3d::UnitZ()), 0.05);
}

// An even plane (noise only): its RMS is that of its patches, so its fit stands.
TEST (FlatPatchNormal, AnEvenPlaneKeepsItsFit)
{
  const Eigen::Vector3d truth = Eigen::Vector3d (0.03, -0.02, 1.0).normalized();
  const Eigen::Vector3d e1 = truth.unitOrthogonal(), e2 = truth.cross (e1);
  std::vector<Eigen::Vector3d> points;
  unsigned state = 7;
  for (double u = -30.0; u < 30.0; u += 0.4)
    for (double v = -20.0; v < 20.0; v += 0.4) {
      state = state * 1103515245u + 12345u;
      const double noise = ((state >> 8) % 2001) / 40000.0 - 0.025; // +-2.5 cm
      points.push_back (u * e1 + v * e2 + noise * truth);
    }
  const Eigen::Vector3d fitted = fittedNormal (points);
  Eigen::Vector3d normal;
  EXPECT_FALSE (estimateFlatPatchNormal (points, fitted, normal));
  EXPECT_TRUE (normal == fitted);
  // The same plane with a 40 cm step across it (a quay, a terrace) is uneven: the
  // patches' normal, on the side of the normal given, is the plane's.
  for (auto& p : points)
    if (p.dot (e1) > 10.0)
      p += 0.4 * truth;
  ASSERT_TRUE (estimateFlatPatchNormal (points, -fittedNormal (points), normal));
  EXPECT_LT (angleDeg (normal, -truth), 0.05);
}

// Too few points or patches: false, and the normal given back as it came.
TEST (FlatPatchNormal, TooLittleToGoOnKeepsTheFittedNormal)
{
  const Eigen::Vector3d fitted = Eigen::Vector3d (0.01, 0.0, 1.0).normalized();
  Eigen::Vector3d normal;
  EXPECT_FALSE (estimateFlatPatchNormal ({}, fitted, normal));
  EXPECT_TRUE (normal == fitted);
  // 400 points in a line: no cell has a slope across it.
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 400; ++i)
    line.emplace_back (0.1 * i, 0.0, 0.0);
  EXPECT_FALSE (estimateFlatPatchNormal (line, fitted, normal));
  EXPECT_TRUE (normal == fitted);
  // 100 points spread over 32 x 32 cells: no cell holds 8.
  std::vector<Eigen::Vector3d> sparse;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      sparse.emplace_back (10.0 * i, 10.0 * j, 0.0);
  EXPECT_FALSE (estimateFlatPatchNormal (sparse, fitted, normal));
  EXPECT_TRUE (normal == fitted);
  // Non-finite normal or too few cells across.
  std::vector<Eigen::Vector3d> dense;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      dense.emplace_back (0.1 * i, 0.1 * j, 0.0);
  EXPECT_FALSE (estimateFlatPatchNormal (dense, Eigen::Vector3d::Zero(), normal));
  EXPECT_FALSE (estimateFlatPatchNormal (dense, fitted, normal, 1));
  EXPECT_TRUE (normal == fitted);
}
