/*
 * pcl_ext: a uniform 2D grid over the points of one profile, for fixed-radius queries.
 */
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace profiles {
namespace detail {
/** \brief Points of a profile bucketed in square cells; only occupied cells are stored.
 *
 * Profile points lie on curves, so most cells are empty: cells are kept as a sorted key
 * list (row-major), and a query walks one key range per row. Cheaper than a tree for
 * the few hundred points of a profile, and exact. A row table finds a row's cells
 * without searching the whole key list. */
class ProfileGrid {
public:
  void
  build (const std::vector<Eigen::Vector2f>& uv, float cell)
  {
    uv_ = &uv;
    const std::size_t n = uv.size();
    lo_ = Eigen::Vector2f::Zero();
    if (n == 0)
      return;
    lo_ = uv[0];
    Eigen::Vector2f hi = uv[0];
    for (const auto& p : uv) {
      lo_ = lo_.cwiseMin (p);
      hi = hi.cwiseMax (p);
    }
    // Cells never so small that their numbers overflow: a larger cell only costs time.
    cell_ = std::max (cell, (hi - lo_).maxCoeff() / 65536.f);
    if (!(cell_ > 0.f))
      cell_ = 1.f;
    std::vector<std::uint64_t> key (n);
    for (std::size_t i = 0; i < n; ++i)
      key[i] = keyOf (cellOf (uv[i][0], 0), cellOf (uv[i][1], 1));
    order_.resize (n);
    std::iota (order_.begin(), order_.end(), 0u);
    std::sort (order_.begin(), order_.end(), [&] (std::uint32_t a, std::uint32_t b) {
      return key[a] < key[b] || (key[a] == key[b] && a < b);
    });
    keys_.clear();
    begin_.clear();
    for (std::size_t k = 0; k < n; ++k)
      if (k == 0 || key[order_[k]] != keys_.back()) {
        keys_.push_back (key[order_[k]]);
        begin_.push_back (static_cast<std::uint32_t> (k));
      }
    begin_.push_back (static_cast<std::uint32_t> (n));
    // Row table: the occupied cells of row y are keys_[rows_[y] .. rows_[y + 1]).
    const std::int64_t num_rows = (keys_.back() >> 32) + 1;
    rows_.assign (static_cast<std::size_t> (num_rows) + 1, 0);
    for (const std::uint64_t key : keys_)
      ++rows_[(key >> 32) + 1];
    for (std::size_t y = 1; y < rows_.size(); ++y)
      rows_[y] += rows_[y - 1];
  }

  /** \brief Calls f(j, squared distance) for every point j within \a radius of \a q. */
  template <typename Function>
  void
  forEachWithin (const Eigen::Vector2f& q, float radius, Function f) const
  {
    if (keys_.empty())
      return;
    const float r2 = radius * radius;
    const std::int64_t reach = static_cast<std::int64_t> (std::ceil (radius / cell_));
    const std::int64_t cx = cellOf (q[0], 0), cy = cellOf (q[1], 1);
    for (std::int64_t y = cy - reach; y <= cy + reach; ++y) {
      if (y < 0 || y > kMaxCell)
        continue;
      if (y + 1 >= static_cast<std::int64_t> (rows_.size()))
        break;
      const std::uint64_t first = keyOf (std::max<std::int64_t> (cx - reach, 0), y);
      const std::uint64_t last =
          keyOf (std::min<std::int64_t> (cx + reach, kMaxCell), y);
      const auto row_end = keys_.begin() + rows_[y + 1];
      auto it = std::lower_bound (keys_.begin() + rows_[y], row_end, first);
      for (; it != row_end && *it <= last; ++it) {
        const std::size_t c = static_cast<std::size_t> (it - keys_.begin());
        for (std::uint32_t k = begin_[c]; k < begin_[c + 1]; ++k) {
          const std::uint32_t j = order_[k];
          const float d2 = ((*uv_)[j] - q).squaredNorm();
          if (d2 <= r2)
            f (j, d2);
        }
      }
    }
  }

  /** \brief Calls f(j, squared distance) for every point j in the cells at Chebyshev
   * distance exactly \a ring from the cell of \a q. Every point farther out is at least
   * ring * cellSize() from \a q, which lets a nearest-neighbour search stop early. */
  template <typename Function>
  void
  forEachInRing (const Eigen::Vector2f& q, std::int64_t ring, Function f) const
  {
    if (keys_.empty())
      return;
    const std::int64_t cx = cellOf (q[0], 0), cy = cellOf (q[1], 1);
    const auto visit_row = [&] (std::int64_t y, std::int64_t x0, std::int64_t x1) {
      if (y < 0 || y + 1 >= static_cast<std::int64_t> (rows_.size()) || x1 < 0)
        return;
      const std::uint64_t first = keyOf (std::max<std::int64_t> (x0, 0), y);
      const std::uint64_t last = keyOf (std::min<std::int64_t> (x1, kMaxCell), y);
      const auto row_end = keys_.begin() + rows_[y + 1];
      for (auto it = std::lower_bound (keys_.begin() + rows_[y], row_end, first);
           it != row_end && *it <= last;
           ++it) {
        const std::size_t c = static_cast<std::size_t> (it - keys_.begin());
        for (std::uint32_t k = begin_[c]; k < begin_[c + 1]; ++k) {
          const std::uint32_t j = order_[k];
          f (j, ((*uv_)[j] - q).squaredNorm());
        }
      }
    };
    if (ring == 0) {
      visit_row (cy, cx, cx);
      return;
    }
    visit_row (cy - ring, cx - ring, cx + ring);
    visit_row (cy + ring, cx - ring, cx + ring);
    for (std::int64_t y = cy - ring + 1; y < cy + ring; ++y) {
      visit_row (y, cx - ring, cx - ring);
      visit_row (y, cx + ring, cx + ring);
    }
  }

  /** \brief The (at most) \a k nearest points to \a q within \a reach that accept(j,
   * squared distance) takes, into \a best as (squared distance, index), nearest first,
   * ties by index. Rings of cells are searched outward until the k-th is nearer than
   * the next ring or the ring passes the reach (\a max_ring at most). */
  template <typename Accept>
  void
  nearestInRings (const Eigen::Vector2f& q,
                  std::size_t k,
                  float reach,
                  std::int64_t max_ring,
                  Accept accept,
                  std::vector<std::pair<float, std::uint32_t>>& best) const
  {
    best.clear();
    const auto consider = [&] (std::uint32_t j, float d2) {
      if (!accept (j, d2))
        return;
      const std::pair<float, std::uint32_t> c (d2, j);
      if (best.size() == k && !(c < best.back()))
        return;
      best.insert (std::upper_bound (best.begin(), best.end(), c), c);
      if (best.size() > k)
        best.pop_back();
    };
    for (std::int64_t ring = 0; ring <= max_ring; ++ring) {
      forEachInRing (q, ring, consider);
      const float ring_reach = ring * cell_;
      if (ring_reach >= reach ||
          (best.size() == k && best.back().first <= ring_reach * ring_reach))
        break;
    }
  }

  float
  cellSize () const
  {
    return cell_;
  }

private:
  static constexpr std::int64_t kMaxCell = (std::int64_t (1) << 31) - 1;

  std::int64_t
  cellOf (float value, int axis) const
  {
    const double c = std::floor ((value - lo_[axis]) / cell_);
    return static_cast<std::int64_t> (std::min<double> (std::max (c, -1.0), kMaxCell));
  }

  static std::uint64_t
  keyOf (std::int64_t x, std::int64_t y)
  {
    return (static_cast<std::uint64_t> (y) << 32) | static_cast<std::uint64_t> (x);
  }

  const std::vector<Eigen::Vector2f>* uv_ = nullptr;
  Eigen::Vector2f lo_;
  float cell_ = 1.f;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> begin_;
  std::vector<std::uint32_t> rows_;
};
/** \brief The grid of nearest-neighbour searches ring by ring (ProfileGrid::
 * nearestInRings) among a profile's points within \a threshold, or, with local
 * \a thresholds, within each point's own threshold capped at \a threshold. Small cells,
 * a third of the shortest threshold: in dense parts of a profile the nearest are found
 * in the first rings, and the threshold only bounds the search in sparse parts. */
class ThresholdRings {
public:
  ThresholdRings (const std::vector<Eigen::Vector2f>& uv,
                  double threshold,
                  const std::vector<float>* thresholds)
  : radius_ (static_cast<float> (threshold)), thresholds_ (thresholds)
  {
    grid_.build (
        uv,
        (thresholds && !thresholds->empty()
             ? std::min (*std::min_element (thresholds->begin(), thresholds->end()),
                         radius_)
             : radius_) /
            3.f);
    max_ring_ = static_cast<std::int64_t> (std::ceil (radius_ / grid_.cellSize())) + 1;
  }

  const ProfileGrid&
  grid () const
  {
    return grid_;
  }

  /** \brief The ring beyond which no point is within the threshold. */
  std::int64_t
  maxRing () const
  {
    return max_ring_;
  }

  /** \brief Point \a i's search radius: its threshold, at most the global one. */
  float
  reach (std::uint32_t i) const
  {
    return thresholds_ ? std::min ((*thresholds_)[i], radius_) : radius_;
  }

private:
  float radius_;
  const std::vector<float>* thresholds_;
  ProfileGrid grid_;
  std::int64_t max_ring_ = 0;
};
} // namespace detail
} // namespace profiles
} // namespace pcl_ext
