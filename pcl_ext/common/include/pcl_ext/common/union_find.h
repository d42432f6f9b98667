/*
 * pcl_ext: a small union-find (disjoint sets) with a deterministic root per set.
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief Disjoint sets with path halving; the root of a set is its smallest element,
 * so results never depend on the order unions are made in. */
class UnionFind {
public:
  explicit UnionFind (std::size_t n = 0) : parent_ (n)
  {
    std::iota (parent_.begin(), parent_.end(), 0u);
  }

  /** \brief Add a set of one new element; \return the element (the previous size). */
  std::uint32_t
  add ()
  {
    parent_.push_back (static_cast<std::uint32_t> (parent_.size()));
    return parent_.back();
  }

  std::size_t
  size () const
  {
    return parent_.size();
  }

  std::uint32_t
  find (std::uint32_t x)
  {
    while (parent_[x] != x) {
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
} // namespace pcl_ext
