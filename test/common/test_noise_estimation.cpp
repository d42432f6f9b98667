/*
 * Tests of estimateNoiseAndSpacing on surfaces of known noise and spacing.
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/noise_estimation.h>
#include <pcl_ext/common/random.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// An n x n grid of spacing s, folded along x = fold (0: flat) into a right angle, with
// Gaussian noise of sigma along each face's normal.
Cloud
noisyGrid (int n, double s, double sigma, int fold, unsigned seed)
{
  pcl_ext::RandomStream rng (
      seed); // the project's generator: the same on every library
  Cloud cloud;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double e = sigma * rng.gaussian();
      if (fold > 0 && i >= fold)
        cloud.push_back (pcl::PointXYZ (static_cast<float> (fold * s + e),
                                        static_cast<float> (j * s),
                                        static_cast<float> ((i - fold) * s)));
      else
        cloud.push_back (pcl::PointXYZ (static_cast<float> (i * s),
                                        static_cast<float> (j * s),
                                        static_cast<float> (e)));
    }
  return cloud;
}

// The neighbourhood of each grid point away from the sides: the grid points within 4
// steps (49 points), as a k = 49 search would give on the flat grid.
std::vector<pcl_ext::NeighbourhoodSpread>
gridSpreads (const Cloud& cloud, int n)
{
  std::vector<pcl_ext::NeighbourhoodSpread> spreads;
  for (int i = 4; i < n - 4; ++i)
    for (int j = 4; j < n - 4; ++j) {
      pcl::Indices nn;
      for (int a = -4; a <= 4; ++a)
        for (int b = -4; b <= 4; ++b)
          if (a * a + b * b <= 16)
            nn.push_back ((i + a) * n + j + b);
      Eigen::Matrix3d covariance;
      Eigen::Vector3d centroid;
      pcl_ext::NeighbourhoodSpread spread;
      spread.size = pcl_ext::computeLocalCovariance (cloud, nn, covariance, centroid);
      pcl_ext::EigenDecomposition eigen;
      EXPECT_TRUE (pcl_ext::computeEigenDecomposition (covariance, eigen));
      spread.values = eigen.values;
      spreads.push_back (spread);
    }
  return spreads;
}
} // namespace

TEST (NoiseEstimation, NoisyPlaneGivesItsNoiseAndSpacing)
{
  for (const double sigma : {0.001, 0.003}) {
    const Cloud cloud = noisyGrid (80, 0.01, sigma, 0, 1);
    const auto estimate = pcl_ext::estimateNoiseAndSpacing (gridSpreads (cloud, 80));
    ASSERT_TRUE (estimate.valid) << estimate.reason;
    EXPECT_NEAR (estimate.sigma, sigma, 0.1 * sigma);
    EXPECT_NEAR (estimate.spacing, 0.01, 0.001);
    EXPECT_EQ (estimate.used, 72u * 72u / 2u);
  }
}

TEST (NoiseEstimation, CreaseDoesNotRaiseTheNoise)
{
  // A third of the neighbourhoods reach across the fold; the flattest half do not.
  const double sigma = 0.002;
  const Cloud cloud = noisyGrid (80, 0.01, sigma, 40, 2);
  const auto estimate = pcl_ext::estimateNoiseAndSpacing (gridSpreads (cloud, 80));
  ASSERT_TRUE (estimate.valid) << estimate.reason;
  EXPECT_NEAR (estimate.sigma, sigma, 0.15 * sigma);
  EXPECT_NEAR (estimate.spacing, 0.01, 0.0015);
}

TEST (NoiseEstimation, NoiseFreePlaneGivesZero)
{
  const Cloud cloud = noisyGrid (40, 0.01, 0.0, 0, 3);
  const auto estimate = pcl_ext::estimateNoiseAndSpacing (gridSpreads (cloud, 40));
  ASSERT_TRUE (estimate.valid) << estimate.reason;
  EXPECT_LT (estimate.sigma, 1e-5);
  EXPECT_NEAR (estimate.spacing, 0.01, 0.001);
}

TEST (NoiseEstimation, SaysWhyItCannotEstimate)
{
  // Too few neighbourhoods.
  const Cloud small = noisyGrid (12, 0.01, 0.001, 0, 4);
  auto estimate = pcl_ext::estimateNoiseAndSpacing (gridSpreads (small, 12));
  EXPECT_FALSE (estimate.valid);
  EXPECT_FALSE (estimate.reason.empty());
  EXPECT_TRUE (std::isnan (estimate.sigma));

  // Noise as large as the neighbourhoods: no surface to measure it about.
  const Cloud blob = noisyGrid (40, 0.01, 0.05, 0, 5);
  estimate = pcl_ext::estimateNoiseAndSpacing (gridSpreads (blob, 40));
  EXPECT_FALSE (estimate.valid);
  EXPECT_NE (estimate.reason.find ("not flat"), std::string::npos) << estimate.reason;

  // A bad share.
  EXPECT_FALSE (pcl_ext::estimateNoiseAndSpacing ({}, 0.0).valid);
}
