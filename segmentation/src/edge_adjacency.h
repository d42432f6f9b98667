/*
 * pcl_ext: both directions of a list of edges as compressed rows, for walking a graph
 * of profile points.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace profiles {
namespace detail {
/** \brief The neighbours of vertex i are neighbours[offsets[i] .. offsets[i + 1]), in
 * the order the edges are visited. \param[in] for_each_edge called with a function f
 * (a, b) that it calls for every edge; it is called twice */
template <typename ForEachEdge>
void
buildAdjacency (std::size_t n,
                ForEachEdge for_each_edge,
                std::vector<std::uint32_t>& offsets,
                std::vector<std::uint32_t>& neighbours)
{
  offsets.assign (n + 1, 0);
  for_each_edge ([&] (std::uint32_t a, std::uint32_t b) {
    ++offsets[a + 1];
    ++offsets[b + 1];
  });
  for (std::size_t i = 0; i < n; ++i)
    offsets[i + 1] += offsets[i];
  neighbours.resize (offsets[n]);
  std::vector<std::uint32_t> next (offsets.begin(), offsets.end() - 1);
  for_each_edge ([&] (std::uint32_t a, std::uint32_t b) {
    neighbours[next[a]++] = b;
    neighbours[next[b]++] = a;
  });
}
} // namespace detail
} // namespace profiles
} // namespace pcl_ext
