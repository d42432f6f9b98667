/*
 * Tests of the library's counter-based random numbers (the simulator's and the
 * segmentation's): known SplitMix64 values, seeded streams, uniform, index and Gaussian
 * deviates, the same on every standard library.
 */
#include <pcl_ext/common/random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

using namespace pcl_ext;

TEST (Random, GaussianMoments)
{
  RandomStream rng (123);
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double g = rng.gaussian();
    sum += g;
    sum2 += g * g;
  }
  EXPECT_NEAR (sum / n, 0.0, 0.01);
  EXPECT_NEAR (sum2 / n, 1.0, 0.01);
}

TEST (Random, SplitMixKnownValues)
{
  // The first outputs of SplitMix64 seeded with 0 (Steele, Lea & Flood's reference
  // generator): splitMix64 (k * golden gamma) is its output k + 1.
  EXPECT_EQ (splitMix64 (0), 0xe220a8397b1dcdafULL);
  EXPECT_EQ (splitMix64 (0x9e3779b97f4a7c15ULL), 0x6e789e6aa1b965f4ULL);
  EXPECT_EQ (splitMix64 (2 * 0x9e3779b97f4a7c15ULL), 0x06c45d188009454fULL);
  // A bijection: no two of many keys collide.
  std::set<std::uint64_t> seen;
  for (std::uint64_t k = 0; k < 10000; ++k)
    seen.insert (splitMix64 (k));
  EXPECT_EQ (seen.size(), 10000u);
  // Pairs are ordered.
  EXPECT_NE (hashCombine (1, 2), hashCombine (2, 1));
  EXPECT_EQ (hashCombine (1, 2), hashCombine (1, 2));
}

TEST (Random, SeededStreamsRepeatAndDiffer)
{
  RandomStream a (42), b (42), c (43);
  std::vector<std::uint64_t> first;
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t x = a.next();
    EXPECT_EQ (x, b.next()) << i;
    first.push_back (x);
  }
  int same = 0;
  for (int i = 0; i < 100; ++i)
    same += c.next() == first[static_cast<std::size_t> (i)];
  EXPECT_EQ (same, 0);
  // The stream of key k is SplitMix64 seeded with splitMix64 (k).
  RandomStream d (7);
  const std::uint64_t state = splitMix64 (7) + 0x9e3779b97f4a7c15ULL;
  EXPECT_EQ (d.next(), splitMix64 (state));
}

TEST (Random, UniformsInTheUnitInterval)
{
  RandomStream rng (5);
  const int n = 100000;
  double sum = 0.0, lo = 1.0, hi = 0.0;
  int below_tenth = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE (u, 0.0);
    ASSERT_LT (u, 1.0);
    sum += u;
    lo = std::min (lo, u);
    hi = std::max (hi, u);
    below_tenth += u < 0.1;
  }
  EXPECT_NEAR (sum / n, 0.5, 0.005);
  EXPECT_NEAR (static_cast<double> (below_tenth) / n, 0.1, 0.005);
  EXPECT_LT (lo, 1e-3);
  EXPECT_GT (hi, 1.0 - 1e-3);
  // Gaussians are finite (the log never sees 0).
  for (int i = 0; i < n; ++i)
    ASSERT_TRUE (std::isfinite (rng.gaussian()));
}

TEST (Random, IndexIsTheStreamModuloTheBound)
{
  // For a small bound the rejected draws (below 2^64 mod n, here 6) never occur in
  // practice: index (n) is the next 64 bits modulo n, fixed by SplitMix64 alone.
  RandomStream a (9), b (9);
  for (int i = 0; i < 1000; ++i)
    EXPECT_EQ (a.index (10), b.next() % 10) << i;
  EXPECT_EQ (a.index (0), 0u);
  EXPECT_EQ (a.index (1), 0u);
}

TEST (Random, IndexIsUniformAndInRange)
{
  RandomStream rng (17);
  const std::uint64_t n = 7;
  const int draws = 70000;
  std::vector<int> count (n, 0);
  for (int i = 0; i < draws; ++i) {
    const std::uint64_t k = rng.index (n);
    ASSERT_LT (k, n);
    ++count[k];
  }
  // Chi-square with 6 degrees of freedom: below 22.5 with probability 0.999.
  double chi2 = 0.0;
  for (const int c : count)
    chi2 += (c - draws / 7.0) * (c - draws / 7.0) / (draws / 7.0);
  EXPECT_LT (chi2, 22.5);
  // A bound just above 2^63 rejects almost half the draws; the values stay in range
  // and fall on both halves equally.
  const std::uint64_t big = (std::uint64_t (1) << 63) + 1;
  int upper = 0;
  for (int i = 0; i < 10000; ++i) {
    const std::uint64_t k = rng.index (big);
    ASSERT_LT (k, big);
    upper += k >= big / 2;
  }
  EXPECT_NEAR (upper / 10000.0, 0.5, 0.03);
}
