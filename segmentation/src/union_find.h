/*
 * pcl_ext: a small union-find (disjoint sets) used by the profile segmenters and the graph.
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace pcl_ext
{
namespace profiles
{
namespace detail
{
/** \brief Disjoint sets with path halving; the root of a set is its smallest element, so
  * results never depend on the order unions are made in. */
class UnionFind
{
public:
  explicit UnionFind (std::size_t n = 0) : parent_ (n) { std::iota (parent_.begin (), parent_.end (), 0u); }

  std::uint32_t
  find (std::uint32_t x)
  {
    while (parent_[x] != x)
    {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  /** \brief Join the sets of a and b; false when they were already one. */
  bool
  unite (std::uint32_t a, std::uint32_t b)
  {
    a = find (a);
    b = find (b);
    if (a == b)
      return false;
    if (b < a)
      std::swap (a, b);
    parent_[b] = a;
    return true;
  }

private:
  std::vector<std::uint32_t> parent_;
};

/** \brief For each point, the smallest index of a point with exactly the same coordinates. */
template <typename Vector> std::vector<std::uint32_t>
coincidentRepresentatives (const std::vector<Vector>& points)
{
  std::vector<std::uint32_t> order (points.size ()), rep (points.size ());
  std::iota (order.begin (), order.end (), 0u);
  const auto less = [&] (std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < points[a].size (); ++k)
      if (points[a][k] != points[b][k])
        return points[a][k] < points[b][k];
    return a < b;
  };
  std::sort (order.begin (), order.end (), less);
  for (std::size_t k = 0; k < order.size (); ++k)
    rep[order[k]] = (k > 0 && points[order[k]] == points[order[k - 1]]) ? rep[order[k - 1]]
                                                                         : order[k];
  return rep;
}
}  // namespace detail
}  // namespace profiles
}  // namespace pcl_ext
