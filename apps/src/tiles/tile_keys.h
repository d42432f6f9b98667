/*
 * pcl_ext_tiles: 64-bit keys (pcl_ext::hashPosition's sampling keys, point indices)
 * saved as tile values, which are floats: three parts of at most 22 bits, each exact
 * in a float.
 */
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The high, middle and low part of \a key. */
inline void
splitKey (std::uint64_t key, float parts[3])
{
  parts[0] = static_cast<float> (key >> 42);
  parts[1] = static_cast<float> ((key >> 20) & 0x3FFFFF);
  parts[2] = static_cast<float> (key & 0xFFFFF);
}

/** \brief The key of the three parts \a parts (high, middle, low). */
inline std::uint64_t
joinKey (const float* parts)
{
  return (static_cast<std::uint64_t> (parts[0]) << 42) |
         (static_cast<std::uint64_t> (parts[1]) << 20) |
         static_cast<std::uint64_t> (parts[2]);
}

/** \brief Append \a key to the tile values \a names (high, middle, low part). */
inline void
appendKey (std::map<std::string, std::vector<float>>& values,
           const char* const names[3],
           std::uint64_t key)
{
  float parts[3];
  splitKey (key, parts);
  for (int p = 0; p < 3; ++p)
    values[names[p]].push_back (parts[p]);
}

/** \brief The key of value \a i of the three parts appendKey wrote. */
inline std::uint64_t
keyAt (const std::vector<float> parts[3], std::size_t i)
{
  const float at[3] = {parts[0][i], parts[1][i], parts[2][i]};
  return joinKey (at);
}
} // namespace apps
} // namespace pcl_ext
