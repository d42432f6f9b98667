/*
 * pcl_ext: minimum spanning tree segmentation of the points of a profile (Sithole &
 * Mapurisa, section 3).
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "coincident_points.h"
#include "profile_grid.h"
#include <pcl_ext/common/union_find.h>

#include <algorithm>
#include <cstring>
#include <numeric>

namespace pcl_ext {
namespace profiles {
namespace {
/** A pair of points of the profile and its squared length. */
struct Pair {
  float d2;
  std::uint32_t a, b;
};

/** Stable sort by length: a least-significant-digit radix sort of the lengths' bits
 * (squared lengths are never negative, so their bits order as the floats do). */
void
sortByLength (std::vector<Pair>& pairs)
{
  constexpr int kDigitBits = 11;
  constexpr std::uint32_t kBuckets = 1u << kDigitBits;
  std::vector<Pair> sorted (pairs.size());
  std::vector<std::size_t> start (kBuckets + 1);
  for (int shift = 0; shift < 32; shift += kDigitBits) {
    const auto digit = [shift] (const Pair& p) {
      std::uint32_t bits;
      std::memcpy (&bits, &p.d2, sizeof bits);
      return (bits >> shift) & (kBuckets - 1);
    };
    std::fill (start.begin(), start.end(), 0);
    for (const Pair& p : pairs)
      ++start[digit (p) + 1];
    // A digit every pair shares moves nothing.
    if (std::find (start.begin(), start.end(), pairs.size()) != start.end())
      continue;
    std::partial_sum (start.begin(), start.end(), start.begin());
    for (const Pair& p : pairs)
      sorted[start[digit (p)]++] = p;
    pairs.swap (sorted);
  }
}
} // namespace

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
  UnionFind sets (n);
  // A coincident point's one pair (zero length, to its representative) always joins two
  // sets: it is taken first, wherever its turn among the zero-length pairs would be.
  for (std::uint32_t i = 0; i < n; ++i)
    if (rep[i] != i) {
      sets.unite (rep[i], i);
      edges.push_back ({rep[i], i});
    }
  // The pairs in (a, b) order, then stably by length: Kruskal's order, ties by (a, b).
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rep[i] != i)
      continue;
    // With local thresholds an edge must be within both ends' thresholds.
    const float reach =
        thresholds ? std::min ((*thresholds)[i], static_cast<float> (threshold))
                   : static_cast<float> (threshold);
    const std::size_t first = pairs.size();
    grid.forEachWithin (profile.uv[i], reach, [&] (std::uint32_t j, float d2) {
      if (j > i && rep[j] == j &&
          (!thresholds || d2 <= (*thresholds)[j] * (*thresholds)[j]))
        pairs.push_back ({d2, i, j});
    });
    std::sort (pairs.begin() + first, pairs.end(), [] (const Pair& x, const Pair& y) {
      return x.b < y.b;
    });
  }
  sortByLength (pairs);
  for (const Pair& p : pairs)
    if (sets.unite (p.a, p.b))
      edges.push_back ({p.a, p.b});
  std::sort (edges.begin(), edges.end(), [] (const LocalEdge& x, const LocalEdge& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
}
} // namespace profiles
} // namespace pcl_ext
