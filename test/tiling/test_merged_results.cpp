/*
 * planTiles, writeTiles and MergedResults on a small point file: a wall across every
 * tile is one segment, an object inside one tile another, a NaN point in none; by size,
 * the wall counted over all tiles.
 */
#include <pcl_ext/tiling/merged_results.h>
#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_points.h>
#include <pcl_ext/tiling/tile_results.h>

#include "../io/temp_folder.h"

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace pcl_ext::tiling;

TEST (MergedResults, SegmentsOfTilesJoinAcrossTheHalos)
{
  const std::string dir = freshFolder ("merged_results");
  // A wall along x through four 5 m tiles (points 0-199), an object 4 m from it inside
  // one tile (200-209), and a point without coordinates (210).
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 200; ++i)
    cloud.push_back (pcl::PointXYZ (0.1f * i, 0.0f, 1.0f));
  for (int i = 0; i < 10; ++i)
    cloud.push_back (pcl::PointXYZ (12.0f + 0.1f * i, 4.0f, 1.0f));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back (pcl::PointXYZ (nan, nan, nan));
  cloud.is_dense = false;
  const std::string input = dir + "/wall.pcd";
  ASSERT_EQ (pcl::io::savePCDFileBinary (input, cloud), 0);

  TilePlan plan;
  ASSERT_TRUE (planTiles ({input}, 5.0, 1.0, plan));
  EXPECT_EQ (plan.getTotalPoints(), 211u);
  ASSERT_TRUE (TileResults::create (dir, plan.getTotalPoints()));
  pcl_ext::NoiseSampleCut sample_cut;
  ASSERT_TRUE (writeTiles (plan, dir, 0, {}, &sample_cut));
  const TileGrid grid = plan.getGrid();
  ASSERT_GE (grid.size(), 4u);
  // The noise sample's cut of the finite points as the tiles hold them (the NaN point
  // has none): fewer points than the sample, so the largest key of all.
  pcl_ext::NoiseSampleCut of_tiles;
  for (std::size_t t = 0; t < grid.size(); ++t) {
    std::vector<TilePoint> points;
    ASSERT_TRUE (readTilePoints (dir, t, points));
    for (const auto& p : points)
      if (p.owner == t)
        of_tiles.add (pcl_ext::noiseSampleKeyOf (p.x, p.y, p.z));
  }
  ASSERT_FALSE (sample_cut.empty());
  EXPECT_EQ (sample_cut.get(), of_tiles.get());

  // Each tile labels its wall points 0 and the object 1 (y above 2), core and halo.
  std::size_t halo_points = 0;
  for (std::size_t t = 0; t < grid.size(); ++t) {
    std::vector<TilePoint> points;
    ASSERT_TRUE (readTilePoints (dir, t, points));
    std::vector<std::uint64_t> core;
    std::vector<std::uint32_t> labels;
    std::vector<HaloLabel> halo;
    for (const auto& p : points) {
      const std::uint32_t label = p.y > 2.0f ? 1 : 0;
      if (p.owner == t) {
        core.push_back (p.index);
        labels.push_back (label);
      }
      else
        halo.push_back ({p.index, p.owner, label});
    }
    halo_points += halo.size();
    ASSERT_TRUE (TileResults::write (dir, core, labels));
    ASSERT_TRUE (saveHaloLabels (dir, t, halo));
    std::vector<SegmentSize> sizes;
    for (std::size_t i = 0; i < core.size(); ++i) {
      if (sizes.size() <= labels[i])
        sizes.resize (labels[i] + 1);
      sizes[labels[i]].first = sizes[labels[i]].points == 0
                                   ? core[i]
                                   : std::min (sizes[labels[i]].first, core[i]);
      ++sizes[labels[i]].points;
    }
    for (std::uint32_t l = 0; l < sizes.size(); ++l)
      sizes[l].label = l;
    ASSERT_TRUE (saveSegmentSizes (dir, t, sizes));
  }
  EXPECT_GT (halo_points, 0u);

  MergedResults merged;
  ASSERT_TRUE (merged.open (plan, dir, MergedResults::Kind::Segments));
  pcl::PCLPointCloud2 chunk;
  std::vector<std::uint32_t> values, all;
  std::size_t input_index = 9;
  while (merged.read (64, chunk, input_index, values) > 0) {
    EXPECT_EQ (input_index, 0u);
    all.insert (all.end(), values.begin(), values.end());
  }
  EXPECT_FALSE (merged.failed());
  ASSERT_EQ (all.size(), 211u);
  for (std::size_t i = 0; i < 200; ++i)
    EXPECT_EQ (all[i], 0u) << i; // one wall: numbered by its first point
  for (std::size_t i = 200; i < 210; ++i)
    EXPECT_EQ (all[i], 1u) << i;
  EXPECT_EQ (all[210], SegmentMerge::kNoSegment);

  // By size over the joined tiles: no tile holds 60 wall points, the wall has 200 and
  // stays; the object (10 points) is dropped.
  MergedResults by_size;
  by_size.setSegmentsBySize (60);
  ASSERT_TRUE (by_size.open (plan, dir, MergedResults::Kind::Segments));
  EXPECT_EQ (by_size.getNumberOfSegments(), 1u);
  all.clear();
  while (by_size.read (64, chunk, input_index, values) > 0)
    all.insert (all.end(), values.begin(), values.end());
  ASSERT_EQ (all.size(), 211u);
  EXPECT_EQ (all[0], 0u);
  EXPECT_EQ (all[199], 0u);
  EXPECT_EQ (all[205], SegmentMerge::kNoSegment);
  // The object, under the size and joined by no halo, is not even kept; each tile's
  // piece of the wall, as small but joined, is.
  SegmentMerge merge;
  ASSERT_TRUE (joinTileSegments (plan, dir, true, 60, merge));
  const auto object_tile = static_cast<std::uint32_t> (
      grid.getTile (plan.origin.x() + 12.5, plan.origin.y() + 4.0));
  ASSERT_NE (object_tile, TileGrid::kNoTile);
  EXPECT_FALSE (merge.contains (SegmentMerge::key (object_tile, 1)));
  EXPECT_EQ (merge.number (SegmentMerge::key (object_tile, 1)),
             SegmentMerge::kNoSegment);
  for (std::uint32_t t = 0; t < 4; ++t) {
    const auto wall_tile = static_cast<std::uint32_t> (
        grid.getTile (plan.origin.x() + 5.0 * t + 2.5, plan.origin.y()));
    EXPECT_TRUE (merge.contains (SegmentMerge::key (wall_tile, 0))) << t;
    EXPECT_EQ (merge.number (SegmentMerge::key (wall_tile, 0)), 0u) << t;
  }

  // A tile that did not run: its halo labels are missing, the merge refuses.
  std::remove ((dir + "/tile_1.halo").c_str());
  testing::internal::CaptureStderr();
  EXPECT_FALSE (merged.open (plan, dir, MergedResults::Kind::Segments));
  testing::internal::GetCapturedStderr();
}

TEST (MergedResults, PlansOfNothingAreRefused)
{
  const std::string dir = freshFolder ("merged_results_empty");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back (pcl::PointXYZ (nan, nan, nan));
  cloud.is_dense = false;
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir + "/nan.pcd", cloud), 0);
  TilePlan plan;
  testing::internal::CaptureStderr();
  EXPECT_FALSE (planTiles ({dir + "/nan.pcd"}, 5.0, 1.0, plan)); // no finite point
  cloud[0] = pcl::PointXYZ (1.0f, 2.0f, 3.0f);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir + "/one.pcd", cloud), 0);
  EXPECT_FALSE (planTiles ({dir + "/one.pcd"}, 0.0, 1.0, plan));  // no tile size
  EXPECT_FALSE (planTiles ({dir + "/one.pcd"}, 5.0, -1.0, plan)); // negative halo
  testing::internal::GetCapturedStderr();
  ASSERT_TRUE (planTiles ({dir + "/one.pcd"}, 5.0, 1.0, plan)); // a one-point tile
  EXPECT_EQ (plan.getGrid().size(), 1u);
  ASSERT_TRUE (saveTilePlan (dir + "/plan.txt", plan));
  TilePlan again;
  ASSERT_TRUE (loadTilePlan (dir + "/plan.txt", again));
  EXPECT_EQ (again.inputs, plan.inputs);
  EXPECT_EQ (again.origin, plan.origin);
  EXPECT_EQ (again.min, plan.min);
  EXPECT_EQ (again.tile_size, plan.tile_size);
  std::ofstream (dir + "/broken.txt") << "pcl_ext tile plan 1\nbox 0 0\n";
  testing::internal::CaptureStderr();
  EXPECT_FALSE (loadTilePlan (dir + "/broken.txt", again));
  EXPECT_FALSE (loadTilePlan (dir + "/missing.txt", again));
  testing::internal::GetCapturedStderr();
}
