/*
 * Tests of the cloud statistics and the configuration chosen from them
 * (profiles::estimateCloudStatistics, profiles::chooseConfiguration).
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/profile_auto.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

using namespace pcl_ext::profiles;

namespace {
/** Gaussian by Box-Muller from the project's random numbers (the same on every
 * standard library). */
double
gaussian (pcl_ext::RandomStream& random)
{
  const double u = 1.0 - random.uniform(), v = random.uniform();
  return std::sqrt (-2.0 * std::log (u)) * std::cos (2.0 * M_PI * v);
}

/** A square grid of \a n x \a n points of step \a step on a tilted plane, at \a
 * origin, with Gaussian noise of \a sigma along the plane's normal. */
void
addPlane (std::vector<Eigen::Vector3f>& xyz,
          int n,
          double step,
          double sigma,
          const Eigen::Vector3d& origin,
          std::uint64_t seed)
{
  const Eigen::Matrix3d r = (Eigen::AngleAxisd (0.4, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd (0.7, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  pcl_ext::RandomStream random (seed);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d p (step * i, step * j, sigma * gaussian (random));
      xyz.push_back ((origin + r * p).cast<float>());
    }
}
} // namespace

TEST (ProfileAuto, PlaneGivesItsSpacingAndNoise)
{
  // Square grid of step 0.02: spacing sqrt(pi 2 s^2 / 6) = 1.023 s (the 6th neighbour
  // at s sqrt(2)); noise 4 mm across the plane.
  std::vector<Eigen::Vector3f> xyz;
  addPlane (xyz, 150, 0.02, 0.004, Eigen::Vector3d (1.0, 2.0, 0.5), 7);
  const CloudStatistics s = estimateCloudStatistics (xyz);
  EXPECT_GT (s.samples, 1900u);
  EXPECT_NEAR (s.spacing, 0.02 * std::sqrt (M_PI / 3.0), 0.002);
  EXPECT_NEAR (s.noise, 0.004, 0.0006);
  EXPECT_LT (s.spacing_variation, 1.5);

  // Without noise: none measured.
  std::vector<Eigen::Vector3f> clean;
  addPlane (clean, 150, 0.02, 0.0, Eigen::Vector3d::Zero(), 7);
  const CloudStatistics c = estimateCloudStatistics (clean);
  EXPECT_NEAR (c.spacing, 0.02 * std::sqrt (M_PI / 3.0), 5e-4);
  EXPECT_LT (c.noise, 1e-5);
}

TEST (ProfileAuto, DensityVariationIsTheRatioOfSparseToDense)
{
  // As many points at step 0.01 as at step 0.05, apart: the spacing varies by 5.
  std::vector<Eigen::Vector3f> xyz;
  addPlane (xyz, 100, 0.01, 0.0005, Eigen::Vector3d::Zero(), 1);
  addPlane (xyz, 100, 0.05, 0.0005, Eigen::Vector3d (20.0, 0.0, 0.0), 2);
  const CloudStatistics s = estimateCloudStatistics (xyz);
  EXPECT_NEAR (s.spacing_variation, 5.0, 0.5);
  EXPECT_GT (s.spacing_variation, kAutoLocalThresholdVariation);
}

TEST (ProfileAuto, TooFewPointsGiveNothing)
{
  const CloudStatistics s = estimateCloudStatistics (
      std::vector<Eigen::Vector3f> (10, Eigen::Vector3f::Ones()));
  EXPECT_EQ (s.samples, 0u);
  EXPECT_EQ (s.spacing, 0.0);
  EXPECT_FALSE (chooseConfiguration (s, 1.0).curve_fitting);
}

TEST (ProfileAuto, ConfigurationFollowsTheStatistics)
{
  CloudStatistics s;
  s.spacing = 0.02;
  s.noise = 0.004;
  s.spacing_variation = 2.0;
  // Objects apart: proximity chaining, the paper's default.
  const AutoConfiguration apart = chooseConfiguration (s, 0.2);
  EXPECT_FALSE (apart.curve_fitting);
  EXPECT_FALSE (apart.join_cylinders);
  EXPECT_FALSE (apart.local_threshold);
  // Touching surfaces: curve fitting, for noisy scans at 0.2 spacings of noise.
  const AutoConfiguration touching = chooseConfiguration (s, 0.8);
  EXPECT_TRUE (touching.curve_fitting);
  EXPECT_TRUE (touching.noisy);
  EXPECT_TRUE (touching.side_frames);
  EXPECT_TRUE (touching.join_cylinders);
  // A clean scan keeps the paper's curve fitting; a varying density local thresholds.
  s.noise = 0.0005;
  s.spacing_variation = 5.0;
  const AutoConfiguration clean = chooseConfiguration (s, 0.8);
  EXPECT_TRUE (clean.curve_fitting);
  EXPECT_FALSE (clean.noisy);
  EXPECT_TRUE (clean.local_threshold);
  EXPECT_FALSE (describeConfiguration (s, 0.8, clean).empty());
}
