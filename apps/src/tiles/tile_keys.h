/*
 * pcl_ext_tiles: 64-bit sampling keys (pcl_ext::hashPosition) saved as tile values,
 * which are floats: three parts of at most 22 bits, each exact in a float.
 */
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief Append \a key to the tile values \a names (high, middle, low part). */
inline void
appendKey (std::map<std::string, std::vector<float>>& values,
           const char* const names[3],
           std::uint64_t key)
{
  values[names[0]].push_back (static_cast<float> (key >> 42));
  values[names[1]].push_back (static_cast<float> ((key >> 20) & 0x3FFFFF));
  values[names[2]].push_back (static_cast<float> (key & 0xFFFFF));
}

/** \brief The key of value \a i of the three parts appendKey wrote. */
inline std::uint64_t
keyAt (const std::vector<float> parts[3], std::size_t i)
{
  return (static_cast<std::uint64_t> (parts[0][i]) << 42) |
         (static_cast<std::uint64_t> (parts[1][i]) << 20) |
         static_cast<std::uint64_t> (parts[2][i]);
}
} // namespace apps
} // namespace pcl_ext
