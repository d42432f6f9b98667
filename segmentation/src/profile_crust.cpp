/*
 * pcl_ext: curve reconstruction of the points of a profile (Sithole & Mapurisa, section
 * 5.2: the profiles of the nested spheres), by the nearest-neighbour crust.
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
crustEdges (const ProfilePoints& profile,
            double threshold,
            std::vector<LocalEdge>& edges,
            const std::vector<float>* thresholds)
{
  edges.clear();
  const std::size_t n = profile.uv.size();
  if (n < 2 || !(threshold >= 0.0))
    return;
  const std::vector<std::uint32_t> rep = detail::coincidentRepresentatives (profile.uv);
  const detail::ThresholdRings rings (profile.uv, threshold, thresholds);
  const detail::ProfileGrid& grid = rings.grid();
  const std::int64_t max_ring = rings.maxRing();
  const auto limit = [&rings] (std::uint32_t i) { return rings.reach (i); };
  std::vector<std::pair<float, std::uint32_t>> best;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i) {
      edges.push_back ({rep[i], i}); // coincident points hang on their representative
      continue;
    }
    const Eigen::Vector2f& p = profile.uv[i];
    const float reach = limit (i);
    const auto within = [&] (std::uint32_t j, float d2) {
      return j != i && rep[j] == j && d2 <= reach * reach &&
             !(thresholds && d2 > limit (j) * limit (j));
    };
    // The nearest neighbour q: an edge of the curve through p when the sampling is
    // dense enough (Dey & Kumar 1999, lemma 1).
    grid.nearestInRings (p, 1, reach, max_ring, within, best);
    if (best.empty())
      continue;
    const std::uint32_t q = best.front().second;
    edges.push_back ({std::min (i, q), std::max (i, q)});
    // The half neighbour: the nearest point on the other side of p from q (the angle
    // q-p-s above 90 degrees), the curve's other edge at p. A point with none ends its
    // curve.
    const Eigen::Vector2f pq = profile.uv[q] - p;
    grid.nearestInRings (
        p,
        1,
        reach,
        max_ring,
        [&] (std::uint32_t j, float d2) {
          return within (j, d2) && (profile.uv[j] - p).dot (pq) < 0.f;
        },
        best);
    if (!best.empty()) {
      const std::uint32_t s = best.front().second;
      edges.push_back ({std::min (i, s), std::max (i, s)});
    }
  }
  std::sort (edges.begin(), edges.end(), [] (const LocalEdge& x, const LocalEdge& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
  edges.erase (std::unique (edges.begin(),
                            edges.end(),
                            [] (const LocalEdge& x, const LocalEdge& y) {
                              return x.a == y.a && x.b == y.b;
                            }),
               edges.end());
}
} // namespace profiles
} // namespace pcl_ext
