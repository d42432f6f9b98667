/*
 * PointFileChunks: a LAS file and a PCD file read in chunks give the points, the origin
 * and the float coordinates of io::loadPointFile; missing files and chunks without
 * coordinates are refused.
 */
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/io/read_error.h>
#include <pcl_ext/tiling/point_file_chunks.h>

#include "../io/temp_folder.h"

#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

using pcl_ext::tiling::PointFileChunks;

namespace {
/** 1,000 points of a georeferenced wall (x ~ 500,000, y ~ 6,000,000), millimetre
 * coordinates, written as LAS (in double, through savePointFile) and as a PCD of the
 * local coordinates. */
pcl::PCLPointCloud2
wallCloud (Eigen::Vector3d& origin)
{
  origin = Eigen::Vector3d (500000.0, 6000000.0, 0.0);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 1000; ++i)
    cloud.push_back (pcl::PointXYZ (
        0.013f * (i % 100), 0.0f, 0.021f * static_cast<float> (i / 100)));
  pcl::PCLPointCloud2 out;
  pcl::toPCLPointCloud2 (cloud, out);
  return out;
}

/** Every point of \a path read in chunks of \a chunk_size: x y z floats. */
std::vector<float>
readAllXyz (PointFileChunks& chunks, std::size_t chunk_size)
{
  std::vector<float> xyz;
  pcl::PCLPointCloud2 chunk;
  while (const std::size_t n = chunks.read (chunk_size, chunk)) {
    EXPECT_LE (n, chunk_size);
    EXPECT_EQ (chunk.width * chunk.height, n);
    const std::size_t at = pcl_ext::tiling::xyzOffset (chunk);
    for (std::size_t i = 0; i < n; ++i) {
      float p[3];
      std::memcpy (p, chunk.data.data() + i * chunk.point_step + at, sizeof (p));
      xyz.insert (xyz.end(), p, p + 3);
    }
  }
  return xyz;
}

std::vector<float>
loadXyz (const std::string& path, Eigen::Vector3d& origin)
{
  pcl_ext::io::PointFile file;
  pcl_ext::io::loadPointFile (path, file);
  origin = file.origin;
  std::vector<float> xyz;
  const std::size_t at = pcl_ext::tiling::xyzOffset (file.cloud);
  for (std::size_t i = 0; i < file.cloud.width * file.cloud.height; ++i) {
    float p[3];
    std::memcpy (
        p, file.cloud.data.data() + i * file.cloud.point_step + at, sizeof (p));
    xyz.insert (xyz.end(), p, p + 3);
  }
  return xyz;
}
} // namespace

TEST (PointFileChunks, LasAndPcdGiveTheirPointsAsLoadPointFile)
{
  const std::string dir = freshFolder ("point_file_chunks");
  Eigen::Vector3d origin;
  const pcl::PCLPointCloud2 wall = wallCloud (origin);
  ASSERT_TRUE (pcl_ext::io::savePointFile (dir + "/wall.las", wall, origin));
  ASSERT_TRUE (
      pcl_ext::io::savePointFile (dir + "/wall.pcd", wall, Eigen::Vector3d::Zero()));
  for (const std::string name : {"wall.las", "wall.pcd"}) {
    SCOPED_TRACE (name);
    const std::string path = dir + "/" + name;
    Eigen::Vector3d expected_origin;
    const std::vector<float> expected = loadXyz (path, expected_origin);
    PointFileChunks chunks;
    chunks.open (path);
    EXPECT_EQ (chunks.getPointCount(), 1000u);
    EXPECT_EQ (chunks.getOrigin(), expected_origin);
    Eigen::Vector3d min, max;
    chunks.getBounds (min, max);
    const Eigen::Vector3d shift = name == "wall.las" ? origin : Eigen::Vector3d::Zero();
    EXPECT_NEAR (min.x(), shift.x(), 1e-3);
    EXPECT_NEAR (max.x(), shift.x() + 0.013 * 99, 1e-3);
    EXPECT_NEAR (min.y(), shift.y(), 1e-3);
    EXPECT_NEAR (max.z(), shift.z() + 0.021 * 9, 1e-3);
    // Chunks of 64 (the last one short), then again from the start after rewind().
    EXPECT_EQ (readAllXyz (chunks, 64), expected);
    chunks.rewind();
    EXPECT_EQ (readAllXyz (chunks, 1000), expected);
    // Another origin: the coordinates move by the difference.
    chunks.rewind();
    chunks.setOrigin (expected_origin + Eigen::Vector3d (1.0, 2.0, 0.5));
    const std::vector<float> moved = readAllXyz (chunks, 300);
    ASSERT_EQ (moved.size(), expected.size());
    for (std::size_t i = 0; i < moved.size(); i += 3) {
      EXPECT_NEAR (moved[i], expected[i] - 1.0f, 1e-4);
      EXPECT_NEAR (moved[i + 1], expected[i + 1] - 2.0f, 1e-4);
      EXPECT_NEAR (moved[i + 2], expected[i + 2] - 0.5f, 1e-4);
    }
  }
  // The LAS header goes with the description (what a writer needs to write like it).
  PointFileChunks las;
  las.open (dir + "/wall.las");
  EXPECT_TRUE (las.getDescription().las.has_value());
}

TEST (PointFileChunks, UnreadableInputsAreRefused)
{
  const std::string dir = freshFolder ("point_file_chunks_bad");
  PointFileChunks chunks;
  EXPECT_THROW (chunks.open (dir + "/missing.las"), pcl_ext::io::ReadError);
  std::ofstream (dir + "/short.las", std::ios::binary) << "LASF";
  EXPECT_THROW (chunks.open (dir + "/short.las"), pcl_ext::io::ReadError);
  // A chunk without x y z has no coordinates to tile.
  pcl::PCLPointCloud2 no_xyz;
  pcl::PointCloud<pcl::Intensity> values (3, 1);
  pcl::toPCLPointCloud2 (values, no_xyz);
  EXPECT_THROW (pcl_ext::tiling::xyzOffset (no_xyz), std::invalid_argument);
}
