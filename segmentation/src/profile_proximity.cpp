/*
 * pcl_ext: proximity chaining of the points of a profile (Sithole & Mapurisa, 4.1.1).
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "profile_grid.h"
#include "union_find.h"

#include <algorithm>
#include <utility>

namespace pcl_ext
{
namespace profiles
{
void
proximityEdges (const ProfilePoints& profile, double threshold, unsigned int neighbours,
                std::vector<LocalEdge>& edges)
{
  edges.clear ();
  const std::size_t n = profile.uv.size ();
  if (n < 2 || !(threshold >= 0.0) || neighbours == 0)
    return;
  const std::vector<std::uint32_t> rep = detail::coincidentRepresentatives (profile.uv);
  detail::ProfileGrid grid;
  grid.build (profile.uv, static_cast<float> (threshold));
  std::vector<std::pair<float, std::uint32_t>> near;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    if (rep[i] != i)
    {
      edges.push_back ({rep[i], i});
      continue;
    }
    near.clear ();
    grid.forEachWithin (profile.uv[i], static_cast<float> (threshold),
                        [&] (std::uint32_t j, float d2) {
                          if (rep[j] == j && j != i)
                            near.emplace_back (d2, j);
                        });
    const std::size_t k = std::min<std::size_t> (neighbours, near.size ());
    std::partial_sort (near.begin (), near.begin () + k, near.end ());
    for (std::size_t m = 0; m < k; ++m)
      edges.push_back ({std::min (i, near[m].second), std::max (i, near[m].second)});
  }
  std::sort (edges.begin (), edges.end (), [] (const LocalEdge& x, const LocalEdge& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
  edges.erase (std::unique (edges.begin (), edges.end (),
                            [] (const LocalEdge& x, const LocalEdge& y) {
                              return x.a == y.a && x.b == y.b;
                            }),
               edges.end ());
}
}  // namespace profiles
}  // namespace pcl_ext
