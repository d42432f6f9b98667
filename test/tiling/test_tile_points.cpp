/*
 * TilePointWriter and readTilePoints: points sorted into their tiles' files and read
 * back in index order; broken files refused.
 */
#include <pcl_ext/tiling/tile_points.h>

#include "../io/temp_folder.h"

#include <gtest/gtest.h>

#include <fstream>

using pcl_ext::tiling::TilePoint;

TEST (TilePoints, WrittenThroughSmallBuffersAndReadBack)
{
  const std::string dir = freshFolder ("tile_points");
  {
    pcl_ext::tiling::TilePointWriter writer (dir, 3, 7);
    for (std::uint64_t i = 0; i < 1000; ++i) {
      const TilePoint p{
          i, 0.5f * i, -1.0f * i, 3.0f, static_cast<std::uint32_t> (i % 3)};
      ASSERT_TRUE (writer.add (i % 2, p)); // tile 0 even, tile 1 odd, tile 2 none
    }
    ASSERT_TRUE (writer.finish());
    EXPECT_EQ (writer.getCount (0), 500u);
    EXPECT_EQ (writer.getCount (2), 0u);
  }
  std::vector<TilePoint> points;
  ASSERT_TRUE (pcl_ext::tiling::readTilePoints (dir, 0, points));
  ASSERT_EQ (points.size(), 500u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ (points[i].index, 2 * i);
    EXPECT_EQ (points[i].x, 0.5f * (2 * i));
    EXPECT_EQ (points[i].y, -1.0f * (2 * i));
    EXPECT_EQ (points[i].z, 3.0f);
    EXPECT_EQ (points[i].owner, (2 * i) % 3);
  }
  ASSERT_TRUE (pcl_ext::tiling::readTilePoints (dir, 2, points));
  EXPECT_TRUE (points.empty()); // an empty tile has an empty file
}

TEST (TilePoints, BrokenFilesAreRefused)
{
  const std::string dir = freshFolder ("tile_points_broken");
  std::vector<TilePoint> points{{1, 0, 0, 0, 0}};
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::readTilePoints (dir, 9, points)); // missing
  EXPECT_TRUE (points.empty());
  std::ofstream (pcl_ext::tiling::tilePointsPath (dir, 0), std::ios::binary) << "abc";
  EXPECT_FALSE (pcl_ext::tiling::readTilePoints (dir, 0, points)); // 3 bytes
  {
    pcl_ext::tiling::TilePointWriter writer (dir, 1);
    writer.add (0, {5, 0, 0, 0, 0});
    writer.add (0, {4, 0, 0, 0, 0}); // out of order
    writer.finish();
  }
  EXPECT_FALSE (pcl_ext::tiling::readTilePoints (dir, 0, points));
  pcl_ext::tiling::TilePointWriter unwritable ("/nonexistent-folder", 1, 1);
  EXPECT_FALSE (unwritable.add (0, {0, 0, 0, 0, 0}));
  EXPECT_FALSE (unwritable.finish());
  testing::internal::GetCapturedStderr();
}

TEST (TilePoints, AttributesFollowThePointsAndBrokenOnesAreRefused)
{
  const std::string dir = freshFolder ("tile_attributes");
  {
    pcl_ext::tiling::TilePointWriter writer (dir, 2, 3, 2);
    for (std::uint64_t i = 0; i < 10; ++i) {
      const float values[2] = {float (i), -float (i)};
      ASSERT_TRUE (writer.add (i % 2, {i, 0, 0, 0, 0}, values));
    }
    ASSERT_TRUE (writer.finish());
  }
  std::vector<TilePoint> points;
  std::vector<float> values;
  ASSERT_TRUE (pcl_ext::tiling::readTilePoints (dir, 1, points));
  ASSERT_TRUE (pcl_ext::tiling::readTileAttributes (dir, 1, 2, values));
  ASSERT_EQ (values.size(), 2 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ (values[2 * i], float (points[i].index));
    EXPECT_EQ (values[2 * i + 1], -float (points[i].index));
  }
  ASSERT_TRUE (pcl_ext::tiling::readTileAttributes (dir, 1, 0, values));
  EXPECT_TRUE (values.empty()); // no attributes asked: none read
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::tiling::readTileAttributes (dir, 7, 2, values)); // missing
  std::ofstream (pcl_ext::tiling::tileAttributesPath (dir, 0), std::ios::binary)
      << "abcde";
  EXPECT_FALSE (pcl_ext::tiling::readTileAttributes (dir, 0, 2, values)); // 5 bytes
  EXPECT_TRUE (values.empty());
  testing::internal::GetCapturedStderr();
}
