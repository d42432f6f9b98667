/*
 * pcl_ext: the local gaps of a profile, for link thresholds that follow the point
 * density.
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "coincident_points.h"
#include "profile_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pcl_ext {
namespace profiles {
void
localGaps (const ProfilePoints& profile,
           double max_distance,
           unsigned int neighbours,
           std::vector<float>& gaps)
{
  const std::size_t n = profile.uv.size();
  const float cap = static_cast<float> (max_distance);
  gaps.assign (n, cap);
  if (n < 2 || !(cap > 0.f) || !std::isfinite (cap) || neighbours == 0)
    return;
  const std::vector<std::uint32_t> rep = detail::coincidentRepresentatives (profile.uv);
  // Small cells searched ring by ring, as for proximity chaining: dense stretches stop
  // after the first rings.
  detail::ProfileGrid grid;
  grid.build (profile.uv, cap / 16.f);
  const std::int64_t max_ring =
      static_cast<std::int64_t> (std::ceil (cap / grid.cellSize())) + 1;
  const std::size_t m = neighbours;
  const float cap2 = cap * cap;

  // The m nearest distinct points of each representative within the cap (ties by
  // index), and its nearest-neighbour gap: the distance to the first of them (the cap
  // when none).
  std::vector<std::uint32_t> lists (n * m);
  std::vector<std::uint32_t> sizes (n, 0);
  std::vector<float> gap (n, cap);
  std::vector<std::pair<float, std::uint32_t>> best;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i)
      continue;
    grid.nearestInRings (
        profile.uv[i],
        m,
        cap,
        max_ring,
        [&] (std::uint32_t j, float d2) { return j != i && rep[j] == j && d2 <= cap2; },
        best);
    sizes[i] = static_cast<std::uint32_t> (best.size());
    for (std::size_t k = 0; k < best.size(); ++k)
      lists[i * m + k] = best[k].second;
    if (!best.empty())
      gap[i] = std::sqrt (best.front().first);
  }
  // The local gap is the median over the point and its neighbours: one wide gap (a
  // chain's end, a hole) does not lengthen it, a sparse stretch of chain does.
  std::vector<float> values;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i)
      continue;
    values.assign (1, gap[i]);
    for (std::uint32_t k = 0; k < sizes[i]; ++k)
      values.push_back (gap[lists[i * m + k]]);
    const auto middle = values.begin() + values.size() / 2;
    std::nth_element (values.begin(), middle, values.end());
    gaps[i] = *middle;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    gaps[i] = gaps[rep[i]];
}
} // namespace profiles
} // namespace pcl_ext
