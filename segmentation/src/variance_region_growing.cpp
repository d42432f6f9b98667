/*
 * pcl_ext: the region-growing kernel of Belton & Lichti (2006, section 3) and the
 * precompiled VarianceRegionGrowing for the common point types.
 */
#include <pcl_ext/common/union_find.h>

#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/segmentation/impl/variance_region_growing.hpp>

void
pcl_ext::growSurfaceSegments (const NeighbourRowsView& rows,
                              const pcl::Indices& row_points,
                              const std::vector<std::int8_t>& class_of_point,
                              const std::vector<std::uint32_t>& row_reach,
                              unsigned int threads,
                              std::vector<std::int32_t>& root)
{
  root.clear();
  if (!row_reach.empty() && row_reach.size() != row_points.size())
    return;
  const auto surface = static_cast<std::int8_t> (PointClass::Surface);
  const std::ptrdiff_t num_rows = static_cast<std::ptrdiff_t> (row_points.size());
  const pcl::index_t* const neighbours = rows.indices;

  // 1. The walks, in parallel: how far along its row each seed links (the position of
  //    the first stop). They only read, so any thread count gives the same ends.
  std::vector<std::uint32_t> end (row_points.size(), 0);
#pragma omp parallel for num_threads(resolveThreadCount(threads))                      \
    schedule(dynamic, 2048) default(none) shared(rows,                                 \
                                                 neighbours,                           \
                                                 row_points,                           \
                                                 class_of_point,                       \
                                                 row_reach,                            \
                                                 end,                                  \
                                                 num_rows,                             \
                                                 surface)
  for (std::ptrdiff_t r = 0; r < num_rows; ++r) {
    if (class_of_point[row_points[r]] != surface)
      continue;
    const std::size_t first = rows.begin (r);
    std::size_t count = rows.size (r);
    if (!row_reach.empty())
      count = std::min<std::size_t> (count, row_reach[r]);
    std::size_t m = first;
    for (; m < first + count; ++m) {
      const std::int8_t c = class_of_point[neighbours[m]];
      if (c != surface && c >= 0)
        break;
    }
    end[r] = static_cast<std::uint32_t> (m - first);
  }

  // 2. The joins and merges. Both put seed and neighbour in one set, so the sets are
  //    the connected components of the links whatever the order; uniting them in row
  //    order in one thread keeps the union-find simple (its root is the smallest point
  //    index, whatever order the unions come in).
  UnionFind sets (class_of_point.size());
  for (std::ptrdiff_t r = 0; r < num_rows; ++r) {
    const auto seed = static_cast<std::uint32_t> (row_points[r]);
    const std::size_t first = rows.begin (r);
    for (std::size_t m = first; m < first + end[r]; ++m)
      if (class_of_point[neighbours[m]] == surface)
        sets.unite (seed, static_cast<std::uint32_t> (neighbours[m]));
  }

  root.assign (class_of_point.size(), -1);
  for (std::ptrdiff_t r = 0; r < num_rows; ++r) {
    const auto p = static_cast<std::uint32_t> (row_points[r]);
    if (class_of_point[p] == surface)
      root[p] = static_cast<std::int32_t> (sets.find (p));
  }
}

PCL_EXT_INSTANTIATE (VarianceRegionGrowing, PCL_EXT_XYZ_POINT_TYPES)
