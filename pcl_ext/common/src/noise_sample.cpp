/*
 * pcl_ext: the noise sample chosen by position.
 */
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/random.h>

#include <algorithm>
#include <tuple>

namespace pcl_ext {
std::uint64_t
noiseSampleKeyOf (float x, float y, float z)
{
  return hashPosition (x, y, z, 0x6c765f6e6f697365ULL);
}

NoiseEstimate
estimateNoiseFromSample (std::vector<KeyedSpread> candidates)
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
  std::vector<NeighbourhoodSpread> spreads;
  spreads.reserve (candidates.size());
  for (const auto& c : candidates)
    spreads.push_back (c.spread);
  return estimateNoiseAndSpacing (spreads);
}
} // namespace pcl_ext
