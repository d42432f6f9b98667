/*
 * pcl_ext: the returns of a simulated scan on its grid of rays, as the passes after the
 * ray casting take them (internal).
 */
#pragma once

#include <pcl_ext/search/kdtree_3f.h>
#include <pcl_ext/simulation/geometry.h>
#include <pcl_ext/simulation/simulated_point.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace simulation {
namespace detail {
/** \brief One azimuth column of one scanner: the unit of work of the ray casting. */
struct ColumnTask {
  int scanner;
  long column; // azimuth index in [0, num_columns)
  long j_min, j_max;
};

/** \brief What the coverage test needs of a return: its row, its noise-free position
 * and the distance to the returns of the neighbouring rays on a continuous surface. */
struct ScanReturn {
  long row;
  Vec3 truth;
  double range;
  double spacing;
  double band;            ///< the truth's edge and boundary distance at this return
  Eigen::Vector3f normal; ///< unit surface normal at the true position
  bool porous; ///< on a porous primitive (vegetation), not a continuous surface
};

/** \brief The points of one column task, in row order. */
using ColumnPoints =
    std::vector<SimulatedPoint, Eigen::aligned_allocator<SimulatedPoint>>;

/** \brief The returns of a scan, task after task, with their neighbours on the grid of
 * rays: the next rows of a column and the next columns of a scanner. */
struct ScanGrid {
  const std::vector<ColumnTask>& tasks;
  long num_columns; ///< columns of a full turn
  long lowest_row;  ///< the lowest row of the field of view (the blind cone below it)
  const std::vector<std::vector<ScanReturn>>& returns; ///< per task, rows ascending

  /** The return of row \a row in task \a task, or null (rows ascend within a task). */
  const ScanReturn*
  find (std::size_t task, long row) const;

  /** The task of the column \a dk columns from task \a k's, same scanner, or -1. */
  long
  adjacentTask (long k, long dk) const;
};

/** Two returns lie on one continuous piece of surface when they are about a spacing
 * apart; a jump of more than 4 spacings is a discontinuity (a shadow, a gap, a
 * silhouette). */
inline bool
continuous (const ScanReturn& a, const ScanReturn& b)
{
  return (a.truth - b.truth).norm() <= 4.0 * std::max (a.spacing, b.spacing);
}

/** All returns in one numbering, task after task, for the searches across tasks and
 * scanners. */
struct ReturnIndex {
  std::vector<std::size_t> first; ///< where each task's returns start; last: count
  std::vector<const ScanReturn*> of_point;
  std::vector<std::uint32_t>
      surface_of_point; ///< segment id before any split into pieces
  std::vector<std::uint32_t> task_of_point;
  bool several_scanners = false; ///< the tasks come from more than one scanner
  search::KdTree3f tree;         ///< over the true positions, when built
};

/** Number the returns of \a grid (their segment ids from \a points) in \a index; the
 * tree is built when \a with_tree is set or the returns come from several scanners. */
void
buildReturnIndex (const ScanGrid& grid,
                  const std::vector<ColumnPoints>& points,
                  bool with_tree,
                  ReturnIndex& index);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
