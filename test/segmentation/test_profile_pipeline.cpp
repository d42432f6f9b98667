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

TEST (ProfilePipeline, APartWithTheCloudsOriginsHasTheCloudsEdges)
{
  // The slabs of stack 0 split in two at a profile border: each part, given the whole
  // cloud's origin, has the whole cloud's edges among its points.
  std::vector<Eigen::Vector3f> xyz = twoPlates();
  for (const auto method : {ProfileMethod::Proximity,
                            ProfileMethod::MinimumSpanningTree,
                            ProfileMethod::CurveReconstruction}) {
    PipelineParameters whole_parameters = parameters (method);
    whole_parameters.normals.resize (1);
    PipelineResult whole;
    ASSERT_TRUE (runProfileSegmentation (xyz, whole_parameters, whole));
    const Stack& stack = whole.stacks[0];
    const std::uint32_t border = static_cast<std::uint32_t> (stack.numProfiles() / 2);
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected[2], got[2];
    for (const auto& e : whole.edges[0])
      expected[stack.profile_of_point[e.source] >= border].insert (
          {e.source, e.target});
    for (int part = 0; part < 2; ++part) {
      std::vector<Eigen::Vector3f> points;
      std::vector<std::uint32_t> index;
      for (std::uint32_t i = 0; i < xyz.size(); ++i)
        if ((stack.profile_of_point[i] >= border) == (part == 1)) {
          points.push_back (xyz[i]);
          index.push_back (i);
        }
      PipelineParameters p = whole_parameters;
      p.origins = {stack.origin};
      PipelineResult result;
      ASSERT_TRUE (runProfileSegmentation (points, p, result));
      EXPECT_EQ (result.stacks[0].origin, stack.origin);
      for (const auto& e : result.edges[0])
        got[part].insert ({index[e.source], index[e.target]});
      EXPECT_FALSE (got[part].empty());
      EXPECT_EQ (got[part], expected[part]) << "part " << part;
    }
    // Without the origin the upper part's profiles start at its own lowest point.
    PipelineResult own;
    std::vector<Eigen::Vector3f> upper;
    for (std::uint32_t i = 0; i < xyz.size(); ++i)
      if (stack.profile_of_point[i] >= border)
        upper.push_back (xyz[i]);
    ASSERT_TRUE (runProfileSegmentation (upper, whole_parameters, own));
    EXPECT_GT (own.stacks[0].origin, stack.origin);
  }
}

TEST (ProfilePipeline, OriginsThatDoNotFitAreRefused)
{
  const auto xyz = twoPlates();
  PipelineParameters p = parameters (ProfileMethod::Proximity);
  PipelineResult result;
  p.origins = {0.0, 0.0}; // not one per stack
  EXPECT_FALSE (runProfileSegmentation (xyz, p, result));
  p.origins.assign (4, std::nan (""));
  EXPECT_FALSE (runProfileSegmentation (xyz, p, result));
  // Above the lowest point of the cloud: a point would fall below profile 0.
  p.origins.assign (4, 0.1);
  EXPECT_FALSE (runProfileSegmentation (xyz, p, result));
  EXPECT_TRUE (result.stacks.empty());
  p.origins.assign (4, -1.0);
  ASSERT_TRUE (runProfileSegmentation (xyz, p, result));
  EXPECT_EQ (result.num_segments, 2u);
}
