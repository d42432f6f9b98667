/*
 * TilePlan: the plan of several inputs (counts, global indices, origin, box), its text
 * file, the suggested tile size, and plans that must be refused.
 */
#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_points.h>

#include "../io/temp_folder.h"

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

using namespace pcl_ext::tiling;

namespace {
/** \a n points on a line from \a from along x, 0.1 m apart, saved as PCD. */
std::string
lineFile (const std::string& path, int n, const Eigen::Vector3f& from)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < n; ++i)
    cloud.push_back (pcl::PointXYZ (from.x() + 0.1f * i, from.y(), from.z()));
  EXPECT_EQ (pcl::io::savePCDFileBinary (path, cloud), 0);
  return path;
}
} // namespace

TEST (TilePlan, TwoInputsAreNumberedOneAfterTheOther)
{
  const std::string dir = freshFolder ("tile_plan");
  const std::string a = lineFile (dir + "/a.pcd", 100, {0.f, 0.f, 1.f}); // x 0 - 9.9
  const std::string b = lineFile (dir + "/b.pcd", 50, {0.f, 12.f, 1.f}); // y 12
  TilePlan plan;
  ASSERT_TRUE (planTiles ({a, b}, 5.0, 0.5, plan));
  EXPECT_EQ (plan.inputs, (std::vector<std::string>{a, b}));
  EXPECT_EQ (plan.counts, (std::vector<std::uint64_t>{100, 50}));
  EXPECT_EQ (plan.getTotalPoints(), 150u);
  EXPECT_EQ (plan.getFirstIndex (0), 0u);
  EXPECT_EQ (plan.getFirstIndex (1), 100u);
  // The box of both inputs, widened by a centimetre for float rounding.
  EXPECT_NEAR (plan.min.x(), 0.0 - 0.01, 1e-5);
  EXPECT_NEAR (plan.max.x(), 9.9 + 0.01, 1e-5);
  EXPECT_NEAR (plan.min.y(), 0.0 - 0.01, 1e-5);
  EXPECT_NEAR (plan.max.y(), 12.0 + 0.01, 1e-5);
  const TileGrid grid = plan.getGrid();
  ASSERT_TRUE (grid.isValid());

  // Every point goes to exactly one tile's core.
  ASSERT_TRUE (writeTiles (plan, dir));
  std::vector<int> owned (plan.getTotalPoints(), 0);
  for (std::size_t t = 0; t < grid.size(); ++t) {
    std::vector<TilePoint> points;
    ASSERT_TRUE (readTilePoints (dir, t, points));
    for (const auto& p : points)
      if (p.owner == t)
        ++owned[p.index];
  }
  for (std::size_t i = 0; i < owned.size(); ++i)
    EXPECT_EQ (owned[i], 1) << "point " << i;

  // The text file keeps everything, the settings included.
  plan.settings["method"] = "segment_variance";
  plan.settings["median_curvature"] = "0.00123";
  ASSERT_TRUE (saveTilePlan (dir + "/plan.txt", plan));
  TilePlan again;
  ASSERT_TRUE (loadTilePlan (dir + "/plan.txt", again));
  EXPECT_EQ (again.inputs, plan.inputs);
  EXPECT_EQ (again.counts, plan.counts);
  EXPECT_EQ (again.origin, plan.origin);
  EXPECT_EQ (again.min, plan.min);
  EXPECT_EQ (again.max, plan.max);
  EXPECT_EQ (again.tile_size, plan.tile_size);
  EXPECT_EQ (again.halo, plan.halo);
  EXPECT_EQ (again.settings, plan.settings);
}

TEST (TilePlan, SuggestedTileSizeHoldsAboutTheAskedPoints)
{
  // 100 m x 100 m, 1e6 points, 1e5 a tile: 1,000 m2 a tile, a side of 31.6 m, rounded
  // up to 1, 2 or 5 times a power of ten.
  EXPECT_DOUBLE_EQ (suggestTileSize ({0.0, 0.0}, {100.0, 100.0}, 1000000, 100000),
                    50.0);
  EXPECT_DOUBLE_EQ (suggestTileSize ({0.0, 0.0}, {100.0, 100.0}, 1000000, 10000), 10.0);
  EXPECT_DOUBLE_EQ (suggestTileSize ({0.0, 0.0}, {100.0, 100.0}, 1000000, 40000), 20.0);
}

TEST (TilePlan, FittedTileSizeKeepsTheDensestTileWithinTheLimit)
{
  // 100 m x 100 m at 1 point a square metre, and 4,000 more points in the square metre
  // (30, 30) - (31, 31), as near a scanner: 14,000 points, at most 5,000 a tile. A
  // uniform density gives 100 m tiles (all points in one). The fitted size is a
  // multiple of 5 m cells (a sixteenth of 100 m, rounded down to 1, 2 or 5 times a
  // power of ten): 30 m, whose tile [30, 60) holds the dense square and 900 others; at
  // 35 m the tile [0, 35) holds it and 1,225 others, too many.
  const std::string dir = freshFolder ("tile_plan_fit");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x)
      cloud.push_back (pcl::PointXYZ (x + 0.5f, y + 0.5f, 0.0f));
  for (int i = 0; i < 4000; ++i)
    cloud.push_back (
        pcl::PointXYZ (30.1f + 0.012f * (i % 64), 30.1f + 0.012f * (i / 64), 1.0f));
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir + "/dense.pcd", cloud), 0);
  TilePlan plan;
  ASSERT_TRUE (planTiles ({dir + "/dense.pcd"}, 1e9, 0.0, plan));
  EXPECT_DOUBLE_EQ (suggestTileSize (plan.min, plan.max, 14000, 5000), 100.0);
  const auto densest = [&cloud] (double s) {
    std::map<std::pair<long, long>, int> tiles;
    int most = 0;
    for (const auto& p : cloud)
      most = std::max (most,
                       ++tiles[{static_cast<long> (std::floor (p.x / s)),
                                static_cast<long> (std::floor (p.y / s))}]);
    return most;
  };
  const double size = fitTileSize (plan, 5000);
  EXPECT_DOUBLE_EQ (size, 30.0);
  EXPECT_EQ (densest (30.0), 4900);
  EXPECT_EQ (densest (35.0), 5225);
  // Where no size fits (a limit below the dense square's points), the cell: 2 m for
  // 3,000 a tile (a uniform density gives 50 m).
  EXPECT_DOUBLE_EQ (fitTileSize (plan, 3000), 2.0);
}

TEST (TilePlan, InputsFarApartAreRefused)
{
  const std::string dir = freshFolder ("tile_plan_far");
  const std::string a = lineFile (dir + "/a.pcd", 10, {0.f, 0.f, 0.f});
  const std::string b = lineFile (dir + "/b.pcd", 10, {2.0e6f, 0.f, 0.f});
  TilePlan plan;
  testing::internal::CaptureStderr();
  EXPECT_FALSE (planTiles ({a, b}, 5.0, 0.5, plan));
  EXPECT_FALSE (planTiles ({a}, std::nan (""), 0.5, plan));
  std::ofstream (dir + "/bad.txt") << "pcl_ext tile plan 1\ntile_size nonsense\n";
  EXPECT_FALSE (loadTilePlan (dir + "/bad.txt", plan));
  testing::internal::GetCapturedStderr();
}

TEST (TilePlan, RelativeInputsAreKeptAsAbsolutePaths)
{
  const std::string dir = freshFolder ("tile_plan_relative");
  lineFile (dir + "/a.pcd", 10, {0.f, 0.f, 0.f});
  char cwd[4096];
  ASSERT_NE (::getcwd (cwd, sizeof (cwd)), nullptr);
  ASSERT_EQ (::chdir (dir.c_str()), 0);
  TilePlan plan;
  const bool planned = planTiles ({"a.pcd"}, 5.0, 0.5, plan);
  char here[4096];
  const bool known = ::getcwd (here, sizeof (here)) != nullptr;
  ASSERT_EQ (::chdir (cwd), 0);
  ASSERT_TRUE (planned);
  ASSERT_TRUE (known);
  ASSERT_EQ (plan.inputs.size(), 1u);
  EXPECT_EQ (plan.inputs[0], std::string (here) + "/a.pcd");
  // Read from another working folder: the tiles' cores hold the input's ten points.
  ASSERT_TRUE (writeTiles (plan, dir));
  std::size_t owned = 0;
  for (std::size_t t = 0; t < plan.getGrid().size(); ++t) {
    std::vector<TilePoint> tile;
    ASSERT_TRUE (readTilePoints (dir, t, tile));
    owned += std::count_if (
        tile.begin(), tile.end(), [t] (const TilePoint& p) { return p.owner == t; });
  }
  EXPECT_EQ (owned, 10u);
}
