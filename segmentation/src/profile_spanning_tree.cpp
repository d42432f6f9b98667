/*
 * pcl_ext: minimum spanning tree segmentation of the points of a profile (Sithole &
 * Mapurisa, section 3).
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "coincident_points.h"
#include "profile_grid.h"
#include <pcl_ext/common/union_find.h>

#include <algorithm>

namespace pcl_ext {
namespace profiles {
void
spanningTreeEdges (const ProfilePoints& profile,
                   double threshold,
                   std::vector<LocalEdge>& edges,
                   const std::vector<float>* thresholds)
{
  edges.clear();
  const std::size_t n = profile.uv.size();
  if (n < 2 || !(threshold >= 0.0))
    return;
  // Kruskal over the pairs closer than the threshold: longer edges would be cut anyway,
  // so the result is the spanning forest of the threshold graph. Coincident points join
  // their representative with zero-length edges and take no part in the pair search.
  const std::vector<std::uint32_t> rep = detail::coincidentRepresentatives (profile.uv);
  detail::ProfileGrid grid;
  // Cells of the shortest threshold: dense stretches are searched as without local
  // thresholds.
  grid.build (profile.uv,
              thresholds && !thresholds->empty()
                  ? *std::min_element (thresholds->begin(), thresholds->end())
                  : static_cast<float> (threshold));
  struct Pair {
    float d2;
    std::uint32_t a, b;
  };
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i) {
      pairs.push_back ({0.f, rep[i], i});
      continue;
    }
    // With local thresholds an edge must be within both ends' thresholds.
    const float reach =
        thresholds ? std::min ((*thresholds)[i], static_cast<float> (threshold))
                   : static_cast<float> (threshold);
    grid.forEachWithin (profile.uv[i], reach, [&] (std::uint32_t j, float d2) {
      if (j > i && rep[j] == j &&
          (!thresholds || d2 <= (*thresholds)[j] * (*thresholds)[j]))
        pairs.push_back ({d2, i, j});
    });
  }
  std::sort (pairs.begin(), pairs.end(), [] (const Pair& x, const Pair& y) {
    if (x.d2 != y.d2)
      return x.d2 < y.d2;
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
  UnionFind sets (n);
  for (const Pair& p : pairs)
    if (sets.unite (p.a, p.b))
      edges.push_back ({p.a, p.b});
  std::sort (edges.begin(), edges.end(), [] (const LocalEdge& x, const LocalEdge& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
}
} // namespace profiles
} // namespace pcl_ext
