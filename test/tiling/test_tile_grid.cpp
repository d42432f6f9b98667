/*
 * TileGrid: every finite point in exactly one core, halos holding what a neighbourhood
 * needs, borders on multiples of the tile size.
 */
#include <pcl_ext/tiling/tile_grid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using pcl_ext::tiling::TileGrid;

TEST (TileGrid, BordersOnMultiplesOfTheTileSize)
{
  const TileGrid grid (
      Eigen::Vector2d (103.0, -7.0), Eigen::Vector2d (251.0, 38.0), 50.0, 2.0);
  ASSERT_TRUE (grid.isValid());
  EXPECT_EQ (grid.getOrigin(), Eigen::Vector2d (100.0, -50.0));
  EXPECT_EQ (grid.getColumns(), 4u); // 100-150-200-250-300: 251 lies in the fourth
  EXPECT_EQ (grid.getRows(), 2u);    // -50-0-50
  EXPECT_EQ (grid.size(), 8u);
  Eigen::Vector2d lo, hi;
  grid.getCoreBox (5, lo, hi);
  EXPECT_EQ (lo, Eigen::Vector2d (150.0, 0.0));
  EXPECT_EQ (hi, Eigen::Vector2d (200.0, 50.0));
  // Half-open cores: a point on a border belongs to the tile above it.
  EXPECT_EQ (grid.getTile (150.0, 0.0), 5u);
  EXPECT_EQ (grid.getTile (149.999, -0.001), 0u);
  EXPECT_EQ (grid.getTile (251.0, 38.0), 7u);
}

TEST (TileGrid, EveryPointInOneCoreAndInTheHalosAroundIt)
{
  const double halo = 1.5;
  const TileGrid grid (
      Eigen::Vector2d (0.0, 0.0), Eigen::Vector2d (40.0, 30.0), 10.0, halo);
  std::mt19937 rng (7);
  std::uniform_real_distribution<double> x (0.0, 40.0), y (0.0, 30.0);
  std::vector<std::size_t> near;
  for (int i = 0; i < 20000; ++i) {
    const double px = x (rng), py = y (rng);
    const std::size_t own = grid.getTile (px, py);
    ASSERT_NE (own, TileGrid::kNoTile);
    std::size_t cores = 0;
    for (std::size_t t = 0; t < grid.size(); ++t) {
      Eigen::Vector2d lo, hi;
      grid.getCoreBox (t, lo, hi);
      const bool core = px >= lo.x() && px < hi.x() && py >= lo.y() && py < hi.y();
      cores += core;
      if (core)
        EXPECT_EQ (t, own);
    }
    EXPECT_EQ (cores, 1u);
    grid.getTilesNear (px, py, near);
    ASSERT_FALSE (near.empty());
    EXPECT_TRUE (std::is_sorted (near.begin(), near.end()));
    EXPECT_NE (std::find (near.begin(), near.end(), own), near.end());
    // Each tile whose core is within the halo in x and y holds the point.
    for (std::size_t t = 0; t < grid.size(); ++t) {
      Eigen::Vector2d lo, hi;
      grid.getCoreBox (t, lo, hi);
      const bool within = px >= lo.x() - halo && px < hi.x() + halo &&
                          py >= lo.y() - halo && py < hi.y() + halo;
      EXPECT_EQ (within, std::find (near.begin(), near.end(), t) != near.end());
    }
  }
  // A corner point is in the halos of four tiles.
  grid.getTilesNear (20.0, 10.0, near);
  EXPECT_EQ (grid.getColumns(), 5u); // x = 40 lies in a fifth column (half-open cores)
  EXPECT_EQ (near, (std::vector<std::size_t>{1, 2, 6, 7}));
}

TEST (TileGrid, ReachIsTheDistanceToTheHalosInnerSides)
{
  const TileGrid grid (
      Eigen::Vector2d (0.0, 0.0), Eigen::Vector2d (29.0, 9.0), 10.0, 2.0);
  ASSERT_EQ (grid.size(), 3u);
  // Tile 1 (x 10-20): its halo runs from 8 to 22; y is not cut (one row).
  EXPECT_DOUBLE_EQ (grid.getReach (1, 15.0, 5.0), 7.0);
  EXPECT_DOUBLE_EQ (grid.getReach (1, 9.0, 5.0), 1.0);
  // Tile 0 has data beyond it on the right only.
  EXPECT_DOUBLE_EQ (grid.getReach (0, 1.0, 5.0), 11.0);
  const TileGrid one (
      Eigen::Vector2d (0.0, 0.0), Eigen::Vector2d (5.0, 5.0), 10.0, 1.0);
  EXPECT_TRUE (std::isinf (one.getReach (0, 2.0, 2.0)));
}

TEST (TileGrid, NonsenseIsInvalidAndNanPointsHaveNoTile)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector2d lo (0.0, 0.0), hi (10.0, 10.0);
  EXPECT_FALSE (TileGrid (lo, hi, 0.0, 1.0).isValid());
  EXPECT_FALSE (TileGrid (lo, hi, -5.0, 1.0).isValid());
  EXPECT_FALSE (TileGrid (lo, hi, nan, 1.0).isValid());
  EXPECT_FALSE (TileGrid (lo, hi, 5.0, -1.0).isValid());
  EXPECT_FALSE (TileGrid (hi, lo, 5.0, 1.0).isValid());
  EXPECT_FALSE (TileGrid (Eigen::Vector2d (nan, 0.0), hi, 5.0, 1.0).isValid());
  EXPECT_FALSE (TileGrid (lo, Eigen::Vector2d (1e12, 1e12), 1e-3, 0.0).isValid());
  EXPECT_EQ (TileGrid().size(), 0u);
  const TileGrid grid (lo, hi, 5.0, 1.0);
  EXPECT_EQ (grid.getTile (nan, 1.0), TileGrid::kNoTile);
  EXPECT_EQ (grid.getTile (-6.0, 1.0), TileGrid::kNoTile);
  std::vector<std::size_t> near{1, 2};
  grid.getTilesNear (nan, 1.0, near);
  EXPECT_TRUE (near.empty());
  // A one-point cloud is one tile.
  const TileGrid point (
      Eigen::Vector2d (3.0, 4.0), Eigen::Vector2d (3.0, 4.0), 5.0, 1.0);
  EXPECT_EQ (point.size(), 1u);
  EXPECT_EQ (point.getTile (3.0, 4.0), 0u);
}

TEST (TileGrid, AWiderMarginWidensTheReach)
{
  // 5 x 5 tiles of 10 m, halo 1 m; tile 12 is the centre one (x 20-30, y 20-30).
  const TileGrid grid (
      Eigen::Vector2d (0.0, 0.0), Eigen::Vector2d (49.0, 49.0), 10.0, 1.0);
  ASSERT_EQ (grid.size(), 25u);
  EXPECT_DOUBLE_EQ (grid.getReach (12, 25.0, 25.0), 6.0);
  EXPECT_DOUBLE_EQ (grid.getReach (12, 25.0, 25.0, 11.0), 16.0);
  EXPECT_DOUBLE_EQ (grid.getReach (12, 21.0, 25.0, 11.0), 12.0);
  EXPECT_TRUE (std::isinf (grid.getReach (12, 25.0, 25.0, 20.0))); // the whole grid
  EXPECT_TRUE (grid.isWithin (12, 9.5, 25.0, 11.0));
  EXPECT_FALSE (grid.isWithin (12, 8.5, 25.0, 11.0));
  std::vector<std::size_t> around;
  grid.getTilesAround (12, 1, around);
  EXPECT_EQ (around, (std::vector<std::size_t>{6, 7, 8, 11, 12, 13, 16, 17, 18}));
  grid.getTilesAround (0, 1, around);
  EXPECT_EQ (around, (std::vector<std::size_t>{0, 1, 5, 6}));
  grid.getTilesAround (0, 0, around);
  EXPECT_EQ (around, (std::vector<std::size_t>{0}));
}
