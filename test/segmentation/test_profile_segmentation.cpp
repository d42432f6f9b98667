/*
 * Tests of pcl_ext::ProfileSegmentation on analytic clouds with known segments.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include "profile_test_clouds.h"

#include <pcl/common/point_tests.h>

#include <gtest/gtest.h>

#include <functional>
#include <limits>

using namespace profile_test;
using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

TEST (ProfileSegmentation, SeparatedCubesAreOneSegmentEach)
{
  const LabelledCloud scene = threeCubes();
  Segmentation seg;
  seg.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  ASSERT_EQ (clusters.size(), 3u);
  const auto m = evaluate (clusters, scene);
  EXPECT_DOUBLE_EQ (m.mean_best_iou, 1.0);
  EXPECT_EQ (m.correct, 3u);
  // The automatic lengths follow the grid step (0.02, jittered).
  EXPECT_NEAR (seg.getUsedPointSpacing(), 0.02, 0.004);
  EXPECT_NEAR (seg.getUsedProfileWidth(), 1.5 * seg.getUsedPointSpacing(), 1e-12);
  EXPECT_NEAR (seg.getUsedDistanceThreshold(), 3.0 * seg.getUsedPointSpacing(), 1e-12);
  // The graph: 4 stacks, every edge inside one profile of its stack and within the
  // threshold.
  ASSERT_EQ (seg.getStackEdges().size(), 4u);
  for (std::size_t s = 0; s < 4; ++s) {
    const auto profile = seg.getProfileOfPoints (s);
    ASSERT_EQ (profile.size(), scene.cloud->size());
    EXPECT_GT (seg.getStackEdges()[s].size(), scene.cloud->size() / 2);
    for (const auto& e : seg.getStackEdges()[s]) {
      ASSERT_EQ (profile[e.source], profile[e.target]);
      const Eigen::Vector3f d = (*scene.cloud)[e.source].getVector3fMap() -
                                (*scene.cloud)[e.target].getVector3fMap();
      const Eigen::Vector3f phi = seg.getStackNormals()[s];
      EXPECT_LE ((d - d.dot (phi) * phi).norm(), seg.getUsedDistanceThreshold() + 1e-5);
    }
  }
  const auto coloured = seg.getColoredCloud();
  ASSERT_EQ (coloured->size(), scene.cloud->size());
  EXPECT_NE ((*coloured)[clusters[0].indices[0]].rgba,
             (*coloured)[clusters[1].indices[0]].rgba);
}

namespace {
/** Same segments and profile edges on 1, 2 and 3 threads, for one method and options.
 */
void
expectDeterministic (const LabelledCloud& scene,
                     Segmentation::ProfileMethod method,
                     bool local_threshold,
                     bool side_frames)
{
  std::vector<std::vector<pcl::PointIndices>> results;
  std::vector<std::size_t> edge_counts;
  for (unsigned int threads : {1u, 2u, 3u}) {
    Segmentation seg;
    seg.setInputCloud (scene.cloud);
    seg.setProfileSegmentation (method);
    seg.setLocalThreshold (local_threshold);
    seg.setSideFrames (side_frames);
    seg.setNumberOfThreads (threads);
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    results.push_back (clusters);
    edge_counts.push_back (seg.getStackEdges()[1].size());
  }
  // Curve fitting splits the coarse pipes too, so its splitting code is part of the
  // check.
  if (method == Segmentation::ProfileMethod::CurveFitting)
    EXPECT_GT (results[0].size(), 1u);
  for (std::size_t r = 1; r < results.size(); ++r) {
    EXPECT_EQ (edge_counts[r], edge_counts[0]) << static_cast<int> (method);
    ASSERT_EQ (results[r].size(), results[0].size()) << static_cast<int> (method);
    for (std::size_t c = 0; c < results[0].size(); ++c)
      EXPECT_EQ (results[r][c].indices, results[0][c].indices)
          << static_cast<int> (method);
  }
}
} // namespace

// Two tests rather than one, so that ctest can run them side by side (curve fitting is
// the slow part, and several times slower in the sanitized build).
TEST (ProfileSegmentation, DeterministicForAnyThreadCount)
{
  const LabelledCloud scene = coarseCoaxialPipes();
  expectDeterministic (scene, Segmentation::ProfileMethod::Proximity, false, false);
  expectDeterministic (scene, Segmentation::ProfileMethod::CurveFitting, false, false);
}

// The options not in the paper: local thresholds with proximity and spanning trees,
// side frames with curve fitting.
TEST (ProfileSegmentation, DeterministicForAnyThreadCountWithTheOptions)
{
  const LabelledCloud scene = coarseCoaxialPipes();
  expectDeterministic (scene, Segmentation::ProfileMethod::Proximity, true, false);
  expectDeterministic (
      scene, Segmentation::ProfileMethod::MinimumSpanningTree, true, false);
  expectDeterministic (scene, Segmentation::ProfileMethod::CurveFitting, false, true);
}

TEST (ProfileSegmentation, ProfileWidthAsInFigure6)
{
  // Two parallel plates 0.06 apart (3 spacings), randomly sampled at spacing 0.02.
  LabelledCloud scene;
  std::mt19937 rng (4);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  for (int plate = 0; plate < 2; ++plate)
    for (int k = 0; k < 2500; ++k)
      scene.add (Eigen::Vector3d (u (rng), u (rng), 0.06 * plate), plate + 1);
  const auto segments = [&] (double width) {
    Segmentation seg;
    seg.setInputCloud (scene.cloud);
    seg.setDistanceThreshold (0.03);
    seg.setProfileWidth (width);
    seg.setMinClusterSize (
        5); // random sampling leaves a few stray points along the borders
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    return evaluate (clusters, scene);
  };
  const auto good = segments (0.03);
  EXPECT_EQ (good.correct, 2u);
  EXPECT_GE (good.mean_best_iou, 0.99);
  // Too thin: sparse profiles break apart, over-segmentation (figure 6, top).
  const auto thin = segments (0.005);
  EXPECT_GT (thin.num_predicted_segments, 10u);
  EXPECT_LT (thin.mean_best_iou, good.mean_best_iou);
  // Too wide: the plates fall into the same profiles and merge (figure 6, bottom).
  const auto wide = segments (0.3);
  EXPECT_EQ (wide.num_predicted_segments, 1u);
  EXPECT_EQ (wide.under_segmented, 2u);
}

TEST (ProfileSegmentation, StackOptionsAndMinimumSize)
{
  const LabelledCloud scene = threeCubes();
  Segmentation seg;
  seg.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> clusters;
  seg.setStackDistribution (Segmentation::StackDistribution::HorizontalHalfCircle);
  seg.setNumberOfStacks (3);
  seg.extract (clusters);
  EXPECT_EQ (clusters.size(), 3u);
  for (const auto& n : seg.getStackNormals())
    EXPECT_NEAR (n.z(), 0.0f, 1e-6f);
  seg.setStackNormals ({{0, 0, 2}, {1, 0, 0}, {0, 1, 1}});
  seg.extract (clusters);
  EXPECT_EQ (clusters.size(), 3u);
  EXPECT_NEAR (seg.getStackNormals()[0].norm(), 1.0f, 1e-6f);
  // Minimum size: drop the smallest cube (0.6 m: 6 * 30 * 30 = 5400 points).
  const std::size_t smallest = clusters.back().indices.size();
  seg.setMinClusterSize (static_cast<pcl::uindex_t> (smallest + 1));
  seg.extract (clusters);
  EXPECT_EQ (clusters.size(), 2u);
  // Sorted by decreasing size.
  EXPECT_GE (clusters[0].indices.size(), clusters[1].indices.size());
  // Indices: only the given points are segmented.
  pcl::IndicesPtr half (new pcl::Indices);
  for (std::size_t i = 0; i < scene.cloud->size(); ++i)
    if (scene.labels[i] == 1)
      half->push_back (static_cast<pcl::index_t> (i));
  Segmentation sub;
  sub.setInputCloud (scene.cloud);
  sub.setIndices (half);
  sub.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices, *half);
}

TEST (ProfileSegmentation, BadInput)
{
  Segmentation seg;
  std::vector<pcl::PointIndices> clusters (3);
  // No cloud.
  seg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  // Empty cloud.
  Cloud::Ptr cloud (new Cloud);
  seg.setInputCloud (cloud);
  seg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  // One point: no spacing to estimate; with explicit lengths, one segment.
  cloud->push_back (pcl::PointXYZ (1, 2, 3));
  seg.setInputCloud (cloud);
  seg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  seg.setProfileWidth (0.1);
  seg.setDistanceThreshold (0.1);
  seg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices, pcl::Indices{0});
  // All points coincide: automatic spacing fails; explicit lengths give one segment.
  Cloud::Ptr same (new Cloud);
  same->resize (100, pcl::PointXYZ (1, 1, 1));
  Segmentation dup;
  dup.setInputCloud (same);
  dup.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  dup.setProfileWidth (0.1);
  dup.setDistanceThreshold (0.1);
  for (const auto method : {Segmentation::ProfileMethod::Proximity,
                            Segmentation::ProfileMethod::MinimumSpanningTree,
                            Segmentation::ProfileMethod::CurveFitting}) {
    dup.setProfileSegmentation (method);
    dup.extract (clusters);
    ASSERT_EQ (clusters.size(), 1u);
    EXPECT_EQ (clusters[0].indices.size(), 100u);
  }
}

TEST (ProfileSegmentation, NonFinitePointsAreNeverSegmented)
{
  LabelledCloud scene = threeCubes();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < scene.cloud->size(); i += 97)
    (*scene.cloud)[i].x = (i % 2) ? nan : inf;
  for (const bool dense : {false, true}) // a wrong is_dense must not matter
  {
    scene.cloud->is_dense = dense;
    Segmentation seg;
    seg.setInputCloud (scene.cloud);
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    ASSERT_EQ (clusters.size(), 3u);
    std::size_t total = 0;
    for (const auto& c : clusters)
      for (const auto i : c.indices) {
        EXPECT_TRUE (pcl::isXYZFinite ((*scene.cloud)[i]));
        ++total;
      }
    EXPECT_EQ (total, scene.cloud->size() - (scene.cloud->size() + 96) / 97);
  }
  // All points non-finite: empty output.
  Cloud::Ptr bad (new Cloud);
  bad->resize (10, pcl::PointXYZ (nan, 0, 0));
  bad->is_dense = false;
  Segmentation seg;
  seg.setInputCloud (bad);
  std::vector<pcl::PointIndices> clusters (1);
  seg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
}

TEST (ProfileSegmentation, DegenerateClouds)
{
  // Collinear points at spacing 0.01: one segment; a gap of 0.1 splits them.
  Cloud::Ptr line (new Cloud);
  for (int i = 0; i < 200; ++i)
    line->push_back (pcl::PointXYZ (0.01f * i + (i >= 100 ? 0.1f : 0.f), 0, 0));
  Segmentation seg;
  seg.setInputCloud (line);
  std::vector<pcl::PointIndices> clusters;
  for (const auto method : {Segmentation::ProfileMethod::Proximity,
                            Segmentation::ProfileMethod::MinimumSpanningTree,
                            Segmentation::ProfileMethod::CurveFitting}) {
    seg.setProfileSegmentation (method);
    seg.extract (clusters);
    ASSERT_EQ (clusters.size(), 2u) << static_cast<int> (method);
    EXPECT_EQ (clusters[0].indices.size(), 100u);
  }
  // A coplanar square grid (z = 0) with a horizontal stack normal distribution:
  // vertical profiles cut it in lines; with a vertical user normal the whole plane is
  // one profile.
  Cloud::Ptr plane (new Cloud);
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
      plane->push_back (pcl::PointXYZ (0.01f * i, 0.01f * j, 0));
  seg.setInputCloud (plane);
  seg.setProfileSegmentation (Segmentation::ProfileMethod::Proximity);
  seg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices.size(), plane->size());
  seg.setStackNormals ({{0, 0, 1}});
  seg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  // Width larger than the cloud: one profile per stack, still one segment.
  seg.setStackNormals ({});
  seg.setProfileWidth (10.0);
  seg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
}

TEST (ProfileSegmentation, NonsenseParameters)
{
  const LabelledCloud scene = threeCubes();
  const auto fails = [&] (const std::function<void (Segmentation&)>& set) {
    Segmentation seg;
    seg.setInputCloud (scene.cloud);
    set (seg);
    std::vector<pcl::PointIndices> clusters (2);
    seg.extract (clusters);
    return clusters.empty() && seg.getStackEdges().empty();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setNumberOfStacks (0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setProfileWidth (-0.1); }));
  EXPECT_TRUE (fails ([&] (Segmentation& s) { s.setProfileWidth (nan); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) {
    s.setProfileWidth (std::numeric_limits<double>::infinity());
  }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setDistanceThreshold (-1.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setProfileWidthFactor (0.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setDistanceThresholdFactor (-2.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setPointSpacing (-0.01); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setStackNormals ({{0, 0, 0}}); }));
  EXPECT_TRUE (fails ([&] (Segmentation& s) {
    s.setStackNormals ({{static_cast<float> (nan), 0, 1}});
  }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setProximityNeighbours (0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setMaxTurnAngle (0.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setMaxTurnAngle (2.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setResidualFactor (-1.0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setTurnSignificance (-1.0); }));
  EXPECT_TRUE (fails ([&] (Segmentation& s) { s.setTurnSignificance (nan); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setMinClusterSize (0); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) {
    s.setMinClusterSize (10);
    s.setMaxClusterSize (5);
  }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setCurveWindow (-1.0); }));
  EXPECT_TRUE (fails ([&] (Segmentation& s) { s.setMaxThresholdFactor (nan); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) { s.setMaxThresholdFactor (0.5); }));
  EXPECT_TRUE (fails ([] (Segmentation& s) {
    s.setMaxThresholdFactor (std::numeric_limits<double>::infinity());
  }));
  // One stack is valid (documented): profiles cannot join, so segments are profile
  // chains.
  EXPECT_FALSE (fails ([] (Segmentation& s) { s.setNumberOfStacks (1); }));
}
