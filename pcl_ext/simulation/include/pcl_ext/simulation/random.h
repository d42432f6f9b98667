/*
 * pcl_ext: counter-based random numbers for the scanner simulator.
 */
#pragma once

#include <cmath>
#include <cstdint>

namespace pcl_ext {
namespace simulation {
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

/** \brief A small random stream seeded from a hash, so that every ray draws its own
 * numbers.
 *
 * Each ray of a scan seeds one stream from (seed, scanner, ray index), which makes the
 * output independent of the thread count and of the order in which rays are processed.
 * Uniforms and Gaussians are computed here (SplitMix64 output, Box-Muller) rather than
 * with the standard library's distributions, whose algorithms differ between
 * implementations.
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
} // namespace simulation
} // namespace pcl_ext
