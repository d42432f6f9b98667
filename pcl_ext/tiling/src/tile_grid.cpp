/*
 * pcl_ext: the square tiles of a large cloud, each a half-open core box plus a halo.
 */
#include <pcl_ext/tiling/tile_grid.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace tiling {
namespace {
/** The cell of coordinate \a v on the axis with origin \a o, clamped to the grid. */
std::size_t
cellOf (double v, double o, double size, std::size_t cells)
{
  const double c = std::floor ((v - o) / size);
  if (c < 0.0)
    return 0;
  return std::min (static_cast<std::size_t> (c), cells - 1);
}
} // namespace

TileGrid::TileGrid (const Eigen::Vector2d& min,
                    const Eigen::Vector2d& max,
                    double tile_size,
                    double halo)
{
  if (!min.allFinite() || !max.allFinite() || (min.array() > max.array()).any() ||
      !std::isfinite (tile_size) || !(tile_size > 0.0) || !std::isfinite (halo) ||
      !(halo >= 0.0))
    return;
  const Eigen::Vector2d origin = (min / tile_size).array().floor() * tile_size;
  // Cells up to and including the one holding max (half-open cores).
  const double columns = std::floor ((max.x() - origin.x()) / tile_size) + 1.0;
  const double rows = std::floor ((max.y() - origin.y()) / tile_size) + 1.0;
  if (!(columns * rows <= 4294967296.0))
    return;
  origin_ = origin;
  size_ = tile_size;
  halo_ = halo;
  columns_ = static_cast<std::size_t> (columns);
  rows_ = static_cast<std::size_t> (rows);
}

std::size_t
TileGrid::getTile (double x, double y) const
{
  if (!isValid() || !std::isfinite (x) || !std::isfinite (y))
    return kNoTile;
  const double cx = std::floor ((x - origin_.x()) / size_);
  const double cy = std::floor ((y - origin_.y()) / size_);
  if (cx < 0.0 || cy < 0.0 || cx >= static_cast<double> (columns_) ||
      cy >= static_cast<double> (rows_))
    return kNoTile;
  return static_cast<std::size_t> (cy) * columns_ + static_cast<std::size_t> (cx);
}

void
TileGrid::getCoreBox (std::size_t tile,
                      Eigen::Vector2d& min,
                      Eigen::Vector2d& max) const
{
  const double c = static_cast<double> (tile % columns_);
  const double r = static_cast<double> (tile / columns_);
  min = origin_ + Eigen::Vector2d (c * size_, r * size_);
  max = min + Eigen::Vector2d (size_, size_);
}

void
TileGrid::getTilesNear (double x, double y, std::vector<std::size_t>& tiles) const
{
  tiles.clear();
  const std::size_t own = getTile (x, y);
  if (own == kNoTile)
    return;
  tiles.push_back (own); // whatever rounding does at its borders
  // Candidate cells: those within the halo of the point, then the exact box test.
  const std::size_t c0 = cellOf (x - halo_, origin_.x(), size_, columns_);
  const std::size_t c1 = cellOf (x + halo_, origin_.x(), size_, columns_);
  const std::size_t r0 = cellOf (y - halo_, origin_.y(), size_, rows_);
  const std::size_t r1 = cellOf (y + halo_, origin_.y(), size_, rows_);
  Eigen::Vector2d lo, hi;
  for (std::size_t r = r0; r <= r1; ++r)
    for (std::size_t c = c0; c <= c1; ++c) {
      const std::size_t t = r * columns_ + c;
      getCoreBox (t, lo, hi);
      if (t != own && x >= lo.x() - halo_ && x < hi.x() + halo_ &&
          y >= lo.y() - halo_ && y < hi.y() + halo_)
        tiles.push_back (t);
    }
  std::sort (tiles.begin(), tiles.end());
}

double
TileGrid::getReach (std::size_t tile, double x, double y, double margin) const
{
  Eigen::Vector2d lo, hi;
  getCoreBox (tile, lo, hi);
  if (margin < 0.0)
    margin = halo_;
  lo.array() -= margin;
  hi.array() += margin;
  const Eigen::Vector2d grid_lo = origin_;
  const Eigen::Vector2d grid_hi =
      origin_ + size_ * Eigen::Vector2d (static_cast<double> (columns_),
                                         static_cast<double> (rows_));
  double reach = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 2; ++a) {
    if (lo[a] > grid_lo[a])
      reach = std::min (reach, (a == 0 ? x : y) - lo[a]);
    if (hi[a] < grid_hi[a])
      reach = std::min (reach, hi[a] - (a == 0 ? x : y));
  }
  return reach;
}

bool
TileGrid::isWithin (std::size_t tile, double x, double y, double margin) const
{
  Eigen::Vector2d lo, hi;
  getCoreBox (tile, lo, hi);
  return x >= lo.x() - margin && x < hi.x() + margin && y >= lo.y() - margin &&
         y < hi.y() + margin;
}

void
TileGrid::getTilesAround (std::size_t tile,
                          std::size_t rings,
                          std::vector<std::size_t>& tiles) const
{
  tiles.clear();
  const std::size_t c = tile % columns_, r = tile / columns_;
  const std::size_t c0 = c > rings ? c - rings : 0, r0 = r > rings ? r - rings : 0;
  const std::size_t c1 = std::min (columns_ - 1, c + rings);
  const std::size_t r1 = std::min (rows_ - 1, r + rings);
  for (std::size_t row = r0; row <= r1; ++row)
    for (std::size_t col = c0; col <= c1; ++col)
      tiles.push_back (row * columns_ + col);
}
} // namespace tiling
} // namespace pcl_ext
