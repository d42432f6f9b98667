/*
 * pcl_ext: little-endian values in LAS byte buffers (LAS is little-endian throughout).
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace las {
static_assert (sizeof (double) == 8 && sizeof (float) == 4, "IEEE 754 types expected");

/** The value of type T stored at \a p (the host is little-endian, as LAS is). */
template <typename T>
inline T
get (const std::uint8_t* p)
{
  T value;
  std::memcpy (&value, p, sizeof (T));
  return value;
}

template <typename T>
inline void
put (std::uint8_t* p, T value)
{
  std::memcpy (p, &value, sizeof (T));
}

/** A fixed-size character field: the characters up to the first NUL. */
inline std::string
getString (const std::uint8_t* p, std::size_t size)
{
  std::size_t n = 0;
  while (n < size && p[n] != 0)
    ++n;
  return std::string (reinterpret_cast<const char*> (p), n);
}

/** A fixed-size character field: \a text cut to \a size, NUL-padded. */
inline void
putString (std::uint8_t* p, std::size_t size, const std::string& text)
{
  std::memset (p, 0, size);
  std::memcpy (p, text.data(), std::min (size, text.size()));
}

/** Appends \a value to \a out. */
template <typename T>
inline void
append (std::vector<std::uint8_t>& out, T value)
{
  const std::size_t at = out.size();
  out.resize (at + sizeof (T));
  put (out.data() + at, value);
}
} // namespace las
} // namespace io
} // namespace pcl_ext
