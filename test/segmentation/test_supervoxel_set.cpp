/*
 * Tests of the adaptive super-voxel over-segmentation without the point type
 * (computeAdaptiveSupervoxels, Lim & Suter 2008, section 3.1) and of SupervoxelSet.
 */
#include "../features/crf_test_clouds.h"

#include <pcl_ext/segmentation/supervoxel_set.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

using pcl_ext::SupervoxelParameters;
using pcl_ext::SupervoxelSet;

TEST (SupervoxelSet, OverlapsAreCountedFromTheMembership)
{
  // Four points: point 0 in super-voxel 0, point 1 in 0 and 1, point 2 in none (not
  // finite), point 3 in 1 and 2.
  SupervoxelSet set;
  EXPECT_TRUE (set.empty());
  set.supervoxels.resize (3);
  set.membership_offsets = {0, 1, 3, 3, 5};
  set.membership = {0, 0, 1, 1, 2};
  EXPECT_EQ (set.size(), 3u);
  EXPECT_FALSE (set.empty());
  EXPECT_EQ (set.countOverlappingPoints(), 2u);
  set.clear();
  EXPECT_TRUE (set.empty());
  EXPECT_TRUE (set.membership_offsets.empty());
  EXPECT_EQ (set.countOverlappingPoints(), 0u);
}

TEST (SupervoxelSet, SpheresCoverTheFinitePointsAndNeighboursAreTheClosestMidPoints)
{
  auto cloud = crf_test::floorAndWall (0.1, 0.002);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  (*cloud)[7].y = nan;
  SupervoxelParameters p;
  p.adjacency = 2;
  p.threads = 1;
  SupervoxelSet set;
  pcl_ext::AdaptiveRadiusEstimator estimator;
  ASSERT_TRUE (pcl_ext::computeAdaptiveSupervoxels (cloud, {}, p, set, &estimator));
  EXPECT_EQ (estimator.cloud().get(), cloud.get());
  ASSERT_FALSE (set.empty());
  ASSERT_EQ (set.membership_offsets.size(), cloud->size() + 1);
  EXPECT_EQ (set.membership.size(), set.membership_offsets.back());
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const std::size_t count = set.membership_offsets[i + 1] - set.membership_offsets[i];
    if (i == 7)
      EXPECT_EQ (count, 0u) << "a NaN point belongs to no super-voxel";
    else
      EXPECT_GE (count, 1u) << "point " << i;
  }
  for (std::size_t v = 0; v < set.size(); ++v) {
    const auto& sv = set.supervoxels[v];
    const Eigen::Vector3f c = (*cloud)[sv.seed].getVector3fMap();
    // The membership lists v under every member; the mid-point was in no earlier
    // super-voxel.
    for (const auto i : sv.members) {
      const auto first = set.membership.begin() + set.membership_offsets[i];
      const auto last = set.membership.begin() + set.membership_offsets[i + 1];
      EXPECT_NE (std::find (first, last, v), last);
      EXPECT_LE (((*cloud)[i].getVector3fMap() - c).norm(), sv.radius * 1.0001f);
    }
    for (std::size_t u = 0; u < v; ++u) {
      const auto& earlier = set.supervoxels[u].members;
      EXPECT_EQ (std::find (earlier.begin(), earlier.end(), sv.seed), earlier.end());
    }
    // Adjacency: the two nearest other mid-points, closest first.
    ASSERT_EQ (set.adjacency[v].size(), 2u);
    std::vector<float> d;
    for (std::size_t u = 0; u < set.size(); ++u)
      if (u != v)
        d.push_back (((*cloud)[set.supervoxels[u].seed].getVector3fMap() - c).norm());
    std::sort (d.begin(), d.end());
    for (std::size_t k = 0; k < 2; ++k) {
      const auto u = set.adjacency[v][k];
      EXPECT_NE (u, v);
      EXPECT_NEAR (
          ((*cloud)[set.supervoxels[u].seed].getVector3fMap() - c).norm(), d[k], 1e-5f);
    }
  }
  // No regional neighbours asked for: none recorded.
  p.adjacency = 0;
  ASSERT_TRUE (pcl_ext::computeAdaptiveSupervoxels (cloud, {}, p, set));
  for (const auto& neighbours : set.adjacency)
    EXPECT_TRUE (neighbours.empty());
}

TEST (SupervoxelSet, BadInputClearsTheResult)
{
  const auto cloud = crf_test::floorAndWall (0.1, 0.002);
  SupervoxelSet set;
  ASSERT_TRUE (
      pcl_ext::computeAdaptiveSupervoxels (cloud, {}, SupervoxelParameters(), set));
  ASSERT_FALSE (set.empty());
  EXPECT_FALSE (
      pcl_ext::computeAdaptiveSupervoxels (nullptr, {}, SupervoxelParameters(), set));
  EXPECT_TRUE (set.empty());
  EXPECT_TRUE (set.membership_offsets.empty());
  SupervoxelParameters negative;
  negative.adjacency = -1;
  EXPECT_FALSE (pcl_ext::computeAdaptiveSupervoxels (cloud, {}, negative, set));
  SupervoxelParameters bad_radius;
  bad_radius.radius.max_k = bad_radius.radius.initial_k;
  EXPECT_FALSE (pcl_ext::computeAdaptiveSupervoxels (cloud, {}, bad_radius, set));
  // Colours must be one per point.
  EXPECT_FALSE (pcl_ext::computeAdaptiveSupervoxels (
      cloud,
      std::vector<Eigen::Vector3f> (3, Eigen::Vector3f::Ones()),
      SupervoxelParameters(),
      set));
  EXPECT_TRUE (set.empty());
}

namespace {
/** The super-voxels of \a cloud by mid-point position: radius and member count; the
 * noise constant \a noise (0: estimated from \a cloud). */
std::map<std::tuple<float, float, float>, std::pair<float, std::size_t>>
byMidPoint (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, double noise)
{
  SupervoxelParameters p;
  p.threads = 2;
  p.radius.noise = noise;
  SupervoxelSet set;
  std::map<std::tuple<float, float, float>, std::pair<float, std::size_t>> result;
  if (!pcl_ext::computeAdaptiveSupervoxels (cloud, {}, p, set))
    return result;
  for (const auto& sv : set.supervoxels) {
    const auto& m = (*cloud)[static_cast<std::size_t> (sv.seed)];
    result[{m.x, m.y, m.z}] = {sv.radius, sv.members.size()};
  }
  return result;
}
} // namespace

TEST (SupervoxelSet, TheDrawBelongsToThePointsNotToTheirOrder)
{
  // The same points in reverse order give the same super-voxels; a part of the cloud
  // with a margin around it gives the whole cloud's super-voxels inside it, as the
  // tiles of pcl_ext_tiles need.
  const auto cloud = crf_test::floorAndWall (0.05, 0.002);
  const auto whole = byMidPoint (cloud, 0.0);
  ASSERT_GT (whole.size(), 20u);
  auto reversed = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  reversed->assign (cloud->rbegin(), cloud->rend(), 1);
  EXPECT_TRUE (byMidPoint (reversed, 0.0) == whole);

  auto part = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& q : *cloud)
    if (q.y < 3.f)
      part->push_back (q);
  // The part with the whole cloud's noise constant (pcl_ext_tiles estimates it once).
  pcl_ext::AdaptiveRadiusEstimator estimator;
  ASSERT_TRUE (estimator.initialize (cloud, {}, {}));
  const auto in_part = byMidPoint (part, estimator.getNoise());
  std::size_t inside = 0;
  for (const auto& [m, sv] : whole)
    if (std::get<1> (m) < 1.5f) {
      ++inside;
      const auto found = in_part.find (m);
      ASSERT_NE (found, in_part.end()) << "mid-point at y " << std::get<1> (m);
      EXPECT_EQ (found->second, sv);
    }
  EXPECT_GT (inside, 5u);
  std::size_t part_inside = 0;
  for (const auto& [m, sv] : in_part)
    part_inside += std::get<1> (m) < 1.5f;
  EXPECT_EQ (part_inside, inside);
}
