/*
 * Tests of the simulator's analytic primitives: ray hits on their surfaces, holes, cut
 * spheres.
 */
#include <pcl_ext/simulation/primitives.h>
#include <pcl_ext/simulation/random.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_ext::simulation;

namespace {
// Casts rays from random origins towards random points of the primitive's box; every
// hit must lie on the surface, and the hit count must be substantial.
void
checkHitsOnSurface (const Primitive& primitive, int rays, double tolerance)
{
  RandomStream rng (42);
  const Aabb box = primitive.bounds();
  int hits = 0;
  for (int k = 0; k < rays; ++k) {
    const Vec3 target =
        box.min +
        (box.max - box.min)
            .cwiseProduct (Vec3 (rng.uniform(), rng.uniform(), rng.uniform()));
    const Vec3 origin =
        box.centre() + 10.0 * Vec3 (rng.gaussian(), rng.gaussian(), rng.gaussian());
    Ray ray{origin, (target - origin).normalized()};
    double t;
    Vec3 n;
    if (!primitive.intersect (ray, 0.0, 1e9, t, n))
      continue;
    ++hits;
    const Vec3 p = origin + t * ray.direction;
    EXPECT_NEAR (primitive.implicit (p), 0.0, tolerance);
    EXPECT_NEAR (n.norm(), 1.0, 1e-9);
  }
  EXPECT_GT (hits, rays / 10);
}
} // namespace

TEST (SimulationPrimitives, HitsLieOnTheSurface)
{
  checkHitsOnSurface (
      PlanarPolygon (
          Vec3 (1, 2, 3),
          Vec3::UnitX(),
          Vec3 (0, 1, 1).normalized(),
          {{Vec2 (0, 0), Vec2 (2, 0), Vec2 (2, 2), Vec2 (0, 2)},
           {Vec2 (0.5, 0.5), Vec2 (1.5, 0.5), Vec2 (1.5, 1.5), Vec2 (0.5, 1.5)}}),
      2000,
      1e-9);
  checkHitsOnSurface (Annulus (Vec3 (0, 0, 1), Vec3 (1, 1, 0), 0.2, 0.5), 2000, 1e-9);
  checkHitsOnSurface (
      ConeFrustum (Vec3 (0, 0, 0), Vec3 (0, 1, 1), 2.0, 0.5, 0.2), 2000, 1e-9);
  checkHitsOnSurface (Sphere (Vec3 (1, 1, 1), 0.7, Vec3::UnitZ(), 0.3), 2000, 1e-9);
  checkHitsOnSurface (
      Ellipsoid (Vec3 (0, 0, 2), Eigen::Matrix3d::Identity(), Vec3 (1.0, 0.5, 0.3)),
      2000,
      1e-9);
  checkHitsOnSurface (
      TorusSection (
          Vec3 (0, 0, 0), Vec3::UnitY(), Vec3::UnitZ(), 0.5, 0.1, 1.5707963267948966),
      4000,
      1e-7);
  std::vector<double> heights;
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 12; ++i)
      heights.push_back (0.3 * std::sin (0.7 * i) * std::cos (0.5 * j));
  checkHitsOnSurface (HeightField (-3.0, -2.0, 0.5, 12, 10, heights), 4000, 1e-9);
}

TEST (SimulationPrimitives, PolygonHolesAndCutSphere)
{
  PlanarPolygon wall (Vec3::Zero(),
                      Vec3::UnitX(),
                      Vec3::UnitZ(),
                      {{Vec2 (0, 0), Vec2 (4, 0), Vec2 (4, 3), Vec2 (0, 3)},
                       {Vec2 (1, 1), Vec2 (2, 1), Vec2 (2, 2), Vec2 (1, 2)}});
  double t;
  Vec3 n;
  // Through the window hole: no hit; beside it: hit at y = 0.
  EXPECT_FALSE (wall.intersect ({Vec3 (1.5, -5, 1.5), Vec3::UnitY()}, 0, 100, t, n));
  ASSERT_TRUE (wall.intersect ({Vec3 (3.0, -5, 1.5), Vec3::UnitY()}, 0, 100, t, n));
  EXPECT_NEAR (t, 5.0, 1e-12);
  // A sphere cut open towards -y: a ray along +y enters through the opening and hits
  // the back.
  Sphere cut (Vec3::Zero(), 1.0, -Vec3::UnitY(), 0.5);
  ASSERT_TRUE (cut.intersect ({Vec3 (0, -5, 0), Vec3::UnitY()}, 0, 100, t, n));
  EXPECT_NEAR (t, 6.0, 1e-12);
}
