/*
 * Tests of the noise sample chosen by position: its cut and the estimate of a cloud
 * from the samples of its parts.
 */
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {
/** \a n keyed neighbourhoods of a plane with noise sigma 0.002 and spacing 0.02 (the
 * eigenvalues of a disc of k = 50 points), each with a random key. */
std::vector<pcl_ext::KeyedSpread>
planeSpreads (std::size_t n, std::uint64_t seed)
{
  pcl_ext::RandomStream rng (seed);
  std::vector<pcl_ext::KeyedSpread> spreads (n);
  for (auto& s : spreads) {
    s.key = rng.next();
    const double l0 = 0.002 * 0.002 * (0.8 + 0.4 * rng.uniform());
    const double r2 = 50 * 0.02 * 0.02 / M_PI;
    s.spread.values = Eigen::Vector3d (l0, r2 / 4 * 0.9, r2 / 4 * 1.1);
    s.spread.size = 50;
  }
  return spreads;
}
} // namespace

TEST (NoiseSample, TheCutKeepsTheSmallestKeysAndEveryTie)
{
  pcl_ext::NoiseSampleCut cut;
  EXPECT_TRUE (cut.empty());
  for (std::uint64_t k = 0; k < 3 * pcl_ext::kNoiseSampleSize; ++k)
    cut.add (3 * pcl_ext::kNoiseSampleSize - k); // descending
  EXPECT_EQ (cut.get(), pcl_ext::kNoiseSampleSize);
  pcl_ext::NoiseSampleCut few;
  for (const std::uint64_t k : {7u, 3u, 9u})
    few.add (k);
  EXPECT_EQ (few.get(), 9u); // fewer keys than the sample: all of them
}

TEST (NoiseSample, PartsGiveTheWholeCloudsEstimateInAnyOrder)
{
  const std::size_t part_size = pcl_ext::kNoiseSampleSize * 3 / 2;
  const auto all = planeSpreads (3 * part_size, 11);
  const pcl_ext::NoiseEstimate whole = pcl_ext::estimateNoiseFromSample (all);
  ASSERT_TRUE (whole.valid) << whole.reason;
  EXPECT_NEAR (whole.sigma, 0.002, 0.0004);
  EXPECT_NEAR (whole.spacing, 0.02, 0.002);
  // Three parts, each keeping only the keys at most its own cut (as a tile saves its
  // sample), merged in reverse order: the whole cloud's estimate, bit for bit.
  std::vector<pcl_ext::KeyedSpread> merged;
  for (std::size_t part = 3; part-- > 0;) {
    const auto first = all.begin() + static_cast<std::ptrdiff_t> (part * part_size);
    const std::vector<pcl_ext::KeyedSpread> own (
        first, first + static_cast<std::ptrdiff_t> (part_size));
    pcl_ext::NoiseSampleCut cut;
    for (const auto& s : own)
      cut.add (s.key);
    for (auto it = own.rbegin(); it != own.rend(); ++it)
      if (it->key <= cut.get())
        merged.push_back (*it);
  }
  EXPECT_LT (merged.size(), all.size());
  const pcl_ext::NoiseEstimate from_parts = pcl_ext::estimateNoiseFromSample (merged);
  EXPECT_EQ (from_parts.sigma, whole.sigma);
  EXPECT_EQ (from_parts.spacing, whole.spacing);
  EXPECT_EQ (from_parts.used, whole.used);
}

TEST (NoiseSample, KeysDependOnThePositionOnly)
{
  EXPECT_EQ (pcl_ext::noiseSampleKeyOf (1.f, 2.f, 3.f),
             pcl_ext::noiseSampleKeyOf (1.f, 2.f, 3.f));
  EXPECT_NE (pcl_ext::noiseSampleKeyOf (1.f, 2.f, 3.f),
             pcl_ext::noiseSampleKeyOf (1.f, 2.f, 3.0001f));
  EXPECT_EQ (pcl_ext::noiseSampleKeyOf (0.f, 0.f, 0.f),
             pcl_ext::noiseSampleKeyOf (-0.f, 0.f, 0.f)); // one zero
}

TEST (NoiseSample, TooFewOrUnusableNeighbourhoodsGiveNoEstimate)
{
  const pcl_ext::NoiseEstimate none = pcl_ext::estimateNoiseFromSample ({});
  EXPECT_FALSE (none.valid);
  EXPECT_FALSE (none.reason.empty());
  auto spreads = planeSpreads (pcl_ext::kNoiseSampleSize, 3);
  for (auto& s : spreads) // NaN eigenvalues and empty neighbourhoods: not usable
    s.spread.values[0] = std::numeric_limits<double>::quiet_NaN();
  spreads[0].spread = pcl_ext::NeighbourhoodSpread();
  const pcl_ext::NoiseEstimate unusable = pcl_ext::estimateNoiseFromSample (spreads);
  EXPECT_FALSE (unusable.valid);
  EXPECT_TRUE (std::isnan (unusable.sigma));
}

TEST (NoiseSample, CurvatureMedianIsTheSamplesWithTheNoiseRemoved)
{
  // Known kappa: l0 = i * 1e-6 over l1 = l2 = 1 for the 20,000 smallest keys 0..19999,
  // far larger l0 beyond the cut (keys from 10^6), which must not count.
  std::vector<pcl_ext::KeyedSpread> spreads;
  const std::size_t n = pcl_ext::kNoiseSampleSize;
  for (std::size_t i = 0; i < 2 * n; ++i) {
    pcl_ext::KeyedSpread s;
    const bool in_sample = i < n;
    s.key = in_sample ? i : 1000000 + i;
    s.spread.values = Eigen::Vector3d (in_sample ? i * 1e-6 : 1.0, 1.0, 1.0);
    s.spread.size = 50;
    spreads.push_back (s);
  }
  // The upper median of l0 / (l0 + 2) over i = 0 .. n - 1: i = n / 2.
  const auto kappa = [] (double l0) {
    return static_cast<double> (static_cast<float> (l0 / (l0 + 2.0)));
  };
  const double l0 = static_cast<double> (static_cast<float> ((n / 2) * 1e-6));
  EXPECT_EQ (pcl_ext::sampleCurvatureMedian (spreads, 0.0), kappa (l0));
  // The noise variance is taken off l0 first (not below 0).
  EXPECT_EQ (pcl_ext::sampleCurvatureMedian (spreads, 0.001), kappa (l0 - 0.001));
  EXPECT_EQ (pcl_ext::sampleCurvatureMedian (spreads, 1.0), 0.0);
  // In another order: the same median.
  std::reverse (spreads.begin(), spreads.end());
  EXPECT_EQ (pcl_ext::sampleCurvatureMedian (spreads, 0.0), kappa (l0));
  // Eigenvalues that are not finite give no kappa and do not count.
  auto with_nan = spreads;
  for (std::size_t i = 0; i < n; i += 2)
    with_nan[with_nan.size() - 1 - i].spread.values[1] =
        std::numeric_limits<double>::quiet_NaN();
  const double odd = pcl_ext::sampleCurvatureMedian (with_nan, 0.0);
  EXPECT_TRUE (std::isfinite (odd));
  EXPECT_NE (odd, kappa (l0)); // the median of the other half
  // Neighbourhoods without a covariance do not count; none at all: NaN.
  for (std::size_t i = 0; i < spreads.size(); ++i)
    spreads[i].spread = pcl_ext::NeighbourhoodSpread();
  EXPECT_TRUE (std::isnan (pcl_ext::sampleCurvatureMedian (spreads, 0.0)));
  EXPECT_TRUE (std::isnan (pcl_ext::sampleCurvatureMedian ({}, 0.0)));
}
