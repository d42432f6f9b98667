/*
 * pcl_ext: estimateNoiseAndSpacing.
 */
#include <pcl_ext/common/noise_estimation.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace pcl_ext {
namespace {
double
median (std::vector<double>& values)
{
  const auto middle = values.begin() + static_cast<std::ptrdiff_t> (values.size() / 2);
  std::nth_element (values.begin(), middle, values.end());
  return *middle;
}
} // namespace

NoiseEstimate
estimateNoiseAndSpacing (const std::vector<NeighbourhoodSpread>& spreads,
                         double flat_share)
{
  NoiseEstimate result;
  if (!(flat_share > 0.0 && flat_share <= 1.0)) {
    result.reason = "the share of flattest neighbourhoods must lie in (0, 1]";
    return result;
  }
  // (curvature, index) of the usable neighbourhoods.
  std::vector<std::pair<double, std::size_t>> usable;
  usable.reserve (spreads.size());
  for (std::size_t i = 0; i < spreads.size(); ++i) {
    const auto& s = spreads[i];
    const double sum = s.values.sum();
    if (s.size < 4 || !s.values.allFinite() || !(s.values[1] + s.values[2] > 0.0) ||
        s.values[0] < 0.0)
      continue;
    usable.emplace_back (s.values[0] / sum, i);
  }
  if (usable.size() < kMinNoiseNeighbourhoods) {
    result.reason = "too few neighbourhoods with a surface (" +
                    std::to_string (usable.size()) + ", at least " +
                    std::to_string (kMinNoiseNeighbourhoods) + " needed)";
    return result;
  }
  const auto used = std::max<std::size_t> (
      1, static_cast<std::size_t> (flat_share * static_cast<double> (usable.size())));
  std::nth_element (usable.begin(),
                    usable.begin() + static_cast<std::ptrdiff_t> (used - 1),
                    usable.end());
  std::vector<double> l0, spacing, kappa;
  l0.reserve (used);
  spacing.reserve (used);
  kappa.reserve (used);
  for (std::size_t u = 0; u < used; ++u) {
    const auto& s = spreads[usable[u].second];
    const double n = static_cast<double> (s.size);
    kappa.push_back (usable[u].first);
    l0.push_back (s.values[0] * n / (n - 3.0));
    spacing.push_back (std::sqrt (2.0 * M_PI * (s.values[1] + s.values[2]) / n));
  }
  result.used = used;
  result.flat_curvature = median (kappa);
  if (!(result.flat_curvature <= kMaxFlatCurvature)) {
    result.reason = "the flattest neighbourhoods are not flat (median curvature " +
                    std::to_string (result.flat_curvature) + ")";
    return result;
  }
  result.sigma = std::sqrt (median (l0));
  result.spacing = median (spacing);
  result.valid = true;
  return result;
}
} // namespace pcl_ext
