/*
 * pcl_ext: the returns of a simulated scan on its grid of rays (internal).
 */
#include "scan_grid.h"

#include <numeric>
#include <utility>

namespace pcl_ext {
namespace simulation {
namespace detail {
const ScanReturn*
ScanGrid::find (std::size_t task, long row) const
{
  const auto& column = returns[task];
  const auto it = std::lower_bound (
      column.begin(), column.end(), row, [] (const ScanReturn& r, long j) {
        return r.row < j;
      });
  return it != column.end() && it->row == row ? &*it : nullptr;
}

long
ScanGrid::adjacentTask (long k, long dk) const
{
  const long num_tasks = static_cast<long> (tasks.size());
  // Columns of one scanner are consecutive tasks; a full turn wraps around.
  for (long m : {k + dk, k - dk * (num_columns - 1)})
    if (m >= 0 && m < num_tasks && tasks[m].scanner == tasks[k].scanner &&
        (tasks[m].column - tasks[k].column - dk) % num_columns == 0)
      return m;
  return -1;
}

void
buildReturnIndex (const ScanGrid& grid,
                  const std::vector<ColumnPoints>& points,
                  bool with_tree,
                  ReturnIndex& index)
{
  const auto& tasks = grid.tasks;
  const auto& returns = grid.returns;
  for (std::size_t k = 1; k < tasks.size() && !index.several_scanners; ++k)
    index.several_scanners = tasks[k].scanner != tasks[0].scanner;
  with_tree = with_tree || index.several_scanners;
  index.first.assign (returns.size() + 1, 0);
  for (std::size_t k = 0; k < returns.size(); ++k)
    index.first[k + 1] = index.first[k] + returns[k].size();
  const std::size_t n = index.first.back();
  std::vector<float> xyz;
  if (with_tree)
    xyz.reserve (3 * n);
  index.of_point.reserve (n);
  index.surface_of_point.reserve (n);
  index.task_of_point.reserve (n);
  for (std::size_t k = 0; k < returns.size(); ++k)
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      const Vec3& t = returns[k][i].truth;
      if (with_tree)
        xyz.insert (xyz.end(),
                    {static_cast<float> (t.x()),
                     static_cast<float> (t.y()),
                     static_cast<float> (t.z())});
      index.of_point.push_back (&returns[k][i]);
      index.surface_of_point.push_back (points[k][i].segment);
      index.task_of_point.push_back (static_cast<std::uint32_t> (k));
    }
  if (with_tree && n > 0) {
    std::vector<pcl::index_t> ids (n);
    std::iota (ids.begin(), ids.end(), 0);
    index.tree.build (std::move (xyz), std::move (ids));
  }
}
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
