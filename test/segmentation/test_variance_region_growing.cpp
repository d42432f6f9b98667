/*
 * VarianceRegionGrowing (Belton & Lichti 2006, section 3): the walk rules on hand-made
 * neighbourhoods, the segmenter on given classes, its outputs and bad input. The
 * segmenter after the classification, on analytic shapes:
 * test/classification/test_variance_segmentation.
 */
#include "../features/analytic_clouds.h"
#include "variance_test_clouds.h"

#include <pcl_ext/segmentation/variance_region_growing.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Growing = pcl_ext::VarianceRegionGrowing<Point>;
using Labels = pcl::PointCloud<pcl::Label>;
constexpr std::int8_t S = 1, E = 2, B = 3; // PointClass values
const float kNoLimit = std::numeric_limits<float>::infinity();

/** Rows as the kernel takes them, written as lists of (neighbour, distance). */
struct Rows {
  std::vector<std::size_t> offsets{0};
  pcl::Indices neighbours;
  std::vector<float> sqr_distances;
  pcl::Indices points;

  void
  add (pcl::index_t point, const std::vector<std::pair<pcl::index_t, float>>& row)
  {
    points.push_back (point);
    for (const auto& [j, d] : row) {
      neighbours.push_back (j);
      sqr_distances.push_back (d * d);
    }
    offsets.push_back (neighbours.size());
  }

  /** The walks with every row cut where its distances pass \a max_sqr. */
  std::vector<std::int32_t>
  grow (const std::vector<std::int8_t>& classes, float max_sqr = kNoLimit) const
  {
    std::vector<std::uint32_t> reach;
    if (max_sqr != kNoLimit)
      for (std::size_t r = 0; r < points.size(); ++r) {
        std::size_t m = offsets[r];
        while (m < offsets[r + 1] && sqr_distances[m] <= max_sqr)
          ++m;
        reach.push_back (static_cast<std::uint32_t> (m - offsets[r]));
      }
    const pcl_ext::NeighbourRowsView view{
        neighbours.data(), offsets.data(), 0, points.size()};
    std::vector<std::int32_t> root;
    pcl_ext::growSurfaceSegments (view, points, classes, reach, 1, root);
    return root;
  }
};

} // namespace

// ---------------------------------------------------------------------------------------------
// The walk (section 3 and the corrected figure 4), on hand-made rows.

TEST (GrowSurfaceSegments, UnlabelledSurfaceNeighboursJoin)
{
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (1, {{1, 0.f}});
  rows.add (2, {{2, 0.f}});
  const auto root = rows.grow ({S, S, S});
  EXPECT_EQ (root, (std::vector<std::int32_t>{0, 0, 0}));
}

TEST (GrowSurfaceSegments, NonSurfaceNeighbourStopsTheWalk)
{
  // Point 0's list: itself, the edge point 1, then surface point 2: 2 is beyond the
  // stop.
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (1, {{1, 0.f}, {0, 1.f}, {2, 1.f}});
  rows.add (2, {{2, 0.f}, {1, 1.f}, {0, 2.f}});
  for (const std::int8_t stop : {E, B, std::int8_t (0)}) {
    const auto root = rows.grow ({S, stop, S});
    EXPECT_EQ (root, (std::vector<std::int32_t>{0, -1, 2})) << "class " << int (stop);
  }
  // Without the stop, 0 and 2 link.
  EXPECT_EQ (rows.grow ({S, S, S}), (std::vector<std::int32_t>{0, 0, 0}));
}

TEST (GrowSurfaceSegments, SurfaceNeighbourOfAnotherSegmentMerges)
{
  // 3 - 2 and 1 - 0 grow apart (in row order 3, 1 first); then 2's walk reaches 1: one
  // segment, whose root is its smallest index whatever the order of the rows.
  Rows rows;
  rows.add (3, {{3, 0.f}, {2, 1.f}});
  rows.add (1, {{1, 0.f}, {0, 1.f}});
  rows.add (2, {{2, 0.f}, {1, 1.f}, {4, 1.5f}});
  rows.add (0, {{0, 0.f}});
  rows.add (4, {{4, 0.f}});
  const auto root = rows.grow ({S, S, S, S, E});
  EXPECT_EQ (root, (std::vector<std::int32_t>{0, 0, 0, 0, -1}));
}

TEST (GrowSurfaceSegments, MaximumDistanceFromTheSeedStopsTheWalk)
{
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 0.5f}, {2, 2.0f}});
  rows.add (1, {{1, 0.f}});
  rows.add (2, {{2, 0.f}});
  EXPECT_EQ (rows.grow ({S, S, S}, 1.0f), (std::vector<std::int32_t>{0, 0, 2}));
  EXPECT_EQ (rows.grow ({S, S, S}, 4.0f), (std::vector<std::int32_t>{0, 0, 0}));
}

TEST (GrowSurfaceSegments, PointsOutsideTheIndicesAreSkipped)
{
  // Point 1 is not segmented (-1): the walk passes over it to 2.
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (2, {{2, 0.f}});
  EXPECT_EQ (rows.grow ({S, -1, S}), (std::vector<std::int32_t>{0, -1, 0}));
}

// ---------------------------------------------------------------------------------------------
// The segmenter on given classes.

TEST (VarianceRegionGrowing, MaximumDistanceSeparatesPatches)
{
  // Two patches 0.2 apart, every point called surface: with k = 50 the neighbourhoods
  // of the facing rows reach across the gap, so without a limit the patches are one
  // segment.
  const auto cloud = pcl_ext::test::twoPatches (0.2);
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setInputClasses (pcl_ext::test::uniformClasses (cloud->size(), 1));
  rg.setMaxDistanceFactor (0.0);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices.size(), cloud->size());
  rg.setMaxDistance (0.15);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 2u);
  EXPECT_EQ (clusters[0].indices.size(), 441u);
  EXPECT_EQ (clusters[1].indices.size(), 441u);
  EXPECT_EQ (clusters[1].indices.front(), 441); // ties: smallest index first
}

TEST (VarianceRegionGrowing, MaximumDistanceFactorFollowsTheSpacing)
{
  // The same two patches at two scales: spacing 0.05 with a 0.2 gap, and both doubled.
  // A limit of twice the local spacing (s = r_m sqrt(pi / m), m = 24 of k = 50: about
  // 0.05 inside a patch, more on its border, where the m-th neighbour is farther)
  // separates them at both scales, as the limit scales with the sampling. Without a
  // limit both are one segment.
  for (const double scale : {1.0, 2.0}) {
    const auto base = pcl_ext::test::twoPatches (0.2);
    Cloud::Ptr cloud (new Cloud);
    for (const auto& p : *base)
      cloud->push_back (Point (
          static_cast<float> (scale * p.x), static_cast<float> (scale * p.y), 0.f));
    Growing rg;
    rg.setInputCloud (cloud);
    rg.setInputClasses (pcl_ext::test::uniformClasses (cloud->size(), 1));
    std::vector<pcl::PointIndices> clusters;
    rg.setMaxDistanceFactor (0.0);
    rg.extract (clusters);
    EXPECT_EQ (clusters.size(), 1u) << scale;
    rg.setMaxDistanceFactor (2.0);
    rg.extract (clusters);
    ASSERT_EQ (clusters.size(), 2u) << scale;
    EXPECT_EQ (clusters[0].indices.size(), 441u);
    EXPECT_EQ (clusters[1].indices.size(), 441u);
  }
  EXPECT_DOUBLE_EQ (Growing().getMaxDistanceFactor(), 3.0); // the default
}

TEST (VarianceRegionGrowing, SizeLimitsDropSegments)
{
  // Patch 0: 441 points; patch 1 cut to 10 x 21 = 210 points by calling a column edge.
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  Labels::Ptr classes = pcl_ext::test::uniformClasses (cloud->size(), 1);
  for (std::size_t i = 441; i < cloud->size(); ++i)
    if ((i - 441) / 21 == 10)
      (*classes)[i].label = 2;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setInputClasses (classes);
  rg.setKSearch (9);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 3u);
  EXPECT_EQ (clusters[0].indices.size(), 441u);
  EXPECT_EQ (clusters[1].indices.size(), 210u);
  EXPECT_EQ (clusters[2].indices.size(), 210u);
  rg.setMinClusterSize (300);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices.size(), 441u);
  rg.setMinClusterSize (1);
  rg.setMaxClusterSize (300);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 2u);
  EXPECT_EQ (clusters[0].indices.size(), 210u);
}

TEST (VarianceRegionGrowing, IndicesRestrictTheSegmentation)
{
  // Only the second patch is segmented; the first is neither segmented nor a stop.
  const auto cloud = pcl_ext::test::twoPatches (0.05);
  pcl::IndicesPtr second (new pcl::Indices);
  for (pcl::index_t i = 441; i < static_cast<pcl::index_t> (cloud->size()); ++i)
    second->push_back (i);
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setIndices (second);
  rg.setInputClasses (pcl_ext::test::uniformClasses (second->size(), 1));
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices, *second);
  Labels labels;
  rg.getSegmentLabels (labels);
  ASSERT_EQ (labels.size(), cloud->size());
  EXPECT_EQ (labels[0].label, 0u);
  EXPECT_EQ (labels[441].label, 1u);
}

TEST (VarianceRegionGrowing, OnlySeedsStartWalks)
{
  // One patch, every point surface (k = 5: each links only to the points next to it).
  // All points as seeds: one segment, as without seeds. Only the first 10 columns as
  // seeds (a tile's core): they and the column they link to are one segment; the other
  // points are labelled, each its own segment, but link nothing.
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  pcl::IndicesPtr one (new pcl::Indices), all (new pcl::Indices),
      seeds (new pcl::Indices);
  for (pcl::index_t i = 0; i < 441; ++i) {
    one->push_back (i);
    all->push_back (i);
    if (i / 21 < 10)
      seeds->push_back (i);
  }
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setIndices (one);
  rg.setKSearch (5);
  rg.setInputClasses (pcl_ext::test::uniformClasses (one->size(), 1));
  std::vector<pcl::PointIndices> clusters;
  rg.setSeedIndices (all);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u);
  EXPECT_EQ (clusters[0].indices.size(), 441u);
  rg.setSeedIndices (seeds);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 1u + 441u - 11u * 21u);
  EXPECT_EQ (clusters[0].indices.size(), 11u * 21u); // the seeds and the next column
  for (std::size_t c = 1; c < clusters.size(); ++c)
    EXPECT_EQ (clusters[c].indices.size(), 1u);
  EXPECT_EQ (rg.getSeedIndices(), seeds);
}

TEST (VarianceRegionGrowing, OutputsLabelsAndColours)
{
  // An organised 2-row cloud: the labels keep its layout.
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  cloud->width = static_cast<std::uint32_t> (cloud->size() / 2);
  cloud->height = 2;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setInputClasses (pcl_ext::test::uniformClasses (cloud->size(), 1));
  Labels labels;
  rg.getSegmentLabels (labels);
  EXPECT_TRUE (labels.empty()); // before extract()
  EXPECT_TRUE (rg.getColoredCloud()->empty());
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 2u);
  rg.getSegmentLabels (labels);
  EXPECT_EQ (labels.width, cloud->width);
  EXPECT_EQ (labels.height, 2u);
  EXPECT_EQ (labels[0].label, 1u);
  EXPECT_EQ (labels[441].label, 2u);
  const auto coloured = rg.getColoredCloud();
  ASSERT_EQ (coloured->size(), cloud->size());
  EXPECT_EQ (coloured->height, 2u);
  const auto& a = (*coloured)[0];
  const auto& b = (*coloured)[441];
  EXPECT_FALSE (a.r == b.r && a.g == b.g && a.b == b.b);
  EXPECT_FALSE (a.r == 255 && a.g == 255 && a.b == 255);
}

// ---------------------------------------------------------------------------------------------
// Bad input: a PCL_ERROR and no segment, never a crash.

TEST (VarianceRegionGrowingBadInput, NoCloudEmptyCloudEmptyIndices)
{
  std::vector<pcl::PointIndices> clusters{pcl::PointIndices()};
  Growing rg;
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  rg.setInputCloud (Cloud::Ptr (new Cloud));
  clusters.resize (1);
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  const auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  rg.setInputCloud (plane.cloud);
  rg.setIndices (pcl::IndicesPtr (new pcl::Indices));
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  Labels labels;
  rg.getSegmentLabels (labels);
  EXPECT_TRUE (labels.empty());
}

TEST (VarianceRegionGrowingBadInput, NoSurfacePoint)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  Growing rg;
  rg.setInputCloud (plane.cloud);
  rg.setInputClasses (pcl_ext::test::uniformClasses (plane.cloud->size(), 2));
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
}

TEST (VarianceRegionGrowingBadInput, SegmentsOfOnePoint)
{
  // Surface points each surrounded by edges: every one is a segment of its own.
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  Labels::Ptr classes = pcl_ext::test::uniformClasses (cloud->size(), 2);
  for (const std::size_t i : {22u, 100u, 300u})
    (*classes)[i].label = 1;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setInputClasses (classes);
  rg.setKSearch (9);
  rg.setFitPlanes (true);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size(), 3u);
  EXPECT_EQ (clusters[0].indices,
             pcl::Indices{22}); // equal sizes: smallest index first
  EXPECT_EQ (clusters[2].indices, pcl::Indices{300});
  ASSERT_EQ (rg.getSegmentPlanes().size(), 3u);
  for (const auto& p : rg.getSegmentPlanes()) {
    EXPECT_FALSE (p.isValid());
    EXPECT_EQ (p.size, 1u);
  }
  // With the usual minimum size nothing is left, and that is no error.
  rg.setMinClusterSize (2);
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty());
}

TEST (VarianceRegionGrowingBadInput, NonsenseParameters)
{
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  std::vector<pcl::PointIndices> clusters;
  const auto fails = [&] (const std::function<void (Growing&)>& set) {
    Growing rg;
    rg.setInputCloud (cloud);
    rg.setInputClasses (pcl_ext::test::uniformClasses (cloud->size(), 1));
    set (rg);
    clusters.resize (1);
    rg.extract (clusters);
    return clusters.empty();
  };
  EXPECT_FALSE (fails ([] (Growing&) {}));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMinClusterSize (0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) {
    rg.setMinClusterSize (10);
    rg.setMaxClusterSize (9);
  }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (INFINITY); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (INFINITY); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxRadius (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxRadius (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (2); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (-5); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (100000); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setRadiusSearch (-0.1); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setRadiusSearch (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (0); })); // neither k nor radius
  EXPECT_TRUE (fails ([&] (Growing& rg) {
    rg.setInputClasses (pcl_ext::test::uniformClasses (cloud->size() - 1, 1));
  }));
  EXPECT_TRUE (
      fails ([] (Growing& rg) { rg.setInputClasses (nullptr); })); // none given
}
