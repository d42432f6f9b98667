/*
 * pcl_ext: the noise sample chosen by position.
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/random.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace pcl_ext {
namespace {
/** The sample among \a candidates (key at most the cut of all their keys), its
 * eigenvalues rounded to float, in the order of keys and values. */
std::vector<KeyedSpread>
sampleOf (std::vector<KeyedSpread> candidates)
{
  NoiseSampleCut cut;
  for (const auto& c : candidates)
    cut.add (c.key);
  const std::uint64_t last = cut.get();
  candidates.erase (
      std::remove_if (candidates.begin(),
                      candidates.end(),
                      [last] (const KeyedSpread& c) { return c.key > last; }),
      candidates.end());
  for (auto& c : candidates)
    c.spread.values = c.spread.values.cast<float>().cast<double>();
  std::sort (candidates.begin(),
             candidates.end(),
             [] (const KeyedSpread& a, const KeyedSpread& b) {
               const auto& u = a.spread.values;
               const auto& v = b.spread.values;
               return std::tie (a.key, u[0], u[1], u[2], a.spread.size) <
                      std::tie (b.key, v[0], v[1], v[2], b.spread.size);
             });
  return candidates;
}
} // namespace

std::uint64_t
noiseSampleKeyOf (float x, float y, float z)
{
  return hashPosition (x, y, z, 0x6c765f6e6f697365ULL);
}

NoiseEstimate
estimateNoiseFromSample (std::vector<KeyedSpread> candidates)
{
  const std::vector<KeyedSpread> sample = sampleOf (std::move (candidates));
  std::vector<NeighbourhoodSpread> spreads;
  spreads.reserve (sample.size());
  for (const auto& c : sample)
    spreads.push_back (c.spread);
  return estimateNoiseAndSpacing (spreads);
}

double
sampleCurvatureMedian (std::vector<KeyedSpread> candidates, double noise_variance)
{
  const std::vector<KeyedSpread> sample = sampleOf (std::move (candidates));
  std::vector<float> kappa;
  kappa.reserve (sample.size());
  for (const auto& c : sample) {
    if (c.spread.size == 0)
      continue; // no covariance: no kappa either
    Eigen::Vector3d values = c.spread.values;
    values[0] = std::max (values[0] - noise_variance, 0.0);
    const float k = static_cast<float> (surfaceVariance (values));
    if (std::isfinite (k))
      kappa.push_back (k);
  }
  if (kappa.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const auto middle = kappa.begin() + kappa.size() / 2;
  std::nth_element (kappa.begin(), middle, kappa.end());
  return static_cast<double> (*middle);
}
} // namespace pcl_ext
