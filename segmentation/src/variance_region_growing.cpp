/*
 * pcl_ext: the region-growing kernel of Belton & Lichti (2006, section 3) and the
 * precompiled VarianceRegionGrowing for the common point types.
 */
#include <pcl_ext/common/union_find.h>

#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/segmentation/impl/variance_region_growing.hpp>

namespace {
/** The kernel, with the squared distance limit of row r given by limit(r). */
template <typename Limit>
void
growSegments (const std::vector<std::size_t>& offsets,
              const pcl::Indices& neighbours,
              const std::vector<float>& sqr_distances,
              const pcl::Indices& row_points,
              const std::vector<std::int8_t>& class_of_point,
              const Limit& limit,
              unsigned int threads,
              std::vector<std::int32_t>& root)
{
  using pcl_ext::PointClass;
  using pcl_ext::resolveThreadCount;
  const auto surface = static_cast<std::int8_t> (PointClass::Surface);
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (row_points.size());

  // 1. The walks, in parallel: how far along its row each seed links (the position of
  // the
  //    first stop). They only read, so any thread count gives the same ends.
  std::vector<std::uint32_t> end (row_points.size(), 0);
#pragma omp parallel for num_threads(resolveThreadCount(threads))                      \
    schedule(dynamic, 2048) default(none) shared(offsets,                              \
                                                 neighbours,                           \
                                                 sqr_distances,                        \
                                                 row_points,                           \
                                                 class_of_point,                       \
                                                 limit,                                \
                                                 end,                                  \
                                                 rows,                                 \
                                                 surface)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    if (class_of_point[row_points[r]] != surface)
      continue;
    const std::size_t first = offsets[r], last = offsets[r + 1];
    const float max_sqr_distance = limit (r);
    std::size_t m = first;
    for (; m < last; ++m) {
      if (sqr_distances[m] > max_sqr_distance)
        break;
      const std::int8_t c = class_of_point[neighbours[m]];
      if (c != surface && c >= 0)
        break;
    }
    end[r] = static_cast<std::uint32_t> (m - first);
  }

  // 2. The joins and merges. Both put seed and neighbour in one set, so the sets are
  // the
  //    connected components of the links whatever the order; uniting them in row order
  //    in one thread keeps the union-find simple (its root is the smallest point index,
  //    whatever order the unions come in).
  pcl_ext::UnionFind sets (class_of_point.size());
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    const auto seed = static_cast<std::uint32_t> (row_points[r]);
    const std::size_t first = offsets[r];
    for (std::size_t m = first; m < first + end[r]; ++m)
      if (class_of_point[neighbours[m]] == surface)
        sets.unite (seed, static_cast<std::uint32_t> (neighbours[m]));
  }

  root.assign (class_of_point.size(), -1);
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    const auto p = static_cast<std::uint32_t> (row_points[r]);
    if (class_of_point[p] == surface)
      root[p] = static_cast<std::int32_t> (sets.find (p));
  }
}
} // namespace

void
pcl_ext::growSurfaceSegments (const std::vector<std::size_t>& offsets,
                              const pcl::Indices& neighbours,
                              const std::vector<float>& sqr_distances,
                              const pcl::Indices& row_points,
                              const std::vector<std::int8_t>& class_of_point,
                              float max_sqr_distance,
                              unsigned int threads,
                              std::vector<std::int32_t>& root)
{
  growSegments (
      offsets,
      neighbours,
      sqr_distances,
      row_points,
      class_of_point,
      [max_sqr_distance] (std::ptrdiff_t) { return max_sqr_distance; },
      threads,
      root);
}

void
pcl_ext::growSurfaceSegments (const std::vector<std::size_t>& offsets,
                              const pcl::Indices& neighbours,
                              const std::vector<float>& sqr_distances,
                              const pcl::Indices& row_points,
                              const std::vector<std::int8_t>& class_of_point,
                              const std::vector<float>& row_max_sqr_distances,
                              unsigned int threads,
                              std::vector<std::int32_t>& root)
{
  root.clear();
  if (row_max_sqr_distances.size() != row_points.size())
    return;
  growSegments (
      offsets,
      neighbours,
      sqr_distances,
      row_points,
      class_of_point,
      [&row_max_sqr_distances] (std::ptrdiff_t r) { return row_max_sqr_distances[r]; },
      threads,
      root);
}

PCL_EXT_INSTANTIATE (VarianceRegionGrowing, PCL_EXT_XYZ_POINT_TYPES)
