/*
 * Tests of SceneGeometry: ray casting through its BVH, and the class ground truth from
 * its crease and border curves.
 */
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/scene_geometry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace pcl_ext::simulation;

TEST (SceneGeometry, BvhMatchesBruteForce)
{
  SceneGeometry geometry;
  RandomStream rng (7);
  for (int k = 0; k < 300; ++k) {
    const Vec3 c (20 * rng.uniform(), 20 * rng.uniform(), 5 * rng.uniform());
    auto sphere = std::make_shared<Sphere> (c, 0.2 + 0.5 * rng.uniform());
    sphere->info.segment = static_cast<std::uint32_t> (k + 1);
    if (k % 5 == 0)
      sphere->porosity = 0.5;
    geometry.addPrimitive (sphere);
  }
  geometry.build();
  for (int r = 0; r < 5000; ++r) {
    Ray ray{Vec3 (10, 10, 2.5) + Vec3 (rng.gaussian(), rng.gaussian(), rng.gaussian()),
            Vec3 (rng.gaussian(), rng.gaussian(), rng.gaussian()).normalized()};
    RayHit a, b;
    const bool ha = geometry.intersect (ray, 50.0, r, a);
    const bool hb = geometry.intersectBruteForce (ray, 50.0, r, b);
    ASSERT_EQ (ha, hb);
    if (ha) {
      EXPECT_EQ (a.primitive, b.primitive);
      EXPECT_DOUBLE_EQ (a.t, b.t);
    }
  }
}

TEST (SceneGeometry, NearestHitBoundsAndPorosity)
{
  // Two parallel walls x = 2 and x = 4 (1 x 1 m, centred on the x axis); the first lets
  // rays through with the given probability (porosity).
  const auto walls = [] (double porosity) {
    SceneGeometry geometry;
    for (const double x : {2.0, 4.0}) {
      auto wall = std::make_shared<PlanarPolygon> (
          Vec3 (x, -0.5, -0.5),
          Vec3::UnitY(),
          Vec3::UnitZ(),
          std::vector<std::vector<Vec2>>{
              {Vec2 (0, 0), Vec2 (1, 0), Vec2 (1, 1), Vec2 (0, 1)}});
      wall->info.segment = x < 3.0 ? 1 : 2;
      if (x < 3.0)
        wall->porosity = porosity;
      geometry.addPrimitive (wall);
    }
    geometry.build();
    return geometry;
  };
  const SceneGeometry solid = walls (0.0);
  // The primitives' boxes, grown by a hair for the BVH.
  EXPECT_NEAR ((solid.bounds().min - Vec3 (2.0, -0.5, -0.5)).norm(), 0.0, 1e-8);
  EXPECT_NEAR ((solid.bounds().max - Vec3 (4.0, 0.5, 0.5)).norm(), 0.0, 1e-8);
  const Ray ray{Vec3::Zero(), Vec3::UnitX()};
  RayHit hit;
  ASSERT_TRUE (solid.intersect (ray, 100.0, 0, hit));
  EXPECT_NEAR (hit.t, 2.0, 1e-12);
  EXPECT_EQ (hit.primitive, 0);
  EXPECT_NEAR (std::abs (hit.normal.x()), 1.0, 1e-12);
  EXPECT_FALSE (solid.intersect (ray, 1.5, 0, hit)); // t_max before the first wall
  EXPECT_FALSE (solid.intersect ({Vec3::Zero(), -Vec3::UnitX()}, 100.0, 0, hit));
  // Fully porous: every ray reaches the second wall. Half porous: about half of them,
  // and always the same ones for the same ray keys.
  const SceneGeometry open = walls (1.0);
  ASSERT_TRUE (open.intersect (ray, 100.0, 0, hit));
  EXPECT_NEAR (hit.t, 4.0, 1e-12);
  EXPECT_EQ (hit.primitive, 1);
  const SceneGeometry half = walls (0.5);
  int through = 0;
  for (std::uint64_t key = 0; key < 1000; ++key) {
    RayHit a, b;
    ASSERT_TRUE (half.intersect (ray, 100.0, key, a));
    ASSERT_TRUE (half.intersect (ray, 100.0, key, b));
    EXPECT_EQ (a.primitive, b.primitive);
    through += a.primitive == 1;
  }
  EXPECT_GT (through, 400);
  EXPECT_LT (through, 600);
}

TEST (SceneGeometry, ClassesFromTheCurvesOfTheirOwnSegment)
{
  // Segment 1 has a crease with segment 2 along the x axis and a border along x = 1, y
  // >= 0; segment 3 has no curve at all.
  SceneGeometry geometry;
  GroundTruthCurve crease;
  crease.a = Vec3 (-10, 0, 0);
  crease.b = Vec3 (10, 0, 0);
  crease.segment_a = 1;
  crease.segment_b = 2;
  geometry.addCurve (crease);
  GroundTruthCurve border;
  border.kind = GroundTruthCurve::Kind::Border;
  border.a = Vec3 (1, 0, 0);
  border.b = Vec3 (1, 10, 0);
  border.segment_a = 1;
  geometry.addCurve (border);
  geometry.build();
  const double band = 0.05;
  EXPECT_EQ (geometry.classify (Vec3 (-3, 0.02, 0), 1, band),
             pcl_ext::PointClass::Edge);
  EXPECT_EQ (geometry.classify (Vec3 (-3, 0.02, 0), 2, band),
             pcl_ext::PointClass::Edge);
  EXPECT_EQ (geometry.classify (Vec3 (1.03, 5, 0), 1, band),
             pcl_ext::PointClass::Boundary);
  EXPECT_EQ (geometry.classify (Vec3 (1.03, 5, 0), 2, band),
             pcl_ext::PointClass::Surface);
  EXPECT_EQ (geometry.classify (Vec3 (-3, 0.02, 0), 3, band),
             pcl_ext::PointClass::Surface);
  EXPECT_EQ (geometry.classify (Vec3 (-3, 1, 0), 1, band),
             pcl_ext::PointClass::Surface);
  // Near both: the nearer decides.
  EXPECT_EQ (geometry.classify (Vec3 (1.01, 0.04, 0), 1, band),
             pcl_ext::PointClass::Boundary);
  EXPECT_EQ (geometry.classify (Vec3 (1.04, 0.01, 0), 1, band),
             pcl_ext::PointClass::Edge);
  double to_crease, to_border;
  geometry.curveDistances (Vec3 (1.03, 0.02, 0), 1, 1.0, to_crease, to_border);
  EXPECT_NEAR (to_crease, 0.02, 1e-12);
  EXPECT_NEAR (to_border, 0.03, 1e-12);
  geometry.curveDistances (Vec3 (1.03, 0.02, 0), 1, 0.025, to_crease, to_border);
  EXPECT_NEAR (to_crease, 0.02, 1e-12);
  EXPECT_TRUE (std::isinf (to_border)) << "farther than the distance asked for";

  // The other faces of the creases near a point: segment 2 seen from segment 1 and the
  // reverse; none from a border, from too far, or for a segment with no crease.
  std::vector<std::uint32_t> others;
  geometry.creaseFacesNear (Vec3 (1.03, 0.02, 0), 1, band, others);
  EXPECT_EQ (others, std::vector<std::uint32_t> ({2}));
  others.clear();
  geometry.creaseFacesNear (Vec3 (-3, 0.02, 0), 2, band, others);
  EXPECT_EQ (others, std::vector<std::uint32_t> ({1}));
  others.clear();
  geometry.creaseFacesNear (Vec3 (1.03, 5, 0), 1, band, others);
  geometry.creaseFacesNear (Vec3 (-3, 0.2, 0), 1, band, others);
  geometry.creaseFacesNear (Vec3 (-3, 0.02, 0), 3, band, others);
  EXPECT_TRUE (others.empty());
}
