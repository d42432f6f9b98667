/*
 * Tests of the simulator's analytic primitives, curves and polynomial solver.
 */
#include <pcl_ext/simulation/primitives.h>
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/scene_geometry.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_ext::simulation;

namespace
{
// Casts rays from random origins towards random points of the primitive's box; every hit must
// lie on the surface, and the hit count must be substantial.
void
checkHitsOnSurface (const Primitive& primitive, int rays, double tolerance)
{
  RandomStream rng (42);
  const Aabb box = primitive.bounds ();
  int hits = 0;
  for (int k = 0; k < rays; ++k)
  {
    const Vec3 target = box.min + (box.max - box.min).cwiseProduct (
                                      Vec3 (rng.uniform (), rng.uniform (), rng.uniform ()));
    const Vec3 origin = box.centre () + 10.0 * Vec3 (rng.gaussian (), rng.gaussian (), rng.gaussian ());
    Ray ray{origin, (target - origin).normalized ()};
    double t;
    Vec3 n;
    if (!primitive.intersect (ray, 0.0, 1e9, t, n))
      continue;
    ++hits;
    const Vec3 p = origin + t * ray.direction;
    EXPECT_NEAR (primitive.implicit (p), 0.0, tolerance);
    EXPECT_NEAR (n.norm (), 1.0, 1e-9);
  }
  EXPECT_GT (hits, rays / 10);
}
}  // namespace

TEST (SimulationPolynomial, QuarticRoots)
{
  // (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10 t^3 + 35 t^2 - 50 t + 24
  const double c[5] = {24, -50, 35, -10, 1};
  double roots[4];
  ASSERT_EQ (solvePolynomial (c, 4, 0.0, 10.0, roots), 4);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR (roots[i], i + 1.0, 1e-12);
  EXPECT_EQ (solvePolynomial (c, 4, 1.5, 2.5, roots), 1);
  EXPECT_NEAR (roots[0], 2.0, 1e-12);
  const double none[5] = {1, 0, 1, 0, 1};  // t^4 + t^2 + 1 > 0
  EXPECT_EQ (solvePolynomial (none, 4, -10.0, 10.0, roots), 0);
}

TEST (SimulationPrimitives, HitsLieOnTheSurface)
{
  checkHitsOnSurface (PlanarPolygon (Vec3 (1, 2, 3), Vec3::UnitX (), Vec3 (0, 1, 1).normalized (),
                                     {{Vec2 (0, 0), Vec2 (2, 0), Vec2 (2, 2), Vec2 (0, 2)},
                                      {Vec2 (0.5, 0.5), Vec2 (1.5, 0.5), Vec2 (1.5, 1.5), Vec2 (0.5, 1.5)}}),
                      2000, 1e-9);
  checkHitsOnSurface (Annulus (Vec3 (0, 0, 1), Vec3 (1, 1, 0), 0.2, 0.5), 2000, 1e-9);
  checkHitsOnSurface (ConeFrustum (Vec3 (0, 0, 0), Vec3 (0, 1, 1), 2.0, 0.5, 0.2), 2000, 1e-9);
  checkHitsOnSurface (Sphere (Vec3 (1, 1, 1), 0.7, Vec3::UnitZ (), 0.3), 2000, 1e-9);
  checkHitsOnSurface (Ellipsoid (Vec3 (0, 0, 2), Eigen::Matrix3d::Identity (), Vec3 (1.0, 0.5, 0.3)),
                      2000, 1e-9);
  checkHitsOnSurface (TorusSection (Vec3 (0, 0, 0), Vec3::UnitY (), Vec3::UnitZ (), 0.5, 0.1,
                                    1.5707963267948966),
                      4000, 1e-7);
  std::vector<double> heights;
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 12; ++i)
      heights.push_back (0.3 * std::sin (0.7 * i) * std::cos (0.5 * j));
  checkHitsOnSurface (HeightField (-3.0, -2.0, 0.5, 12, 10, heights), 4000, 1e-9);
}

TEST (SimulationPrimitives, PolygonHolesAndCutSphere)
{
  PlanarPolygon wall (Vec3::Zero (), Vec3::UnitX (), Vec3::UnitZ (),
                      {{Vec2 (0, 0), Vec2 (4, 0), Vec2 (4, 3), Vec2 (0, 3)},
                       {Vec2 (1, 1), Vec2 (2, 1), Vec2 (2, 2), Vec2 (1, 2)}});
  double t;
  Vec3 n;
  // Through the window hole: no hit; beside it: hit at y = 0.
  EXPECT_FALSE (wall.intersect ({Vec3 (1.5, -5, 1.5), Vec3::UnitY ()}, 0, 100, t, n));
  ASSERT_TRUE (wall.intersect ({Vec3 (3.0, -5, 1.5), Vec3::UnitY ()}, 0, 100, t, n));
  EXPECT_NEAR (t, 5.0, 1e-12);
  // A sphere cut open towards -y: a ray along +y enters through the opening and hits the back.
  Sphere cut (Vec3::Zero (), 1.0, -Vec3::UnitY (), 0.5);
  ASSERT_TRUE (cut.intersect ({Vec3 (0, -5, 0), Vec3::UnitY ()}, 0, 100, t, n));
  EXPECT_NEAR (t, 6.0, 1e-12);
}

TEST (SimulationCurves, Distances)
{
  GroundTruthCurve line;
  line.a = Vec3 (0, 0, 0);
  line.b = Vec3 (2, 0, 0);
  EXPECT_NEAR (line.distance (Vec3 (1, 3, 4)), 5.0, 1e-12);
  EXPECT_NEAR (line.distance (Vec3 (-3, 4, 0)), 5.0, 1e-12);
  GroundTruthCurve circle;
  circle.shape = GroundTruthCurve::Shape::Circle;
  circle.a = Vec3 (0, 0, 1);
  circle.b = Vec3::UnitZ ();
  circle.radius = 2.0;
  EXPECT_NEAR (circle.distance (Vec3 (5, 0, 5)), 5.0, 1e-12);
  EXPECT_NEAR (circle.distance (Vec3 (0, 0, 1)), 2.0, 1e-12);
}

TEST (SimulationGeometry, BvhMatchesBruteForce)
{
  SceneGeometry geometry;
  RandomStream rng (7);
  for (int k = 0; k < 300; ++k)
  {
    const Vec3 c (20 * rng.uniform (), 20 * rng.uniform (), 5 * rng.uniform ());
    auto sphere = std::make_shared<Sphere> (c, 0.2 + 0.5 * rng.uniform ());
    sphere->info.segment = static_cast<std::uint32_t> (k + 1);
    if (k % 5 == 0)
      sphere->porosity = 0.5;
    geometry.addPrimitive (sphere);
  }
  geometry.build ();
  for (int r = 0; r < 5000; ++r)
  {
    Ray ray{Vec3 (10, 10, 2.5) + Vec3 (rng.gaussian (), rng.gaussian (), rng.gaussian ()),
            Vec3 (rng.gaussian (), rng.gaussian (), rng.gaussian ()).normalized ()};
    RayHit a, b;
    const bool ha = geometry.intersect (ray, 50.0, r, a);
    const bool hb = geometry.intersectBruteForce (ray, 50.0, r, b);
    ASSERT_EQ (ha, hb);
    if (ha)
    {
      EXPECT_EQ (a.primitive, b.primitive);
      EXPECT_DOUBLE_EQ (a.t, b.t);
    }
  }
}

TEST (SimulationRandom, GaussianMoments)
{
  RandomStream rng (123);
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i)
  {
    const double g = rng.gaussian ();
    sum += g;
    sum2 += g * g;
  }
  EXPECT_NEAR (sum / n, 0.0, 0.01);
  EXPECT_NEAR (sum2 / n, 1.0, 0.01);
}
