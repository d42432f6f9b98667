/*
 * pcl_ext: the points of a profile that share their coordinates exactly.
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace pcl_ext {
namespace profiles {
namespace detail {
/** \brief For each point, the smallest index of a point with exactly the same
 * coordinates. */
template <typename Vector>
std::vector<std::uint32_t>
coincidentRepresentatives (const std::vector<Vector>& points)
{
  std::vector<std::uint32_t> order (points.size()), rep (points.size());
  std::iota (order.begin(), order.end(), 0u);
  const auto less = [&] (std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < points[a].size(); ++k)
      if (points[a][k] != points[b][k])
        return points[a][k] < points[b][k];
    return a < b;
  };
  std::sort (order.begin(), order.end(), less);
  for (std::size_t k = 0; k < order.size(); ++k)
    rep[order[k]] = (k > 0 && points[order[k]] == points[order[k - 1]])
                        ? rep[order[k - 1]]
                        : order[k];
  return rep;
}
} // namespace detail
} // namespace profiles
} // namespace pcl_ext
