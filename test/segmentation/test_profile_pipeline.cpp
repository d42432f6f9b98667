/*
 * Tests of the profile-intersection segmentation on plain coordinates (Sithole &
 * Mapurisa): stacks, edges and segments of runProfileSegmentation, and its refusals.
 */
#include <pcl_ext/segmentation/profile_pipeline.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

using namespace pcl_ext::profiles;

namespace {
constexpr double kSpacing = 0.02;

/** Two horizontal 0.6 m squares on a 2 cm grid, one at z = 0 and one 0.5 m above it:
 * the first 900 points are the lower square. */
std::vector<Eigen::Vector3f>
twoPlates ()
{
  std::vector<Eigen::Vector3f> xyz;
  for (const float z : {0.f, 0.5f})
    for (int i = 0; i < 30; ++i)
      for (int j = 0; j < 30; ++j)
        xyz.emplace_back (
            static_cast<float> (kSpacing * i), static_cast<float> (kSpacing * j), z);
  return xyz;
}

/** The automatic settings of ProfileSegmentation for this spacing: width 1.5 and
 * threshold 3 spacings, four stacks spread over the hemisphere. */
PipelineParameters
parameters (ProfileMethod method)
{
  PipelineParameters p;
  p.normals = makeStackNormals (4, StackDistribution::Hemisphere);
  p.width = 1.5 * kSpacing;
  p.threshold = 3.0 * kSpacing;
  p.method = method;
  return p;
}
} // namespace

TEST (ProfilePipeline, TwoPlatesAreTwoSegments)
{
  const auto xyz = twoPlates();
  for (const auto method :
       {ProfileMethod::Proximity, ProfileMethod::MinimumSpanningTree}) {
    PipelineResult result;
    ASSERT_TRUE (runProfileSegmentation (xyz, parameters (method), result));
    ASSERT_EQ (result.stacks.size(), 4u);
    ASSERT_EQ (result.edges.size(), 4u);
    ASSERT_EQ (result.labels.size(), xyz.size());
    EXPECT_EQ (result.num_segments, 2u);
    EXPECT_TRUE (
        result.breakpoints.empty() ||
        std::set<std::uint8_t> (result.breakpoints.begin(), result.breakpoints.end()) ==
            std::set<std::uint8_t>{0});
    for (std::size_t i = 0; i < xyz.size(); ++i)
      EXPECT_EQ (result.labels[i], result.labels[i < 900 ? 0 : 900]) << "point " << i;
    EXPECT_NE (result.labels[0], result.labels[900]);
    // Every edge joins two points of one profile: no farther apart than the threshold
    // within the profile plane and the width across it.
    const double reach = std::hypot (3.0 * kSpacing, 1.5 * kSpacing) + 1e-6;
    for (std::size_t s = 0; s < result.edges.size(); ++s) {
      EXPECT_FALSE (result.edges[s].empty());
      EXPECT_EQ (result.stacks[s].order.size(), xyz.size());
      for (const auto& e : result.edges[s]) {
        EXPECT_LE ((xyz[e.source] - xyz[e.target]).norm(), reach);
        EXPECT_EQ (result.stacks[s].profile_of_point[e.source],
                   result.stacks[s].profile_of_point[e.target]);
      }
    }
  }
}

TEST (ProfilePipeline, SameResultForAnyThreadCount)
{
  const auto xyz = twoPlates();
  PipelineParameters p = parameters (ProfileMethod::Proximity);
  PipelineResult one, two;
  ASSERT_TRUE (runProfileSegmentation (xyz, p, one));
  p.threads = 2;
  ASSERT_TRUE (runProfileSegmentation (xyz, p, two));
  EXPECT_EQ (one.labels, two.labels);
  ASSERT_EQ (one.edges.size(), two.edges.size());
  for (std::size_t s = 0; s < one.edges.size(); ++s) {
    ASSERT_EQ (one.edges[s].size(), two.edges[s].size());
    for (std::size_t k = 0; k < one.edges[s].size(); ++k) {
      EXPECT_EQ (one.edges[s][k].source, two.edges[s][k].source);
      EXPECT_EQ (one.edges[s][k].target, two.edges[s][k].target);
    }
  }
}

TEST (ProfilePipeline, InvalidParametersComputeNothing)
{
  const auto xyz = twoPlates();
  PipelineResult result;
  // No points: valid, nothing to label.
  ASSERT_TRUE (
      runProfileSegmentation ({}, parameters (ProfileMethod::Proximity), result));
  EXPECT_EQ (result.num_segments, 0u);
  EXPECT_TRUE (result.labels.empty());
  for (int k = 0; k < 7; ++k) {
    PipelineParameters p = parameters (ProfileMethod::Proximity);
    if (k == 0)
      p.normals.clear();
    if (k == 1)
      p.width = 0.0;
    if (k == 2)
      p.threshold = -1.0;
    if (k == 3)
      p.normals[1] = Eigen::Vector3f::Zero();
    if (k == 4)
      p.threads = 0;
    if (k == 5)
      p.method = ProfileMethod::CurveFitting; // no window, tangent radius or turn
    if (k == 6)
      p.local_threshold = true, p.max_threshold = 0.5 * p.threshold;
    EXPECT_FALSE (runProfileSegmentation (xyz, p, result)) << "case " << k;
    EXPECT_TRUE (result.labels.empty()) << "case " << k;
    EXPECT_TRUE (result.stacks.empty()) << "case " << k;
  }
}
