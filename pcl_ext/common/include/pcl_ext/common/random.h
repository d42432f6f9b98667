/*
 * pcl_ext: counter-based random numbers that are the same with every standard library.
 */
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace pcl_ext {
/** \brief SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix. */
inline std::uint64_t
splitMix64 (std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/** \brief Hash of an ordered pair of keys; chain it to hash tuples. */
inline std::uint64_t
hashCombine (std::uint64_t a, std::uint64_t b)
{
  return splitMix64 (a ^ splitMix64 (b + 0x632be59bd9b4e019ULL));
}

/** \brief Hash of a position's float coordinates (their bits, -0 taken as +0) with
 * \a seed: a random draw attached to the point itself, the same in any cloud that
 * holds it, whatever its index or the points around it (a tile of a larger cloud
 * draws as the whole cloud does). */
inline std::uint64_t
hashPosition (float x, float y, float z, std::uint64_t seed)
{
  std::uint64_t key = splitMix64 (seed);
  for (const float c : {x, y, z}) {
    const float v = c == 0.0f ? 0.0f : c;
    std::uint32_t bits;
    std::memcpy (&bits, &v, sizeof (bits));
    key = hashCombine (key, bits);
  }
  return key;
}

/** \brief A small random stream seeded from a key (SplitMix64).
 *
 * Seed one stream per independent unit of work (a ray, a segment) from a hash of its
 * keys, and the output does not depend on the thread count or the order of the work.
 * Uniforms, indices and Gaussians are computed here rather than with the standard
 * library's distributions, whose algorithms are implementation-defined: the same seed
 * gives the same numbers with every compiler and library.
 */
class RandomStream {
public:
  explicit RandomStream (std::uint64_t key) : state_ (splitMix64 (key)) {}

  /** \brief Next 64 random bits. */
  std::uint64_t
  next ()
  {
    state_ += 0x9e3779b97f4a7c15ULL;
    return splitMix64 (state_);
  }

  /** \brief Uniform double in [0, 1), 53 random bits. */
  double
  uniform ()
  {
    return static_cast<double> (next() >> 11) * 0x1.0p-53;
  }

  /** \brief Uniform integer in [0, n), without modulo bias: draws below 2^64 mod n
   * (fewer than n of the 2^64) are redrawn, so every value has the same number of
   * draws. Returns 0 when \a n is 0. */
  std::uint64_t
  index (std::uint64_t n)
  {
    if (n == 0)
      return 0;
    const std::uint64_t reject_below = (0 - n) % n; // 2^64 mod n
    std::uint64_t r = next();
    while (r < reject_below)
      r = next();
    return r % n;
  }

  /** \brief Standard normal deviate (Box-Muller, cosine branch). */
  double
  gaussian ()
  {
    const double u1 = (static_cast<double> (next() >> 11) + 1.0) * 0x1.0p-53; // (0, 1]
    const double u2 = uniform();
    return std::sqrt (-2.0 * std::log (u1)) * std::cos (6.283185307179586 * u2);
  }

private:
  std::uint64_t state_;
};
} // namespace pcl_ext
