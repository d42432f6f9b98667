/*
 * pcl_ext: the creases of a simulated scan that it saw from one side only (internal).
 */
#include "one_sided_creases.h"

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/point_types.h>

#include <algorithm>

namespace pcl_ext {
namespace simulation {
namespace detail {
void
markOneSidedCreases (const ScanGrid& grid,
                     const ReturnIndex& index,
                     const SceneGeometry& geometry,
                     unsigned int threads,
                     std::vector<ColumnPoints>& points)
{
  const auto& returns = grid.returns;
  const long num_tasks = static_cast<long> (returns.size());
  const auto edge = static_cast<std::uint32_t> (PointClass::Edge);
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads))
  for (long k = 0; k < num_tasks; ++k) {
    pcl::Indices found;
    std::vector<float> sqr;
    std::vector<std::uint32_t> others;
    for (std::size_t i = 0; i < returns[k].size(); ++i) {
      SimulatedPoint& p = points[k][i];
      const ScanReturn& r = returns[k][i];
      if (p.point_class != edge || r.porous)
        continue;
      others.clear();
      geometry.creaseFacesNear (r.truth, p.segment, r.band, others);
      if (others.empty())
        continue;
      const float query[3] = {static_cast<float> (r.truth.x()),
                              static_cast<float> (r.truth.y()),
                              static_cast<float> (r.truth.z())};
      index.tree.radiusSearch (query, 4.0 * r.spacing, found, sqr, 0, false);
      const bool seen = std::any_of (found.begin(), found.end(), [&] (pcl::index_t g) {
        return std::find (others.begin(), others.end(), index.surface_of_point[g]) !=
               others.end();
      });
      if (!seen)
        p.point_class = static_cast<std::uint32_t> (PointClass::Boundary);
    }
  }
}
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
