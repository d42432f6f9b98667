/*
 * Tests of SceneGeometry: ray casting through its BVH.
 */
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/scene_geometry.h>

#include <gtest/gtest.h>

#include <memory>

using namespace pcl_ext::simulation;

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
