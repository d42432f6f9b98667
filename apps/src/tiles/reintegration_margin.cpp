/*
 * pcl_ext_tiles: how wide a margin a tile needs for Belton & Lichti's re-integration
 * (section 4) of its core points to be that of the whole cloud.
 */
#include "reintegration_margin.h"

#include <pcl_ext/point_types.h>
#include <pcl_ext/tiling/segment_merge.h>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace apps {
namespace {
/** Square cells over a box of the plane, each holding the largest value given to it. */
class MaxGrid {
public:
  /** Cells of side \a cell (at least 1/1024 of the box's longer side) over the box
   * [min_x, max_x] x [min_y, max_y]. */
  MaxGrid (double min_x, double min_y, double max_x, double max_y, double cell)
  : min_x_ (min_x), min_y_ (min_y)
  {
    cell_ = std::max ({cell, std::max (max_x - min_x, max_y - min_y) / 1024.0, 1e-6});
    columns_ = static_cast<std::size_t> ((max_x - min_x) / cell_) + 1;
    rows_ = static_cast<std::size_t> ((max_y - min_y) / cell_) + 1;
    max_.assign (columns_ * rows_, 0.0f);
  }

  /** Raise the cells the square of half-side \a half around (x, y) touches to
   * \a value. */
  void
  raise (double x, double y, double half, float value)
  {
    const std::size_t c0 = column (x - half), c1 = column (x + half);
    const std::size_t r0 = row (y - half), r1 = row (y + half);
    for (std::size_t r = r0; r <= r1; ++r)
      for (std::size_t c = c0; c <= c1; ++c)
        max_[c + columns_ * r] = std::max (max_[c + columns_ * r], value);
  }

  /** The largest value of the cells the square of half-side \a half around (x, y)
   * touches. */
  double
  maxAround (double x, double y, double half) const
  {
    const std::size_t c0 = column (x - half), c1 = column (x + half);
    const std::size_t r0 = row (y - half), r1 = row (y + half);
    float m = 0.0f;
    for (std::size_t r = r0; r <= r1; ++r)
      for (std::size_t c = c0; c <= c1; ++c)
        m = std::max (m, max_[c + columns_ * r]);
    return m;
  }

private:
  std::size_t
  index (double v, double min, std::size_t count) const
  {
    const double c = std::floor ((v - min) / cell_);
    return c <= 0.0
               ? 0
               : std::min (count - 1, static_cast<std::size_t> (std::min (c, 1e15)));
  }

  std::size_t
  column (double x) const
  {
    return index (x, min_x_, columns_);
  }

  std::size_t
  row (double y) const
  {
    return index (y, min_y_, rows_);
  }

  double min_x_, min_y_, cell_ = 1.0;
  std::size_t columns_ = 0, rows_ = 0;
  std::vector<float> max_;
};

/** Distance in the plane from (x, y) to the box [min, max]. */
double
distanceToBox (double x,
               double y,
               const Eigen::Vector2d& min,
               const Eigen::Vector2d& max)
{
  const double dx = std::max ({min.x() - x, 0.0, x - max.x()});
  const double dy = std::max ({min.y() - y, 0.0, y - max.y()});
  return std::sqrt (dx * dx + dy * dy);
}

/** Whether the surface point \a i of a segment has a neighbour that is not a surface
 * point of its segment (LocalSurfaceIntersection's border points, which find the local
 * intersections). */
bool
isBorderPoint (const pcl_ext::Neighbourhoods<pcl::PointXYZ>& nb,
               const std::vector<std::uint32_t>& segments,
               const std::vector<std::uint32_t>& classes,
               std::size_t i)
{
  const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
  if (row < 0)
    return false;
  const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
  for (const pcl::index_t j : nb[static_cast<std::size_t> (row)]) {
    const auto k = static_cast<std::size_t> (j);
    if (segments[k] != segments[i] || classes[k] != surface)
      return true;
  }
  return false;
}

/** A tile whose points the tile did not all load, with its largest radius. */
struct Unloaded {
  Eigen::Vector2d min, max; ///< its core box, in the tile cloud's coordinates
  double radius = 0.0;
};
} // namespace

double
neighbourhoodRadius (const pcl_ext::Neighbourhoods<pcl::PointXYZ>& nb, std::size_t i)
{
  const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
  if (row < 0 || nb[static_cast<std::size_t> (row)].size() == 0)
    return 0.0;
  const std::size_t last = nb[static_cast<std::size_t> (row)].size() - 1;
  return std::sqrt (static_cast<double> (
      nb.getSquaredDistance (static_cast<std::size_t> (row), last)));
}

double
neededReintegrationMargin (const TileCloud& tile,
                           const std::vector<std::uint32_t>& segments,
                           const std::vector<std::uint32_t>& classes,
                           const std::vector<float>& tile_radii,
                           double reach_factor,
                           bool intersections)
{
  if (!tile.cloud || !tile.neighbourhoods || tile.neighbourhoods->empty())
    return 0.0;
  const auto& cloud = *tile.cloud;
  const auto& nb = *tile.neighbourhoods;
  const double f = reach_factor;
  const auto radius = [&nb] (std::size_t i) { return neighbourhoodRadius (nb, i); };
  const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
  const auto edge = static_cast<std::uint32_t> (PointClass::Edge);
  const auto boundary = static_cast<std::uint32_t> (PointClass::Boundary);

  // The surface points in a segment (the border points among them) and the points to
  // re-integrate.
  std::vector<std::size_t> segmented, examined;
  std::vector<float> radii;
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0, largest_own = 0.0;
  bool any = false;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!pcl::isFinite (cloud[i]))
      continue;
    const bool in_segment = segments[i] != tiling::SegmentMerge::kNoSegment;
    const bool is_segmented = in_segment && classes[i] == surface;
    const bool is_examined =
        tile.core[i] &&
        ((!in_segment && (classes[i] == edge || classes[i] == boundary)) ||
         (intersections && is_segmented && isBorderPoint (nb, segments, classes, i)));
    if (!is_segmented && !is_examined)
      continue;
    min_x = any ? std::min<double> (min_x, cloud[i].x) : cloud[i].x;
    max_x = any ? std::max<double> (max_x, cloud[i].x) : cloud[i].x;
    min_y = any ? std::min<double> (min_y, cloud[i].y) : cloud[i].y;
    max_y = any ? std::max<double> (max_y, cloud[i].y) : cloud[i].y;
    any = true;
    if (is_segmented) {
      segmented.push_back (i);
      radii.push_back (static_cast<float> (radius (i)));
    }
    if (is_examined) {
      examined.push_back (i);
      largest_own = std::max (largest_own, radius (i));
    }
  }
  if (examined.empty())
    return 0.0;

  // Cells of about twice the median radius of the segments' points.
  double cell = 0.0;
  if (!radii.empty()) {
    std::vector<float> sorted = radii;
    std::nth_element (sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    cell = 2.0 * sorted[sorted.size() / 2];
  }
  MaxGrid largest_radius (min_x, min_y, max_x, max_y, cell);
  for (std::size_t n = 0; n < segmented.size(); ++n)
    largest_radius.raise (cloud[segmented[n]].x, cloud[segmented[n]].y, 0.0, radii[n]);
  // Over each point a's reach: how far a point whose ball B meets it reads beyond B's
  // centre's reach, 2 F r(a) + R(a).
  MaxGrid beyond (min_x, min_y, max_x, max_y, cell);
  for (std::size_t n = 0; n < segmented.size(); ++n) {
    const auto& a = cloud[segmented[n]];
    const double reach = f * radii[n];
    const double value = 2.0 * reach + largest_radius.maxAround (a.x, a.y, reach);
    beyond.raise (a.x, a.y, reach, static_cast<float> (value));
  }

  // The tiles not loaded whole that a point of theirs could reach B from.
  Eigen::Vector2d core_min, core_max;
  tile.grid.getCoreBox (tile.tile, core_min, core_max);
  const Eigen::Vector2d shift = tile.origin.head<2>();
  const Eigen::Vector2d loaded_min =
      core_min - shift - Eigen::Vector2d::Constant (tile.margin);
  const Eigen::Vector2d loaded_max =
      core_max - shift + Eigen::Vector2d::Constant (tile.margin);
  std::vector<Unloaded> unloaded;
  for (std::size_t u = 0; u < tile.grid.size() && u < tile_radii.size(); ++u) {
    if (!(tile_radii[u] > 0.0f))
      continue;
    Unloaded t;
    tile.grid.getCoreBox (u, t.min, t.max);
    t.min -= shift;
    t.max -= shift;
    t.radius = tile_radii[u];
    if ((t.min.array() >= loaded_min.array()).all() &&
        (t.max.array() <= loaded_max.array()).all())
      continue; // loaded whole: its points are on the grids
    // Distance between the boxes of the core and of the tile.
    const double dx = std::max ({t.min.x() - (core_max.x() - shift.x()),
                                 0.0,
                                 (core_min.x() - shift.x()) - t.max.x()});
    const double dy = std::max ({t.min.y() - (core_max.y() - shift.y()),
                                 0.0,
                                 (core_min.y() - shift.y()) - t.max.y()});
    if (std::sqrt (dx * dx + dy * dy) <= f * (largest_own + t.radius))
      unloaded.push_back (t);
  }

  double short_by = -std::numeric_limits<double>::infinity();
  for (const std::size_t i : examined) {
    const auto& q = cloud[i];
    const double space = tile.getReach (q.x, q.y);
    if (std::isinf (space))
      continue;
    const double reach = f * radius (i);
    const double needed = reach + beyond.maxAround (q.x, q.y, reach);
    short_by = std::max (short_by, needed - space);
    for (const auto& t : unloaded) {
      // Its points lie beyond the loaded data and in its box.
      const double to_reach = reach + f * t.radius;
      if (std::max (space, distanceToBox (q.x, q.y, t.min, t.max)) <= to_reach)
        short_by = std::max (short_by, to_reach - space);
    }
  }
  return std::max (0.0, tile.margin + short_by);
}
} // namespace apps
} // namespace pcl_ext
