/*
 * pcl_ext: proximity chaining of the points of a profile (Sithole & Mapurisa, 4.1.1).
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
proximityEdges (const ProfilePoints& profile,
                double threshold,
                unsigned int neighbours,
                std::vector<LocalEdge>& edges,
                const std::vector<float>* thresholds)
{
  edges.clear();
  const std::size_t n = profile.uv.size();
  if (n < 2 || !(threshold >= 0.0) || neighbours == 0)
    return;
  const std::vector<std::uint32_t> rep = detail::coincidentRepresentatives (profile.uv);
  const detail::ThresholdRings rings (profile.uv, threshold, thresholds);
  const detail::ProfileGrid& grid = rings.grid();
  const std::int64_t max_ring = rings.maxRing();
  const auto limit = [&rings] (std::uint32_t i) { return rings.reach (i); };
  const std::size_t k = neighbours;
  // The k nearest of each point (ties by index), kept sorted by insertion.
  std::vector<std::uint32_t> lists (n * k);
  std::vector<std::uint32_t> sizes (n, 0);
  std::vector<std::pair<float, std::uint32_t>> best;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i)
      continue;
    const float reach_i = limit (i);
    const float r2 = reach_i * reach_i;
    // With local thresholds a link must be within both ends' thresholds: a sparse point
    // does not reach into a dense surface farther than that surface's own links do.
    grid.nearestInRings (
        profile.uv[i],
        k,
        reach_i,
        max_ring,
        [&] (std::uint32_t j, float d2) {
          return j != i && rep[j] == j && d2 <= r2 &&
                 !(thresholds && d2 > limit (j) * limit (j));
        },
        best);
    sizes[i] = static_cast<std::uint32_t> (best.size());
    for (std::size_t m = 0; m < best.size(); ++m)
      lists[i * k + m] = best[m].second;
  }
  // Each link once: i-j is emitted by the smaller index, or by the larger when the
  // smaller did not choose it. Coincident points hang on their representative.
  const auto chose = [&] (std::uint32_t a, std::uint32_t b) {
    return std::find (lists.begin() + a * k, lists.begin() + a * k + sizes[a], b) !=
           lists.begin() + a * k + sizes[a];
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i) {
      edges.push_back ({rep[i], i});
      continue;
    }
    for (std::uint32_t m = 0; m < sizes[i]; ++m) {
      const std::uint32_t j = lists[i * k + m];
      if (j > i)
        edges.push_back ({i, j});
      else if (!chose (j, i))
        edges.push_back ({j, i});
    }
  }
}
} // namespace profiles
} // namespace pcl_ext
