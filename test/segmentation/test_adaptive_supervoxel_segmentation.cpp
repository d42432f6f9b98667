/*
 * Tests of the adaptive super-voxels (Lim & Suter 2008, section 3.1).
 */
#include "../features/crf_test_clouds.h"

#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>

#include <gtest/gtest.h>

#include <limits>

using pcl_ext::AdaptiveSupervoxelSegmentation;
using pcl_ext::SupervoxelSet;

namespace {
SupervoxelSet
segment (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
         unsigned threads = 2,
         std::uint64_t seed = 1,
         double noise = 0.0)
{
  AdaptiveSupervoxelSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setNumberOfThreads (threads);
  seg.setSeed (seed);
  seg.setNoise (noise);
  SupervoxelSet set;
  seg.segment (set);
  return set;
}
} // namespace

TEST (AdaptiveSupervoxelSegmentation, CoverEveryPointWithSpheres)
{
  const auto cloud = crf_test::floorAndWall (0.05, 0.003);
  const SupervoxelSet set = segment (cloud);
  ASSERT_FALSE (set.empty());
  ASSERT_EQ (set.membership_offsets.size(), cloud->size() + 1);
  for (std::size_t i = 0; i < cloud->size(); ++i)
    EXPECT_GE (set.membership_offsets[i + 1] - set.membership_offsets[i], 1u)
        << "point " << i;
  for (const auto& sv : set.supervoxels) {
    EXPECT_GT (sv.radius, 0.f);
    EXPECT_GE (sv.steps, 1);
    EXPECT_LE (sv.steps, 10);
    ASSERT_FALSE (sv.members.empty());
    EXPECT_EQ (sv.members.front(), sv.seed);
    const Eigen::Vector3f c = (*cloud)[sv.seed].getVector3fMap();
    for (const auto i : sv.members)
      EXPECT_LE (((*cloud)[i].getVector3fMap() - c).norm(), sv.radius * 1.0001f);
  }
  // Overlaps are recorded: a point held by two super-voxels is listed under both.
  EXPECT_GT (set.countOverlappingPoints(), 0u);
  ASSERT_EQ (set.adjacency.size(), set.size());
  for (std::size_t v = 0; v < set.size(); ++v) {
    EXPECT_EQ (set.adjacency[v].size(), 4u);
    for (const auto k : set.adjacency[v])
      EXPECT_NE (k, v);
  }
  // Fewer super-voxels than points: the reduction the method is for.
  EXPECT_LT (set.size() * 10, cloud->size());
}

TEST (AdaptiveSupervoxelSegmentation, SmallerWhereCurved)
{
  // Flat floor far from the wall versus the crease: curvature shrinks the radius (eq.
  // 2-3).
  const auto cloud = crf_test::floorAndWall (0.05, 0.002);
  const SupervoxelSet set = segment (cloud, 2, 1, 0.002);
  double flat = 0, crease = 0;
  int n_flat = 0, n_crease = 0;
  for (const auto& sv : set.supervoxels) {
    const auto& p = (*cloud)[sv.seed];
    const float d = std::min (std::abs (p.x), std::abs (p.z)); // distance to the crease
    if (p.x > 1.5f && std::abs (p.z) < 0.01f && p.y > 0.5f && p.y < 3.5f &&
        p.x < 3.5f) {
      flat += sv.radius;
      ++n_flat;
    }
    else if (d < 0.02f && p.y > 0.5f && p.y < 3.5f && std::max (p.x, p.z) < 0.15f) {
      crease += sv.radius;
      ++n_crease;
    }
  }
  ASSERT_GT (n_flat, 0);
  ASSERT_GT (n_crease, 0);
  EXPECT_LT (crease / n_crease, 0.8 * flat / n_flat);
}

TEST (AdaptiveSupervoxelSegmentation, DeterministicForASeedAndAnyThreadCount)
{
  const auto cloud = crf_test::floorAndWall (0.05, 0.003);
  const SupervoxelSet a = segment (cloud, 1), b = segment (cloud, 2),
                      c = segment (cloud, 2, 2);
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t v = 0; v < a.size(); ++v) {
    EXPECT_EQ (a.supervoxels[v].seed, b.supervoxels[v].seed);
    EXPECT_EQ (a.supervoxels[v].radius, b.supervoxels[v].radius);
    EXPECT_EQ (a.supervoxels[v].members, b.supervoxels[v].members);
    EXPECT_EQ (a.adjacency[v], b.adjacency[v]);
  }
  bool differs = a.size() != c.size();
  for (std::size_t v = 0; !differs && v < a.size(); ++v)
    differs = a.supervoxels[v].seed != c.supervoxels[v].seed;
  EXPECT_TRUE (differs) << "another seed should draw other mid-points";
}

TEST (AdaptiveSupervoxelSegmentation, BadInputGivesEmptyOutput)
{
  AdaptiveSupervoxelSegmentation<pcl::PointXYZ> seg;
  SupervoxelSet set;
  seg.segment (set); // no input
  EXPECT_TRUE (set.empty());
  auto empty = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  EXPECT_TRUE (segment (empty).empty());
  auto one = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  one->push_back (pcl::PointXYZ (1, 2, 3));
  EXPECT_TRUE (segment (one).empty());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto nans = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  nans->assign (100, pcl::PointXYZ (nan, nan, nan));
  EXPECT_TRUE (segment (nans).empty());
  // NaN points among good ones belong to no super-voxel.
  auto mixed = crf_test::floorAndWall (0.1, 0.003);
  (*mixed)[5].x = nan;
  const SupervoxelSet m = segment (mixed);
  ASSERT_FALSE (m.empty());
  EXPECT_EQ (m.membership_offsets[6], m.membership_offsets[5]);
  // Nonsense parameters.
  const auto cloud = crf_test::floorAndWall (0.1, 0.003);
  for (int k = 0; k < 4; ++k) {
    AdaptiveSupervoxelSegmentation<pcl::PointXYZ> bad;
    bad.setInputCloud (cloud);
    if (k == 0)
      bad.setDamping (0.0);
    if (k == 1)
      bad.setMaxK (10);
    if (k == 2)
      bad.setNoise (-1.0);
    if (k == 3)
      bad.setNumberOfRegionalNeighbours (-2);
    std::vector<pcl::PointIndices> clusters;
    bad.extract (clusters);
    EXPECT_TRUE (clusters.empty()) << "case " << k;
  }
}
