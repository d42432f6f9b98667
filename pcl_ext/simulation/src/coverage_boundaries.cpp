/*
 * pcl_ext: the borders of the scanned part of each surface in a simulated scan
 * (internal).
 */
#include "coverage_boundaries.h"

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/point_types.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace simulation {
namespace detail {
namespace {
/** The borders of each scan by itself (see markCoverageBoundaries), per return; false
 * when there is none. */
bool
findScanBorders (const ScanGrid& grid,
                 unsigned int threads,
                 const std::vector<ColumnPoints>& points,
                 std::vector<std::vector<std::uint8_t>>& scan_borders)
{
  const auto& returns = grid.returns;
  const long num_tasks = static_cast<long> (grid.tasks.size());
  scan_borders.assign (grid.tasks.size(), {});
  for (long k = 0; k < num_tasks; ++k)
    scan_borders[k].assign (returns[k].size(), 0);
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads))
  for (long k = 0; k < num_tasks; ++k) {
    const long left = grid.adjacentTask (k, -1), right = grid.adjacentTask (k, 1);
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      if (points[k][i].point_class != static_cast<std::uint32_t> (PointClass::Surface))
        continue;
      const ScanReturn& r = returns[k][i];
      bool border = r.row - 1 < grid.lowest_row;
      // A porous surface (vegetation) lets rays through its gaps: a missing return
      // there is no border of what was scanned.
      const auto check = [&] (const ScanReturn* n) {
        border = border || (n ? !continuous (*n, r) : !r.porous);
      };
      check (grid.find (static_cast<std::size_t> (k), r.row - 1));
      check (grid.find (static_cast<std::size_t> (k), r.row + 1));
      check (left < 0 ? nullptr : grid.find (static_cast<std::size_t> (left), r.row));
      check (right < 0 ? nullptr : grid.find (static_cast<std::size_t> (right), r.row));
      scan_borders[k][i] = border;
    }
  }
  for (const auto& column : scan_borders)
    if (std::find (column.begin(), column.end(), 1) != column.end())
      return true;
  return false;
}

/** Widest angle around \a r, in its tangent plane, free of the \a found returns of its
 * own \a surface (2 pi when there are none). */
double
widestFreeAngle (const ScanReturn& r,
                 std::uint32_t surface,
                 const pcl::Indices& found,
                 const ReturnIndex& index,
                 std::vector<double>& angles)
{
  const Vec3 n = r.normal.cast<double>();
  const Vec3 u = n.unitOrthogonal(), v = n.cross (u);
  angles.clear();
  for (const auto g : found) {
    const Vec3 d = index.of_point[g]->truth - r.truth;
    if (index.surface_of_point[g] != surface || d.squaredNorm() == 0.0)
      continue;
    angles.push_back (std::atan2 (d.dot (v), d.dot (u)));
  }
  if (angles.empty())
    return 2.0 * M_PI;
  std::sort (angles.begin(), angles.end());
  double widest = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t a = 1; a < angles.size(); ++a)
    widest = std::max (widest, angles[a] - angles[a - 1]);
  return widest;
}

/** Mark as Boundary the scan borders that the returns of all scanners leave open (see
 * markCoverageBoundaries). */
void
markOpenBorders (const ScanGrid& grid,
                 const ReturnIndex& index,
                 unsigned int threads,
                 const std::vector<std::vector<std::uint8_t>>& scan_borders,
                 std::vector<ColumnPoints>& points)
{
  const auto& returns = grid.returns;
  const long num_tasks = static_cast<long> (returns.size());
  // At most this many of the nearest returns: enough to surround a point twice over,
  // and a bound on the work where the spacing is long (grazing incidence).
  constexpr std::size_t kMaxNeighbours = 64;
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads))
  for (long k = 0; k < num_tasks; ++k) {
    pcl::Indices found (kMaxNeighbours);
    std::vector<float> sqr (kMaxNeighbours);
    std::vector<double> angles;
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      if (!scan_borders[k][i])
        continue;
      const ScanReturn& r = returns[k][i];
      const float query[3] = {static_cast<float> (r.truth.x()),
                              static_cast<float> (r.truth.y()),
                              static_cast<float> (r.truth.z())};
      found.resize (kMaxNeighbours);
      found.resize (
          index.tree.nearestKSearch (query, kMaxNeighbours, found.data(), sqr.data()));
      const float reach = static_cast<float> (4.0 * r.spacing);
      std::size_t within = 0;
      while (within < found.size() && sqr[within] <= reach * reach)
        ++within;
      found.resize (within);
      if (widestFreeAngle (r, points[k][i].segment, found, index, angles) > 0.5 * M_PI)
        points[k][i].point_class = static_cast<std::uint32_t> (PointClass::Boundary);
    }
  }
}
} // namespace

void
markCoverageBoundaries (const ScanGrid& grid,
                        const ReturnIndex& index,
                        unsigned int threads,
                        std::vector<ColumnPoints>& points)
{
  std::vector<std::vector<std::uint8_t>> scan_borders;
  if (findScanBorders (grid, threads, points, scan_borders))
    markOpenBorders (grid, index, threads, scan_borders, points);
}
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
