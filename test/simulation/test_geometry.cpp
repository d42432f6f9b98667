/*
 * Tests of the simulator's geometry helpers: boxes and the ray slab test, ground-truth
 * curves, the polynomial solver, orthonormal frames.
 */
#include <pcl_ext/simulation/geometry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace pcl_ext::simulation;

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
  const double none[5] = {1, 0, 1, 0, 1}; // t^4 + t^2 + 1 > 0
  EXPECT_EQ (solvePolynomial (none, 4, -10.0, 10.0, roots), 0);
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
  circle.b = Vec3::UnitZ();
  circle.radius = 2.0;
  EXPECT_NEAR (circle.distance (Vec3 (5, 0, 5)), 5.0, 1e-12);
  EXPECT_NEAR (circle.distance (Vec3 (0, 0, 1)), 2.0, 1e-12);
}

TEST (SimulationPolynomial, LowDegreesAndRangeLimits)
{
  double roots[4];
  const double line[2] = {-1, 2}; // 2 t - 1
  ASSERT_EQ (solvePolynomial (line, 1, -10.0, 10.0, roots), 1);
  EXPECT_NEAR (roots[0], 0.5, 1e-12);
  const double square[3] = {-2, 0, 1}; // t^2 - 2
  ASSERT_EQ (solvePolynomial (square, 2, -10.0, 10.0, roots), 2);
  EXPECT_NEAR (roots[0], -std::sqrt (2.0), 1e-12);
  EXPECT_NEAR (roots[1], std::sqrt (2.0), 1e-12);
  ASSERT_EQ (solvePolynomial (square, 2, 0.0, 10.0, roots), 1);
  EXPECT_NEAR (roots[0], std::sqrt (2.0), 1e-12);
  EXPECT_EQ (solvePolynomial (square, 2, 2.0, 10.0, roots), 0);
}

TEST (SimulationAabb, ExtendGrowAndClipARay)
{
  Aabb box;
  EXPECT_TRUE (box.empty());
  box.extend (Vec3 (0, 0, 0));
  EXPECT_FALSE (box.empty());
  box.extend (Vec3 (1, 2, 3));
  EXPECT_EQ (box.min, Vec3 (0, 0, 0));
  EXPECT_EQ (box.max, Vec3 (1, 2, 3));
  EXPECT_EQ (box.centre(), Vec3 (0.5, 1, 1.5));
  const Aabb grown = box.grown (0.5);
  EXPECT_EQ (grown.min, Vec3 (-0.5, -0.5, -0.5));
  EXPECT_EQ (grown.max, Vec3 (1.5, 2.5, 3.5));
  Aabb other;
  other.extend (Vec3 (-1, 5, 1));
  box.extend (other);
  EXPECT_EQ (box.min, Vec3 (-1, 0, 0));
  EXPECT_EQ (box.max, Vec3 (1, 5, 3));

  // The unit cube against rays along +x: through it the interval is clipped to [5, 6].
  Aabb cube;
  cube.extend (Vec3 (0, 0, 0));
  cube.extend (Vec3 (1, 1, 1));
  const double inf = std::numeric_limits<double>::infinity();
  const Vec3 inv_x (1.0, inf, inf);
  double t0 = 0.0, t1 = 100.0;
  ASSERT_TRUE (cube.clip (Vec3 (-5, 0.5, 0.5), inv_x, t0, t1));
  EXPECT_DOUBLE_EQ (t0, 5.0);
  EXPECT_DOUBLE_EQ (t1, 6.0);
  t0 = 0.0, t1 = 100.0;
  EXPECT_FALSE (cube.clip (Vec3 (-5, 2, 0.5), inv_x, t0, t1)); // passes beside it
  t0 = 0.0, t1 = 5.5;
  ASSERT_TRUE (cube.clip (Vec3 (-5, 0.5, 0.5), inv_x, t0, t1)); // ends inside it
  EXPECT_DOUBLE_EQ (t1, 5.5);
  t0 = 0.0, t1 = 4.0;
  EXPECT_FALSE (cube.clip (Vec3 (-5, 0.5, 0.5), inv_x, t0, t1)); // ends before it
  // A ray in the plane of a face (0 * inf is NaN there) still hits.
  t0 = 0.0, t1 = 100.0;
  EXPECT_TRUE (cube.clip (Vec3 (-5, 1, 0.5), inv_x, t0, t1));
  EXPECT_DOUBLE_EQ (t0, 5.0);
}

TEST (SimulationCurves, BoundsOfSegmentsAndCircles)
{
  GroundTruthCurve line;
  line.a = Vec3 (2, -1, 0);
  line.b = Vec3 (0, 3, 1);
  const Aabb l = line.bounds();
  EXPECT_EQ (l.min, Vec3 (0, -1, 0));
  EXPECT_EQ (l.max, Vec3 (2, 3, 1));
  // A horizontal circle of radius 2 at height 1: flat along z.
  GroundTruthCurve circle;
  circle.shape = GroundTruthCurve::Shape::Circle;
  circle.a = Vec3 (0, 0, 1);
  circle.b = Vec3::UnitZ();
  circle.radius = 2.0;
  const Aabb c = circle.bounds();
  EXPECT_EQ (c.min, Vec3 (-2, -2, 1));
  EXPECT_EQ (c.max, Vec3 (2, 2, 1));
  // Every point of a tilted circle lies in its box.
  circle.b = Vec3 (1, 1, 1).normalized();
  const Aabb t = circle.bounds();
  Vec3 u, v;
  orthonormalFrame (circle.b, u, v);
  for (int k = 0; k < 360; ++k) {
    const Vec3 p = circle.a + 2.0 * (std::cos (k * M_PI / 180) * u +
                                     std::sin (k * M_PI / 180) * v);
    EXPECT_TRUE ((p.array() >= t.min.array() - 1e-12).all() &&
                 (p.array() <= t.max.array() + 1e-12).all())
        << k;
    EXPECT_NEAR (circle.distance (p), 0.0, 1e-12) << k;
  }
}

TEST (SimulationGeometry, OrthonormalFramesAreRightHanded)
{
  const std::vector<Vec3> normals = {Vec3 (0, 0, 1),
                                     Vec3 (1, 0, 0),
                                     Vec3 (0, 0, -1),
                                     Vec3 (1, 2, 3).normalized(),
                                     Vec3 (0.1, 0, 0.995).normalized()};
  for (const Vec3& n : normals) {
    Vec3 u, v;
    orthonormalFrame (n, u, v);
    EXPECT_NEAR (u.norm(), 1.0, 1e-12);
    EXPECT_NEAR (v.norm(), 1.0, 1e-12);
    EXPECT_NEAR (u.dot (n), 0.0, 1e-12);
    EXPECT_NEAR (v.dot (n), 0.0, 1e-12);
    EXPECT_NEAR (u.dot (v), 0.0, 1e-12);
    EXPECT_NEAR ((u.cross (v) - n).norm(), 0.0, 1e-12);
  }
}
