/*
 * Tests of the simulator's geometry helpers: ground-truth curves and the polynomial solver.
 */
#include <pcl_ext/simulation/geometry.h>

#include <gtest/gtest.h>

#include <cmath>

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
  const double none[5] = {1, 0, 1, 0, 1};  // t^4 + t^2 + 1 > 0
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
  circle.b = Vec3::UnitZ ();
  circle.radius = 2.0;
  EXPECT_NEAR (circle.distance (Vec3 (5, 0, 5)), 5.0, 1e-12);
  EXPECT_NEAR (circle.distance (Vec3 (0, 0, 1)), 2.0, 1e-12);
}
