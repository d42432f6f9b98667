/*
 * pcl_ext: the graph of profile edges and its segments (Sithole & Mapurisa, section 2.3
 * and 3).
 */
#include <pcl_ext/segmentation/profile_graph.h>

#include <pcl_ext/common/union_find.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace pcl_ext {
namespace profiles {
namespace {
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
} // namespace

std::size_t
labelSegments (std::size_t n,
               const std::vector<std::vector<GraphEdge>>& stack_edges,
               const std::vector<std::uint8_t>& breakpoints,
               std::vector<std::uint32_t>& labels)
{
  return labelSegments (
      n,
      [&stack_edges] (const EdgeVisitor& visit) {
        for (const auto& edges : stack_edges)
          for (const GraphEdge& e : edges)
            visit (e.source, e.target);
      },
      breakpoints,
      labels);
}

std::size_t
labelSegments (std::size_t n,
               const ForEachEdge& for_each_edge,
               const std::vector<std::uint8_t>& breakpoints,
               std::vector<std::uint32_t>& labels)
{
  const bool has_breaks =
      breakpoints.size() == n &&
      std::find (breakpoints.begin(), breakpoints.end(), 1) != breakpoints.end();
  const auto is_break = [&] (std::uint32_t i) { return has_breaks && breakpoints[i]; };
  UnionFind sets (n);
  for_each_edge ([&] (std::uint32_t a, std::uint32_t b) {
    if (!is_break (a) && !is_break (b))
      sets.unite (a, b);
  });

  std::vector<std::uint32_t> root (n, kNone);
  for (std::uint32_t i = 0; i < n; ++i)
    if (!is_break (i))
      root[i] = sets.find (i);

  if (has_breaks) {
    constexpr std::uint8_t kTouches = 1, kInterior = 2, kOpen = 4;
    std::vector<std::uint8_t> state (n, 0);
    for_each_edge ([&] (std::uint32_t a, std::uint32_t b) {
      if (is_break (b))
        state[a] |= kTouches;
      if (is_break (a))
        state[b] |= kTouches;
    });
    // A component whose every point touches a breakpoint lies inside the band along a
    // crease (the crease points themselves, whose fits were not judged): it has no
    // interior, so it is not a segment of its own but rejoins a neighbour like the
    // breakpoints do.
    for (std::uint32_t i = 0; i < n; ++i)
      if (root[i] != kNone && !(state[i] & kTouches))
        state[root[i]] |= kInterior;
    std::vector<std::uint32_t> open_points;
    for (std::uint32_t i = 0; i < n; ++i)
      if (root[i] == kNone || !(state[root[i]] & kInterior))
        open_points.push_back (i);
    for (const std::uint32_t i : open_points) {
      root[i] = kNone;
      state[i] |= kOpen;
    }
    // The graph neighbours of the open points alone, each point's in the order its
    // edges come (a stable sort of the pairs by point).
    const auto position = [&open_points] (std::uint32_t i) {
      return static_cast<std::uint32_t> (
          std::lower_bound (open_points.begin(), open_points.end(), i) -
          open_points.begin());
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for_each_edge ([&] (std::uint32_t a, std::uint32_t b) {
      if (state[a] & kOpen)
        pairs.emplace_back (position (a), b);
      if (state[b] & kOpen)
        pairs.emplace_back (position (b), a);
    });
    state = std::vector<std::uint8_t>();
    std::stable_sort (pairs.begin(), pairs.end(), [] (const auto& x, const auto& y) {
      return x.first < y.first;
    });
    std::vector<std::uint32_t> offsets (open_points.size() + 1, 0),
        neighbours (pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      ++offsets[pairs[k].first + 1];
      neighbours[k] = pairs[k].second;
    }
    pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>();
    for (std::size_t p = 0; p < open_points.size(); ++p)
      offsets[p + 1] += offsets[p];

    // Synchronous waves: a wave only reads labels of earlier waves, so the result does
    // not depend on the order points are visited in.
    std::vector<std::uint32_t> open (open_points.size());
    std::iota (open.begin(), open.end(), 0u); // positions in open_points
    std::vector<std::pair<std::uint32_t, std::uint32_t>> tally, pending;
    while (!open.empty()) {
      pending.clear();
      std::vector<std::uint32_t> still_open;
      for (const std::uint32_t p : open) {
        tally.clear();
        for (std::uint32_t k = offsets[p]; k < offsets[p + 1]; ++k)
          if (root[neighbours[k]] != kNone)
            tally.emplace_back (root[neighbours[k]], 0);
        if (tally.empty()) {
          still_open.push_back (p);
          continue;
        }
        std::sort (tally.begin(), tally.end());
        std::uint32_t best = kNone, best_count = 0;
        for (std::size_t a = 0; a < tally.size();) {
          std::size_t b = a;
          while (b < tally.size() && tally[b].first == tally[a].first)
            ++b;
          if (b - a > best_count) {
            best_count = static_cast<std::uint32_t> (b - a);
            best = tally[a].first;
          }
          a = b;
        }
        pending.emplace_back (open_points[p], best);
      }
      if (pending.empty())
        break;
      for (const auto& q : pending)
        root[q.first] = q.second;
      open.swap (still_open);
    }
    // Points no wave reached: components among themselves.
    for (const std::uint32_t p : open)
      for (std::uint32_t k = offsets[p]; k < offsets[p + 1]; ++k)
        if (root[neighbours[k]] == kNone)
          sets.unite (open_points[p], neighbours[k]);
    for (const std::uint32_t p : open)
      root[open_points[p]] = sets.find (open_points[p]);
  }

  // The components numbered in order of first vertex, in place of the roots (the sets
  // are not needed any more: their memory goes to the numbering).
  sets = UnionFind();
  std::vector<std::uint32_t> number (n, kNone);
  std::uint32_t count = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t& id = number[root[i]];
    if (id == kNone)
      id = count++;
    root[i] = id;
  }
  labels.swap (root);
  return count;
}
} // namespace profiles
} // namespace pcl_ext
