/*
 * TileResults, halo labels and tile values: the files the tiles of a run leave in its
 * work folder, and the exact statistics read from them.
 */
#include <pcl_ext/tiling/tile_results.h>

#include "../io/temp_folder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>

using pcl_ext::tiling::TileResults;

TEST (TileResults, TilesWriteTheirPointsAnywhereInTheFile)
{
  const std::string dir = freshFolder ("tile_results");
  ASSERT_TRUE (TileResults::create (dir, 200000));
  // Two tiles owning interleaved points, written in runs and singly.
  std::vector<std::uint64_t> even, odd_block;
  std::vector<std::uint32_t> even_values, block_values;
  for (std::uint64_t i = 0; i < 100000; i += 2) {
    even.push_back (i);
    even_values.push_back (static_cast<std::uint32_t> (i / 2));
  }
  for (std::uint64_t i = 150000; i < 200000; ++i) {
    odd_block.push_back (i);
    block_values.push_back (7);
  }
  ASSERT_TRUE (TileResults::write (dir, odd_block, block_values));
  ASSERT_TRUE (TileResults::write (dir, even, even_values));
  std::vector<std::uint32_t> values;
  ASSERT_TRUE (TileResults::read (dir, 0, 200000, values));
  for (std::uint64_t i = 0; i < 200000; ++i) {
    const std::uint32_t expected = i < 100000
                                       ? (i % 2 == 0 ? i / 2 : TileResults::kNoResult)
                                   : i >= 150000 ? 7u
                                                 : TileResults::kNoResult;
    ASSERT_EQ (values[i], expected) << i;
  }
  testing::internal::CaptureStderr();
  EXPECT_FALSE (TileResults::write (dir, {200000}, {1})); // beyond the points
  EXPECT_FALSE (TileResults::read (dir, 199999, 2, values));
  EXPECT_FALSE (TileResults::read (dir + "/none", 0, 1, values));
  testing::internal::GetCapturedStderr();
}

TEST (TileResults, NamedResultsAreFilesOfTheirOwnReadAtAnyPoints)
{
  // A method's second set of values per point (the classes beside the segments) in its
  // own file; readAt reads runs and single points in any order.
  const std::string dir = freshFolder ("tile_named_results");
  ASSERT_TRUE (TileResults::create (dir, 1000));
  ASSERT_TRUE (TileResults::create (dir, 1000, "values"));
  std::vector<std::uint64_t> indices;
  std::vector<std::uint32_t> values;
  for (std::uint64_t i = 100; i < 400; ++i) {
    indices.push_back (i);
    values.push_back (static_cast<std::uint32_t> (3 * i));
  }
  ASSERT_TRUE (TileResults::write (dir, indices, values, "values"));
  std::vector<std::uint32_t> read;
  const std::vector<std::uint64_t> at{399, 5, 100, 101, 102, 250, 999};
  ASSERT_TRUE (TileResults::readAt (dir, at, read, "values"));
  EXPECT_EQ (
      read,
      (std::vector<std::uint32_t>{
          1197, TileResults::kNoResult, 300, 303, 306, 750, TileResults::kNoResult}));
  ASSERT_TRUE (TileResults::readAt (dir, at, read)); // the results: untouched
  EXPECT_EQ (read, std::vector<std::uint32_t> (at.size(), TileResults::kNoResult));
  EXPECT_NE (TileResults::pathIn (dir, "values"), TileResults::pathIn (dir));
  testing::internal::CaptureStderr();
  EXPECT_FALSE (TileResults::readAt (dir, {1000}, read, "values")); // beyond the points
  EXPECT_TRUE (read.empty());
  EXPECT_FALSE (TileResults::readAt (dir, {0}, read, "none"));
  testing::internal::GetCapturedStderr();
}

TEST (TileResults, SegmentIdsRoundTrip)
{
  const std::string dir = freshFolder ("tile_ids");
  const std::vector<std::uint32_t> saved{4, 0xFFFFFFFFu, 0, 17};
  ASSERT_TRUE (pcl_ext::tiling::saveSegmentIds (dir, 2, saved));
  ASSERT_TRUE (pcl_ext::tiling::saveSegmentIds (dir, 3, {}));
  std::vector<std::uint32_t> loaded;
  ASSERT_TRUE (pcl_ext::tiling::loadSegmentIds (dir, 2, loaded));
  EXPECT_EQ (loaded, saved);
  ASSERT_TRUE (pcl_ext::tiling::loadSegmentIds (dir, 3, loaded));
  EXPECT_TRUE (loaded.empty());
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::loadSegmentIds (dir, 4, loaded)); // not joined
  std::ofstream (dir + "/tile_5.ids") << "abc";                    // not whole records
  EXPECT_FALSE (pcl_ext::tiling::loadSegmentIds (dir, 5, loaded));
  testing::internal::GetCapturedStderr();
}

TEST (TileResults, HaloLabelsRoundTrip)
{
  const std::string dir = freshFolder ("tile_halo");
  const std::vector<pcl_ext::tiling::HaloLabel> saved{{5, 1, 2}, {1ull << 40, 7, 0}};
  ASSERT_TRUE (pcl_ext::tiling::saveHaloLabels (dir, 3, saved));
  std::vector<pcl_ext::tiling::HaloLabel> loaded;
  ASSERT_TRUE (pcl_ext::tiling::loadHaloLabels (dir, 3, loaded));
  ASSERT_EQ (loaded.size(), 2u);
  EXPECT_EQ (loaded[1].index, 1ull << 40);
  EXPECT_EQ (loaded[1].owner, 7u);
  EXPECT_EQ (loaded[0].label, 2u);
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::loadHaloLabels (dir, 4, loaded)); // tile 4 not run
  testing::internal::GetCapturedStderr();
}

TEST (TileResults, SegmentSizesRoundTrip)
{
  const std::string dir = freshFolder ("tile_sizes");
  const std::vector<pcl_ext::tiling::SegmentSize> saved{{0, 12, 5}, {3, 1, 1ull << 40}};
  ASSERT_TRUE (pcl_ext::tiling::saveSegmentSizes (dir, 2, saved));
  std::vector<pcl_ext::tiling::SegmentSize> loaded;
  ASSERT_TRUE (pcl_ext::tiling::loadSegmentSizes (dir, 2, loaded));
  ASSERT_EQ (loaded.size(), 2u);
  EXPECT_EQ (loaded[0].points, 12u);
  EXPECT_EQ (loaded[1].label, 3u);
  EXPECT_EQ (loaded[1].first, 1ull << 40);
  ASSERT_TRUE (pcl_ext::tiling::saveSegmentSizes (dir, 5, {})); // a tile of no segment
  ASSERT_TRUE (pcl_ext::tiling::loadSegmentSizes (dir, 5, loaded));
  EXPECT_TRUE (loaded.empty());
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::loadSegmentSizes (dir, 4, loaded)); // not run
  testing::internal::GetCapturedStderr();
}

TEST (TileResults, TilesNotRunAreFound)
{
  const std::string dir = freshFolder ("tile_done");
  ASSERT_TRUE (pcl_ext::tiling::markTileDone (dir, 1));
  ASSERT_TRUE (pcl_ext::tiling::markTileDone (dir, 3));
  EXPECT_EQ (pcl_ext::tiling::findTilesNotDone (dir, 5),
             (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_TRUE (pcl_ext::tiling::findTilesNotDone (dir, 2).size() == 1u);
  // A tile started and not finished is named with its process; done, it is not.
  EXPECT_EQ (pcl_ext::tiling::describeTileStart (dir, 2), "");
  ASSERT_TRUE (pcl_ext::tiling::markTileStarted (dir, 2));
  const std::string start = pcl_ext::tiling::describeTileStart (dir, 2);
  EXPECT_EQ (start.rfind ("process " + std::to_string (::getpid()) + " on host ", 0),
             0u)
      << start;
  EXPECT_NE (start.find (" UTC"), std::string::npos) << start;
  ASSERT_TRUE (pcl_ext::tiling::markTileDone (dir, 2));
  EXPECT_EQ (pcl_ext::tiling::describeTileStart (dir, 2), "");
  EXPECT_EQ (pcl_ext::tiling::findTilesNotDone (dir, 5),
             (std::vector<std::size_t>{0, 4}));
  // A second pass is marked apart from the first.
  EXPECT_EQ (pcl_ext::tiling::findTilesNotDone (dir, 3, "refined"),
             (std::vector<std::size_t>{0, 1, 2}));
  ASSERT_TRUE (pcl_ext::tiling::markTileStarted (dir, 1));
  ASSERT_TRUE (pcl_ext::tiling::markTileDone (dir, 1, "refined"));
  EXPECT_EQ (pcl_ext::tiling::describeTileStart (dir, 1), "");
  EXPECT_EQ (pcl_ext::tiling::findTilesNotDone (dir, 3, "refined"),
             (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ (pcl_ext::tiling::findTilesNotDone (dir, 5),
             (std::vector<std::size_t>{0, 4}));
}

TEST (TileResults, TileValuesReadBackWithNonFiniteOnesAndBrokenFilesRefused)
{
  const std::string dir = freshFolder ("tile_values");
  const std::vector<float> saved{1.5f, std::numeric_limits<float>::quiet_NaN(), -2.f};
  ASSERT_TRUE (pcl_ext::tiling::saveTileValues (dir, 3, "noise_rms", saved));
  std::vector<float> values;
  ASSERT_TRUE (pcl_ext::tiling::loadTileValues (dir, 3, "noise_rms", values));
  ASSERT_EQ (values.size(), 3u);
  EXPECT_EQ (values[0], 1.5f);
  EXPECT_TRUE (std::isnan (values[1])); // kept, unlike nthOfTileValues
  EXPECT_EQ (values[2], -2.f);
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::loadTileValues (dir, 4, "noise_rms", values));
  EXPECT_TRUE (values.empty());
  std::ofstream (dir + "/tile_5.noise_rms", std::ios::binary) << "abcdef";
  EXPECT_FALSE (pcl_ext::tiling::loadTileValues (dir, 5, "noise_rms", values));
  testing::internal::GetCapturedStderr();
}
