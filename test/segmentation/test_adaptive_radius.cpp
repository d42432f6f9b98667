/*
 * Tests of the adaptive radius of Lim & Suter's super-voxels (section 3.1, eq. 1-4):
 * the parameters, the noise constant, the estimator.
 */
#include "../features/crf_test_clouds.h"

#include <pcl_ext/segmentation/adaptive_radius.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

using pcl_ext::AdaptiveRadiusEstimator;
using pcl_ext::AdaptiveRadiusParameters;

namespace {
/** A flat 4 x 4 m grid at z = 0, spacing 0.1 m: 41 x 41 points, point i * 41 + j at
 * (0.1 i, 0.1 j, 0). */
pcl::PointCloud<pcl::PointXYZ>::Ptr
flatGrid ()
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j)
      cloud->push_back (pcl::PointXYZ (0.1f * i, 0.1f * j, 0.f));
  return cloud;
}

constexpr pcl::index_t kCentre = 20 * 41 + 20; // (2, 2, 0)
} // namespace

TEST (AdaptiveRadius, ParametersAreChecked)
{
  EXPECT_TRUE (pcl_ext::checkAdaptiveRadiusParameters ({}, "test"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 11; ++k) {
    AdaptiveRadiusParameters p;
    if (k == 0)
      p.initial_k = 2;
    if (k == 1)
      p.damping = 0.0;
    if (k == 2)
      p.damping = 1.5;
    if (k == 3)
      p.max_iterations = 0;
    if (k == 4)
      p.max_k = p.initial_k;
    if (k == 5)
      p.noise = -0.01;
    if (k == 6)
      p.c1 = 0.0;
    if (k == 7)
      p.epsilon = nan;
    if (k == 8)
      p.colour_weight = -1.0;
    if (k == 9)
      p.min_radius = 1.0, p.max_radius = 1.0;
    if (k == 10)
      p.saturation = nan;
    EXPECT_FALSE (pcl_ext::checkAdaptiveRadiusParameters (p, "test")) << "case " << k;
  }
  AdaptiveRadiusParameters edge;
  edge.damping = 1.0;
  edge.epsilon = 1.0;
  edge.c2 = 0.0;
  EXPECT_TRUE (pcl_ext::checkAdaptiveRadiusParameters (edge, "test"));
}

TEST (AdaptiveRadius, NoiseOfATwoLayerPatchIsItsHalfThickness)
{
  // A 10 x 10 checkerboard of points 1 cm above and below z = 0: the fitted plane is z
  // = 0 and every point lies 1 cm from it.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<pcl::index_t> patch;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      patch.push_back (static_cast<pcl::index_t> (cloud.size()));
      cloud.push_back (
          pcl::PointXYZ (0.1f * i, 0.1f * j, (i + j) % 2 ? 0.01f : -0.01f));
    }
  EXPECT_NEAR (pcl_ext::estimateNoiseFromPlanarPatch (cloud, patch), 0.01, 1e-7);
  // Non-finite points are left out; fewer than three finite ones give NaN.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back (pcl::PointXYZ (nan, nan, nan));
  patch.push_back (static_cast<pcl::index_t> (cloud.size() - 1));
  EXPECT_NEAR (pcl_ext::estimateNoiseFromPlanarPatch (cloud, patch), 0.01, 1e-7);
  EXPECT_TRUE (std::isnan (pcl_ext::estimateNoiseFromPlanarPatch (
      cloud, {0, 1, static_cast<pcl::index_t> (cloud.size() - 1)})));
}

TEST (AdaptiveRadius, FlatGridGrowsToTheKThreshold)
{
  // On a plane eq. 2 gives no curvature, so the first step already passes the k
  // threshold and the radius is the one holding max_k points at the density of the
  // first 15 neighbours: 15 points within sqrt(0.05) (the 15th nearest on a 0.1 grid),
  // pi r^2 rho = 60 at r^2 = 60 / 15 * 0.05 = 0.2.
  const auto cloud = flatGrid();
  AdaptiveRadiusParameters p;
  p.noise = 0.005;
  AdaptiveRadiusEstimator est;
  ASSERT_TRUE (est.initialize (cloud, {}, p));
  EXPECT_EQ (est.getNoise(), 0.005);
  EXPECT_EQ (est.cloud().get(), cloud.get());
  int steps = 0;
  EXPECT_NEAR (est.estimate (kCentre, &steps), std::sqrt (0.2), 1e-4);
  EXPECT_EQ (steps, 1);
  // The bounds: a maximum below that radius holds it there (two steps: the second finds
  // the count it predicted), a minimum above it raises it.
  p.max_radius = 0.3;
  ASSERT_TRUE (est.initialize (cloud, {}, p));
  EXPECT_NEAR (est.estimate (kCentre, &steps), 0.3, 1e-6);
  EXPECT_EQ (steps, 2);
  p.max_radius = std::numeric_limits<double>::infinity();
  p.min_radius = 0.6;
  ASSERT_TRUE (est.initialize (cloud, {}, p));
  EXPECT_NEAR (est.estimate (kCentre), 0.6, 1e-6);
}

TEST (AdaptiveRadius, NeighboursAndNearest)
{
  const auto cloud = flatGrid();
  AdaptiveRadiusParameters p;
  p.noise = 0.005;
  AdaptiveRadiusEstimator est;
  ASSERT_TRUE (est.initialize (cloud, {}, p));
  pcl::Indices nn;
  est.neighbours (kCentre, 0.1001f, nn);
  ASSERT_EQ (nn.size(), 5u); // the point and its four grid neighbours
  EXPECT_EQ (nn[0], kCentre);
  est.nearest (Eigen::Vector3f (2.01f, 2.02f, 0.5f), 1, nn);
  ASSERT_EQ (nn.size(), 1u);
  EXPECT_EQ (nn[0], kCentre);
  est.nearest (Eigen::Vector3f::Zero(), 100000, nn);
  EXPECT_EQ (nn.size(), cloud->size());
  EXPECT_EQ (nn[0], 0);
}

TEST (AdaptiveRadius, InitializeRefusesTooFewPointsAndBadColours)
{
  AdaptiveRadiusEstimator est;
  const AdaptiveRadiusParameters p; // initial_k 15
  EXPECT_FALSE (est.initialize (nullptr, {}, p));
  auto few = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i < 20; ++i)
    few->push_back (pcl::PointXYZ (0.1f * i, 0.f, 0.f));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 6; ++i)
    (*few)[i].x = nan; // 14 finite points left
  EXPECT_FALSE (est.initialize (few, {}, p));
  EXPECT_FALSE (est.initialize (flatGrid(), {Eigen::Vector3f::Ones()}, p));
  AdaptiveRadiusParameters bad;
  bad.damping = 0.0;
  EXPECT_FALSE (est.initialize (flatGrid(), {}, bad));
}

TEST (AdaptiveSupervoxels, NoiseFromAPlanarPatch)
{
  // The mean distance to the plane of Gaussian noise sigma is sigma sqrt(2 / pi).
  const auto cloud = crf_test::floorAndWall (0.02, 0.01);
  std::vector<pcl::index_t> floor;
  for (std::size_t i = 0; i < cloud->size(); ++i)
    if ((*cloud)[i].x > 0.5f)
      floor.push_back (static_cast<pcl::index_t> (i));
  const double sigma = pcl_ext::estimateNoiseFromPlanarPatch (*cloud, floor);
  EXPECT_NEAR (sigma, 0.01 * std::sqrt (2.0 / M_PI), 0.0005);
  EXPECT_TRUE (std::isnan (pcl_ext::estimateNoiseFromPlanarPatch (*cloud, {0, 1})));
  // The automatic estimate finds the same order of noise on the two planes.
  pcl_ext::AdaptiveRadiusEstimator est;
  ASSERT_TRUE (est.initialize (cloud, {}, pcl_ext::AdaptiveRadiusParameters()));
  EXPECT_GT (est.getNoise(), 0.005);
  EXPECT_LT (est.getNoise(), 0.015);
}

TEST (AdaptiveRadius, TheNoiseSampleOfACloudIsThatOfItsPartsMerged)
{
  // The sample is the points of smallest key, so the sample of the whole cloud is the
  // smallest keys of the parts' samples (each part read with a margin, so that its own
  // points' neighbourhoods are the whole cloud's): the same noise constant, exactly.
  const auto cloud = crf_test::floorAndWall (0.05, 0.003);
  AdaptiveRadiusParameters p;
  AdaptiveRadiusEstimator whole;
  ASSERT_TRUE (whole.initialize (cloud, {}, p));
  const double sigma = whole.getNoise();
  // The flattest tenth of the neighbourhoods puts it below the noise, but not far.
  EXPECT_GT (sigma, 0.0015);
  EXPECT_LT (sigma, 0.003);
  EXPECT_EQ (whole.selectNoiseSamplePoints().size(), pcl_ext::kNoiseSamples);

  std::vector<std::pair<std::uint64_t, pcl_ext::NoiseSample>> merged;
  for (const bool left : {true, false}) {
    auto part = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    std::vector<char> own;
    for (const auto& q : *cloud)
      if (left ? q.y < 2.5f : q.y >= 1.5f) {
        part->push_back (q);
        own.push_back (left ? q.y < 2.f : q.y >= 2.f);
      }
    AdaptiveRadiusParameters given = p;
    given.noise = 1.0; // the part must not estimate its own
    AdaptiveRadiusEstimator estimator;
    ASSERT_TRUE (estimator.initialize (part, {}, given));
    for (const auto i : estimator.selectNoiseSamplePoints (&own)) {
      EXPECT_TRUE (own[static_cast<std::size_t> (i)]);
      pcl_ext::NoiseSample s;
      if (estimator.measureNoiseSample (i, s))
        merged.emplace_back (
            pcl_ext::noiseSampleKey ((*part)[static_cast<std::size_t> (i)]), s);
    }
  }
  std::sort (merged.begin(), merged.end(), [] (const auto& a, const auto& b) {
    return a.first < b.first;
  });
  std::vector<pcl_ext::NoiseSample> samples;
  for (std::size_t i = 0; i < pcl_ext::kNoiseSamples; ++i)
    samples.push_back (merged[i].second);
  EXPECT_EQ (pcl_ext::noiseFromSamples (samples), sigma);
  EXPECT_EQ (pcl_ext::noiseFromSamples ({}), 0.0);
}
