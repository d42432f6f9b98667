/*
 * Tests of the planes of Khoshelham & Gorte (2009): pi = (n, d) with n . x + d = 0 (eq.
 * 3) and their images under a rigid or similarity transform (eq. 6).
 */
#include "plane_fixtures.h"

#include <pcl_ext/registration/planes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl_ext;

TEST (Planes, MapPlaneFloorAndWallLength)
{
  MapPlane floor;
  EXPECT_TRUE (floor.isFloor());
  EXPECT_EQ (floor.length(), 0.0);
  MapPlane wall;
  wall.edge = 3;
  wall.start = Eigen::Vector2d (1.0, 1.0);
  wall.end = Eigen::Vector2d (4.0, 5.0);
  EXPECT_FALSE (wall.isFloor());
  EXPECT_DOUBLE_EQ (wall.length(), 5.0);
}

// The image of a plane under x' = s R x + t holds the images of its points, keeps a
// unit normal, moves centroid and extent with the points, and the inverse transform
// brings it back.
TEST (Planes, TransformPlaneMovesThePlaneWithItsPoints)
{
  std::mt19937 rng (11);
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  for (const double scale : {1.0, 1.3})
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::Matrix4d t = test::randomPose (rng, 20.0, 50.0);
      t.topLeftCorner<3, 3>() *= scale;
      Plane plane;
      plane.normal = Eigen::Vector3d (unit (rng), unit (rng), unit (rng)).normalized();
      plane.centroid = 10.0 * Eigen::Vector3d (unit (rng), unit (rng), unit (rng));
      plane.d = -plane.normal.dot (plane.centroid);
      plane.extent.extend (plane.centroid - Eigen::Vector3d (2, 3, 1));
      plane.extent.extend (plane.centroid + Eigen::Vector3d (1, 2, 4));
      const Plane image = transformPlane (plane, t);
      EXPECT_NEAR (image.normal.norm(), 1.0, 1e-12);
      const Eigen::Vector3d u = plane.normal.unitOrthogonal(),
                            v = plane.normal.cross (u);
      for (const double a : {-5.0, 0.0, 7.0})
        for (const double b : {-3.0, 2.0}) {
          const Eigen::Vector3d x = plane.centroid + a * u + b * v;
          EXPECT_NEAR (
              image.signedDistance ((t * x.homogeneous()).head<3>()), 0.0, 1e-9);
        }
      // A point off the plane keeps its side, its distance scaled by s.
      const Eigen::Vector3d off = plane.centroid + 2.0 * plane.normal;
      EXPECT_NEAR (
          image.signedDistance ((t * off.homogeneous()).head<3>()), 2.0 * scale, 1e-9);
      EXPECT_TRUE (image.centroid.isApprox (
          (t * plane.centroid.homogeneous()).head<3>(), 1e-12));
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner =
            plane.extent.corner (static_cast<Eigen::AlignedBox3d::CornerType> (c));
        EXPECT_TRUE (image.extent.exteriorDistance (
                         (t * corner.homogeneous()).head<3>()) < 1e-9);
      }
      const Plane back = transformPlane (image, t.inverse());
      EXPECT_TRUE (back.normal.isApprox (plane.normal, 1e-9));
      EXPECT_NEAR (back.d, plane.d, 1e-9);
    }
  // An empty extent stays empty.
  Plane bare;
  EXPECT_TRUE (transformPlane (bare, Eigen::Matrix4d::Identity()).extent.isEmpty());
}
