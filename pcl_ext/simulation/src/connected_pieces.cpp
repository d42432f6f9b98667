/*
 * pcl_ext: the connected visible pieces of each surface in a simulated scan (internal).
 */
#include "connected_pieces.h"

#include <pcl_ext/common/parallel.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace pcl_ext {
namespace simulation {
namespace detail {
namespace {
/** Split-off pieces smaller than this keep their surface's id. */
constexpr std::uint32_t kMinPiecePoints = 10;
} // namespace

void
splitSegmentsIntoPieces (const ScanGrid& grid,
                         const ReturnIndex& index,
                         unsigned int threads,
                         std::vector<ColumnPoints>& points,
                         std::vector<std::uint32_t>& surface_of_segment)
{
  const auto& tasks = grid.tasks;
  const auto& returns = grid.returns;
  const long num_tasks = static_cast<long> (tasks.size());
  const std::vector<std::size_t>& first = index.first;
  const std::size_t n = first.back();
  if (n == 0)
    return;

  // Links, collected per task in parallel, united in task order.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links (
      tasks.size());
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads))
  for (long k = 0; k < num_tasks; ++k) {
    const long right = grid.adjacentTask (k, 1);
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      const ScanReturn& r = returns[k][i];
      const std::uint32_t segment = points[k][i].segment;
      const auto link = [&] (long m, long row) {
        if (m < 0)
          return;
        const ScanReturn* other = grid.find (static_cast<std::size_t> (m), row);
        if (!other)
          return;
        const std::size_t j = static_cast<std::size_t> (other - returns[m].data());
        if (points[m][j].segment == segment && continuous (r, *other))
          links[k].emplace_back (static_cast<std::uint32_t> (first[k] + i),
                                 static_cast<std::uint32_t> (first[m] + j));
      };
      link (k, r.row + 1);
      link (right, r.row);
    }
  }

  // Returns of different scanners within both spacings.
  if (index.several_scanners) {
    const auto& of_point = index.of_point;
    const auto& surface_of_point = index.surface_of_point;
    const auto& task_of_point = index.task_of_point;
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads))
    for (long k = 0; k < num_tasks; ++k) {
      pcl::Indices found;
      std::vector<float> sqr;
      for (std::size_t i = 0; i < returns[k].size(); ++i) {
        const std::size_t p = first[k] + i;
        const ScanReturn& r = returns[k][i];
        const float query[3] = {static_cast<float> (r.truth.x()),
                                static_cast<float> (r.truth.y()),
                                static_cast<float> (r.truth.z())};
        index.tree.radiusSearch (query, r.spacing, found, sqr, 0, false);
        for (std::size_t f = 0; f < found.size(); ++f) {
          const auto q = static_cast<std::size_t> (found[f]);
          if (q <= p || surface_of_point[q] != surface_of_point[p] ||
              tasks[task_of_point[q]].scanner == tasks[k].scanner)
            continue;
          const double d = (of_point[q]->truth - r.truth).norm();
          if (d <= r.spacing && d <= of_point[q]->spacing)
            links[k].emplace_back (static_cast<std::uint32_t> (p),
                                   static_cast<std::uint32_t> (q));
        }
      }
    }
  }

  std::vector<std::uint32_t> parent (n);
  std::iota (parent.begin(), parent.end(), 0u);
  const auto root = [&parent] (std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& task_links : links)
    for (const auto& [a, b] : task_links) {
      const std::uint32_t ra = root (a), rb = root (b);
      if (ra != rb)
        parent[std::max (ra, rb)] = std::min (ra, rb);
    }
  decltype (links)().swap (links);

  // Pieces by root (the smallest point of the piece), sizes, and the largest of each
  // surface.
  std::vector<std::uint32_t> segment (n), size (n, 0);
  std::uint32_t highest = 0;
  for (long k = 0; k < num_tasks; ++k)
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      segment[first[k] + i] = points[k][i].segment;
      highest = std::max (highest, points[k][i].segment);
    }
  for (std::uint32_t p = 0; p < n; ++p)
    ++size[root (p)];
  std::map<std::uint32_t, std::uint32_t>
      largest; // surface -> root of its largest piece
  std::map<std::uint32_t, bool> porous;
  for (long k = 0; k < num_tasks; ++k)
    for (const ScanReturn& r : returns[k])
      if (r.porous)
        porous[segment[first[k] + (&r - returns[k].data())]] = true;
  for (std::uint32_t p = 0; p < n; ++p)
    if (root (p) == p) {
      const auto it = largest.find (segment[p]);
      if (it == largest.end() || size[p] > size[it->second])
        largest[segment[p]] = p; // roots ascend: ties keep the first piece
    }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> others; // (surface, root)
  std::vector<std::uint32_t> id (n, 0);
  for (std::uint32_t p = 0; p < n; ++p)
    if (root (p) == p) {
      if (largest[segment[p]] == p || size[p] < kMinPiecePoints ||
          porous.count (segment[p]))
        id[p] = segment[p];
      else
        others.emplace_back (segment[p], p);
    }
  std::sort (others.begin(), others.end());
  surface_of_segment.assign (highest + 1 + others.size(), 0);
  for (std::uint32_t s = 1; s <= highest; ++s)
    surface_of_segment[s] = s;
  for (std::size_t o = 0; o < others.size(); ++o) {
    id[others[o].second] = highest + 1 + static_cast<std::uint32_t> (o);
    surface_of_segment[highest + 1 + o] = others[o].first;
  }
  for (long k = 0; k < num_tasks; ++k)
    for (std::size_t i = 0; i < returns[k].size(); ++i)
      points[k][i].segment = id[root (static_cast<std::uint32_t> (first[k] + i))];
}
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
