/*
 * Tests of the simulator's counter-based random numbers: Gaussian deviates.
 */
#include <pcl_ext/simulation/random.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_ext::simulation;

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
