/*
 * pcl_ext: the graph of profile edges and its segments (Sithole & Mapurisa, section 2.3
 * and 3).
 */
#include <pcl_ext/segmentation/profile_graph.h>

#include "edge_adjacency.h"

#include <pcl_ext/common/union_find.h>

#include <algorithm>
#include <limits>
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
  const bool has_breaks =
      breakpoints.size() == n &&
      std::find (breakpoints.begin(), breakpoints.end(), 1) != breakpoints.end();
  const auto is_break = [&] (std::uint32_t i) { return has_breaks && breakpoints[i]; };
  UnionFind sets (n);
  for (const auto& edges : stack_edges)
    for (const GraphEdge& e : edges)
      if (!is_break (e.source) && !is_break (e.target))
        sets.unite (e.source, e.target);

  std::vector<std::uint32_t> root (n, kNone);
  for (std::uint32_t i = 0; i < n; ++i)
    if (!is_break (i))
      root[i] = sets.find (i);

  if (has_breaks) {
    std::vector<std::uint32_t> offsets, neighbours;
    detail::buildAdjacency (
        n,
        [&] (auto f) {
          for (const auto& edges : stack_edges)
            for (const GraphEdge& e : edges)
              f (e.source, e.target);
        },
        offsets,
        neighbours);
    // A component whose every point touches a breakpoint lies inside the band along a
    // crease (the crease points themselves, whose fits were not judged): it has no
    // interior, so it is not a segment of its own but rejoins a neighbour like the
    // breakpoints do.
    std::vector<std::uint8_t> interior (n, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (root[i] == kNone)
        continue;
      bool touches = false;
      for (std::uint32_t k = offsets[i]; k < offsets[i + 1] && !touches; ++k)
        touches = is_break (neighbours[k]);
      if (!touches)
        interior[root[i]] = 1;
    }
    std::vector<std::uint32_t> open;
    for (std::uint32_t i = 0; i < n; ++i)
      if (root[i] == kNone || !interior[root[i]]) {
        root[i] = kNone;
        open.push_back (i);
      }
    // Synchronous waves: a wave only reads labels of earlier waves, so the result does
    // not depend on the order points are visited in.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> tally, pending;
    while (!open.empty()) {
      pending.clear();
      std::vector<std::uint32_t> still_open;
      for (const std::uint32_t i : open) {
        tally.clear();
        for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k)
          if (root[neighbours[k]] != kNone)
            tally.emplace_back (root[neighbours[k]], 0);
        if (tally.empty()) {
          still_open.push_back (i);
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
        pending.emplace_back (i, best);
      }
      if (pending.empty())
        break;
      for (const auto& p : pending)
        root[p.first] = p.second;
      open.swap (still_open);
    }
    // Points no wave reached: components among themselves.
    for (const std::uint32_t i : open)
      for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k)
        if (root[neighbours[k]] == kNone)
          sets.unite (i, neighbours[k]);
    for (const std::uint32_t i : open)
      root[i] = sets.find (i);
  }

  labels.assign (n, 0);
  std::vector<std::uint32_t> number (n, kNone);
  std::uint32_t count = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t& id = number[root[i]];
    if (id == kNone)
      id = count++;
    labels[i] = id;
  }
  return count;
}
} // namespace profiles
} // namespace pcl_ext
