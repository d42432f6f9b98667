/*
 * Tests of estimateCloudNoise: the noise and spacing of whole clouds of known noise and
 * spacing, georeferenced too, and the clouds it cannot estimate from.
 */
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/random.h>
#include <pcl_ext/search/cloud_noise.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** Two walls meeting at a right angle, each an n x n grid of spacing s with Gaussian
 * noise of sigma along its normal, shifted by (x0, y0). */
Cloud
noisyCorner (int n, double s, double sigma, double x0, double y0)
{
  pcl_ext::RandomStream rng (7);
  Cloud cloud;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      cloud.push_back (pcl::PointXYZ (static_cast<float> (x0 + i * s),
                                      static_cast<float> (y0 + sigma * rng.gaussian()),
                                      static_cast<float> (j * s)));
      cloud.push_back (pcl::PointXYZ (static_cast<float> (x0 + sigma * rng.gaussian()),
                                      static_cast<float> (y0 + (i + 1) * s),
                                      static_cast<float> (j * s)));
    }
  return cloud;
}
} // namespace

TEST (CloudNoise, TwoNoisyWallsGiveTheirNoiseAndSpacing)
{
  // 2 x 160 x 160 points: a sample of twenty thousand of them.
  for (const double sigma : {0.002, 0.005}) {
    const Cloud cloud = noisyCorner (160, 0.02, sigma, 0.0, 0.0);
    const auto estimate = pcl_ext::estimateCloudNoise (cloud, 50, 2);
    ASSERT_TRUE (estimate.valid) << estimate.reason;
    EXPECT_NEAR (estimate.sigma, sigma, 0.15 * sigma);
    EXPECT_NEAR (estimate.spacing, 0.02, 0.002);
    EXPECT_GT (estimate.used, 5000u);
  }
}

TEST (CloudNoise, TheSameOnAnyThreadCountAndFarFromTheOrigin)
{
  const Cloud cloud = noisyCorner (120, 0.02, 0.003, 0.0, 0.0);
  const auto one = pcl_ext::estimateCloudNoise (cloud, 50, 1);
  const auto two = pcl_ext::estimateCloudNoise (cloud, 50, 2);
  ASSERT_TRUE (one.valid) << one.reason;
  EXPECT_EQ (one.sigma, two.sigma);
  EXPECT_EQ (one.spacing, two.spacing);
  // A local frame of a georeferenced scan stays usable: the same walls 500 m out.
  const auto far =
      pcl_ext::estimateCloudNoise (noisyCorner (120, 0.02, 0.003, 500.0, 300.0), 50, 2);
  ASSERT_TRUE (far.valid) << far.reason;
  EXPECT_NEAR (far.sigma, 0.003, 0.0005);
}

TEST (CloudNoise, AStackOfCopiesOfOnePointIsSearchedOnce)
{
  // 100,000 copies of one point beside the walls: all of them are in the sample or
  // none is (the sample is chosen by position); their neighbourhoods have no extent
  // and are not used, so the walls give the estimate.
  const Cloud walls = noisyCorner (120, 0.02, 0.003, 0.0, 0.0);
  // A position whose copies are in the sample: a key among the smallest of the walls'.
  pcl_ext::NoiseSampleCut walls_cut;
  for (const auto& p : walls)
    walls_cut.add (pcl_ext::noiseSampleKeyOf (p.x, p.y, p.z));
  pcl::PointXYZ copy (1.0f, -1.0f, 1.0f);
  while (pcl_ext::noiseSampleKeyOf (copy.x, copy.y, copy.z) >= walls_cut.get() / 2)
    copy.z += 0.25f;
  Cloud cloud = walls;
  for (int i = 0; i < 100000; ++i)
    cloud.push_back (copy);
  const auto estimate = pcl_ext::estimateCloudNoise (cloud, 50, 2);
  ASSERT_TRUE (estimate.valid) << estimate.reason;
  EXPECT_NEAR (estimate.sigma, 0.003, 0.0005);
  // A cloud of copies alone: nothing to estimate from, said so.
  Cloud stack;
  for (int i = 0; i < 100000; ++i)
    stack.push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
  const auto none = pcl_ext::estimateCloudNoise (stack, 50, 2);
  EXPECT_FALSE (none.valid);
  EXPECT_FALSE (none.reason.empty());
}

TEST (CloudNoise, SaysWhyItCannotEstimate)
{
  // Fewer points than k, NaN points aside.
  Cloud small = noisyCorner (3, 0.02, 0.001, 0.0, 0.0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 100; ++i)
    small.push_back (pcl::PointXYZ (nan, nan, nan));
  auto estimate = pcl_ext::estimateCloudNoise (small, 50, 2);
  EXPECT_FALSE (estimate.valid);
  EXPECT_FALSE (estimate.reason.empty());
  // k below 4.
  estimate = pcl_ext::estimateCloudNoise (noisyCorner (20, 0.02, 0.001, 0, 0), 3, 2);
  EXPECT_FALSE (estimate.valid);
  // Noise as large as the neighbourhoods: no surface to measure it about.
  estimate = pcl_ext::estimateCloudNoise (noisyCorner (60, 0.02, 0.2, 0.0, 0.0), 50, 2);
  EXPECT_FALSE (estimate.valid);
  EXPECT_FALSE (estimate.reason.empty());
  // The empty cloud.
  estimate = pcl_ext::estimateCloudNoise (Cloud(), 50, 2);
  EXPECT_FALSE (estimate.valid);
}
