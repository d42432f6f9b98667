/*
 * pcl_ext: the nearest points of a sample of a cloud's points, found without a tree.
 */
#pragma once

#include <pcl_ext/segmentation/profile_stacks.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace profiles {
namespace detail {
/** \brief For \a samples points taken evenly along the cloud's longest axis, the \a k
 * nearest other points (at a distance above 0), by a sweep along that axis: \a visit
 * (point, nearest) receives them as (squared distance, point index), ascending, fewer
 * than \a k when the sweep found fewer.
 *
 * The sweep stops once the coordinate gap alone exceeds the k-th distance; the step cap
 * only matters for pathological clouds (everything at one coordinate), where it gives
 * an upper bound instead of a quadratic run time. */
template <typename Visit>
void
forEachSampledNeighbourhood (const std::vector<Eigen::Vector3f>& xyz,
                             std::size_t samples,
                             std::size_t k,
                             Visit visit)
{
  const std::size_t n = xyz.size();
  if (n < 2 || samples == 0 || k == 0)
    return;
  Eigen::Vector3f lo = xyz[0], hi = xyz[0];
  for (const auto& p : xyz) {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  const int axis = sampleAxis (lo, hi);
  std::vector<std::pair<float, std::uint32_t>> sorted (n);
  for (std::size_t i = 0; i < n; ++i)
    sorted[i] = {xyz[i][axis], static_cast<std::uint32_t> (i)};
  std::sort (sorted.begin(), sorted.end());

  const std::size_t max_steps = 8192;
  const std::size_t m = std::min (samples, n);
  std::vector<std::pair<float, std::uint32_t>> nearest;
  for (std::size_t s = 0; s < m; ++s) {
    const std::size_t r = sampleRank (s, n, m);
    const Eigen::Vector3f& p = xyz[sorted[r].second];
    const float c = sorted[r].first;
    nearest.clear();
    const auto bound = [&] {
      return nearest.size() < k ? std::numeric_limits<float>::infinity()
                                : nearest.back().first;
    };
    const auto consider = [&] (std::size_t q) {
      const float d2 = (xyz[sorted[q].second] - p).squaredNorm();
      if (d2 > 0.f && d2 < bound()) {
        const std::pair<float, std::uint32_t> entry (d2, sorted[q].second);
        nearest.insert (std::upper_bound (nearest.begin(), nearest.end(), entry),
                        entry);
        if (nearest.size() > k)
          nearest.pop_back();
      }
    };
    for (std::size_t q = r + 1, steps = 0; q < n && steps < max_steps; ++q, ++steps) {
      const float dc = sorted[q].first - c;
      if (dc * dc >= bound())
        break;
      consider (q);
    }
    for (std::size_t q = r, steps = 0; q-- > 0 && steps < max_steps; ++steps) {
      const float dc = c - sorted[q].first;
      if (dc * dc >= bound())
        break;
      consider (q);
    }
    visit (sorted[r].second, nearest);
  }
}
} // namespace detail
} // namespace profiles
} // namespace pcl_ext
