/*
 * Tests of the linear plane-to-plane estimate (Khoshelham & Gorte 2009, eqs. 8-12).
 */
#include "plane_fixtures.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_transformation_estimation.h>

#include <Eigen/QR>
#include <gtest/gtest.h>

using namespace pcl_ext;

namespace {
// Floor and three walls of the H plan, as map and scan planes related by scan_to_map.
struct FourPlanes {
  std::vector<Plane> map, scan;
  std::vector<PlanePair> pairs;
  Eigen::Matrix4d truth;
};

FourPlanes
fourPlanes (unsigned seed, double scale = 1.0)
{
  FourPlanes f;
  std::vector<MapPlane> map;
  EXPECT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  std::mt19937 rng (seed);
  f.truth = test::randomPose (rng);
  f.truth.topLeftCorner<3, 3>() *= scale;
  for (int i : {0, 1, 2, 7}) // floor, walls y = 0, x = 12 (courtyard) and y = 30
  {
    f.map.push_back (map[i]);
    f.scan.push_back (transformPlane (map[i], f.truth.inverse()));
    f.pairs.push_back (
        {static_cast<int> (f.pairs.size()), static_cast<int> (f.pairs.size()), 1});
  }
  return f;
}
} // namespace

TEST (PlaneTransformationEstimation, RecoversRigidTransformExactly)
{
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const FourPlanes f = fourPlanes (seed);
    PlaneTransformationResult r;
    ASSERT_TRUE (estimatePlaneTransformation (
        f.scan, f.map, f.pairs, PlaneTransformationModel::Rigid, r));
    EXPECT_FALSE (r.degenerate);
    EXPECT_LT ((r.transformation - f.truth).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_NEAR (r.scale, 1.0, 1e-12);
    EXPECT_LT (r.residual_norm, 1e-9);
    ASSERT_EQ (r.angle_residuals.size(), 4u);
    EXPECT_LT (r.max_distance, 1e-9);
    // Noise-free planes: the affine block of eq. 12 is already the rigid transform.
    EXPECT_LT ((r.affine - f.truth.topRows<3>()).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST (PlaneTransformationEstimation, FactoredSolutionEqualsEquation12)
{
  // Perturbed planes: build A (4n x 12) and B of eqs. 10-11 and solve eq. 12 directly.
  FourPlanes f = fourPlanes (7);
  std::mt19937 rng (3);
  std::normal_distribution<double> g (0.0, 0.02);
  for (auto& p : f.scan) {
    p.normal = (p.normal + Eigen::Vector3d (g (rng), g (rng), g (rng))).normalized();
    p.d -= 5 * g (rng);
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero (16, 12);
  Eigen::VectorXd b (16);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j)
      a.block<4, 4> (4 * i, 4 * j) = f.map[i].normal[j] * Eigen::Matrix4d::Identity();
    b.segment<3> (4 * i) = f.scan[i].normal;
    b[4 * i + 3] = f.scan[i].d - f.map[i].d;
  }
  const Eigen::VectorXd x = (a.transpose() * a).ldlt().solve (a.transpose() * b);
  PlaneTransformationResult r;
  ASSERT_TRUE (estimatePlaneTransformation (
      f.scan, f.map, f.pairs, PlaneTransformationModel::Rigid, r));
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col)
      EXPECT_NEAR (r.affine (row, col), x[4 * row + col], 1e-9);
  // The projected transform is a rotation and reports its residuals.
  const Eigen::Matrix3d rot = r.transformation.topLeftCorner<3, 3>();
  EXPECT_LT ((rot * rot.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR (rot.determinant(), 1.0, 1e-12);
  EXPECT_GT (r.residual_norm, 0.0);
  EXPECT_LT (computeTransformationError (r.transformation, f.truth).rotation_deg, 3.0);
}

TEST (PlaneTransformationEstimation, SignOfAPairIsHonoured)
{
  FourPlanes f = fourPlanes (11);
  f.scan[2].normal = -f.scan[2].normal;
  f.scan[2].d = -f.scan[2].d;
  f.pairs[2].sign = -1;
  PlaneTransformationResult r;
  ASSERT_TRUE (estimatePlaneTransformation (
      f.scan, f.map, f.pairs, PlaneTransformationModel::Rigid, r));
  EXPECT_LT ((r.transformation - f.truth).cwiseAbs().maxCoeff(), 1e-9);
}

TEST (PlaneTransformationEstimation, RecoversSimilarity)
{
  const FourPlanes f = fourPlanes (5, 1.25);
  PlaneTransformationResult r;
  ASSERT_TRUE (estimatePlaneTransformation (
      f.scan, f.map, f.pairs, PlaneTransformationModel::Similarity, r));
  EXPECT_NEAR (r.scale, 1.25, 1e-9);
  EXPECT_LT ((r.transformation - f.truth).cwiseAbs().maxCoeff(), 1e-8);
  // A rigid fit cannot explain the scale: it leaves offset residuals.
  PlaneTransformationResult rigid;
  ASSERT_TRUE (estimatePlaneTransformation (
      f.scan, f.map, f.pairs, PlaneTransformationModel::Rigid, rigid));
  EXPECT_GT (rigid.max_distance, 0.5);
}

TEST (PlaneTransformationEstimation, DegenerateSetsAreReportedNotSolved)
{
  const FourPlanes f = fourPlanes (2);
  PlaneTransformationResult r;
  // Walls only: normals span 2D (no floor).
  std::vector<PlanePair> walls (f.pairs.begin() + 1, f.pairs.end());
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, walls, PlaneTransformationModel::Rigid, r));
  EXPECT_TRUE (r.degenerate);
  EXPECT_FALSE (r.valid);
  // Two parallel walls and the floor.
  std::vector<PlanePair> parallel = {f.pairs[0], f.pairs[1], f.pairs[3]};
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, parallel, PlaneTransformationModel::Rigid, r));
  EXPECT_TRUE (r.degenerate);
  // Too few pairs; a similarity needs four.
  std::vector<PlanePair> two (f.pairs.begin(), f.pairs.begin() + 2);
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, two, PlaneTransformationModel::Rigid, r));
  std::vector<PlanePair> three = {f.pairs[0], f.pairs[1], f.pairs[2]};
  EXPECT_TRUE (estimatePlaneTransformation (
      f.scan, f.map, three, PlaneTransformationModel::Rigid, r));
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, three, PlaneTransformationModel::Similarity, r));
  // Out-of-range indices, bad signs, NaN planes.
  std::vector<PlanePair> bad = f.pairs;
  bad[0].map = 9;
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, bad, PlaneTransformationModel::Rigid, r));
  bad = f.pairs;
  bad[1].sign = 0;
  EXPECT_FALSE (estimatePlaneTransformation (
      f.scan, f.map, bad, PlaneTransformationModel::Rigid, r));
  FourPlanes g = f;
  g.scan[1].d = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE (estimatePlaneTransformation (
      g.scan, g.map, g.pairs, PlaneTransformationModel::Rigid, r));
}

TEST (PlaneTransformationEstimation, PlaneTransformerGivesTransformPlaneByParts)
{
  std::mt19937 rng (31);
  Eigen::Matrix4d transformation = test::randomPose (rng);
  transformation.topLeftCorner<3, 3>() *= 1.5; // a similarity
  Plane plane;
  plane.normal = Eigen::Vector3d (0.3, -0.4, 0.2).normalized();
  plane.d = -7.5;
  plane.centroid = -plane.d * plane.normal + Eigen::Vector3d (0.4, 0.3, 0.0);
  plane.extent =
      Eigen::AlignedBox3d (Eigen::Vector3d (-1, -2, 3), Eigen::Vector3d (4, 5, 6));
  const Plane whole = transformPlane (plane, transformation);
  const PlaneTransformer mover (transformation);
  // The parts are those of the whole image to the last bit.
  EXPECT_EQ (mover.normal (plane), whole.normal);
  EXPECT_EQ (mover.point (plane.centroid), whole.centroid);
  EXPECT_EQ (mover.extent (plane).min(), whole.extent.min());
  EXPECT_EQ (mover.extent (plane).max(), whole.extent.max());
  // The image plane holds the images of the plane's points.
  const Eigen::Vector3d on_plane =
      -plane.d * plane.normal + Eigen::Vector3d (0.4, 0.3, -0.1).cross (plane.normal);
  EXPECT_NEAR (whole.signedDistance (mover.point (on_plane)), 0.0, 1e-9);
  EXPECT_NEAR (whole.normal.norm(), 1.0, 1e-12);
  // No extent stays no extent.
  plane.extent.setEmpty();
  EXPECT_TRUE (mover.extent (plane).isEmpty());
  EXPECT_TRUE (transformPlane (plane, transformation).extent.isEmpty());
}
