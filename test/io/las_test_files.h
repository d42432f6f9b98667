/*
 * Helpers for the LAS tests: small LAS files built byte by byte at the offsets of the
 * specification (ASPRS LAS 1.4 R15, section 2.4), independently of the library's own
 * header encoder, and the fields of a PCLPointCloud2 read back.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace las_test {
template <typename T>
inline void
put (std::vector<std::uint8_t>& b, std::size_t at, T v)
{
  if (b.size() < at + sizeof (T))
    b.resize (at + sizeof (T));
  std::memcpy (b.data() + at, &v, sizeof (T));
}

template <typename T>
inline T
get (const std::uint8_t* p)
{
  T v;
  std::memcpy (&v, p, sizeof (T));
  return v;
}

inline void
putText (std::vector<std::uint8_t>& b, std::size_t at, const std::string& s)
{
  if (b.size() < at + s.size())
    b.resize (at + s.size());
  std::memcpy (b.data() + at, s.data(), s.size());
}

struct Vlr {
  std::string user_id;
  std::uint16_t record_id = 0;
  std::string description;
  std::vector<std::uint8_t> data;
};

/** A LAS file: header fields, VLRs, raw point records, EVLRs (1.4). */
struct LasFile {
  int minor = 4;
  std::uint8_t format_byte = 6;
  std::uint16_t record_length = 30;
  std::uint64_t count = 0;
  double scale[3] = {0.01, 0.01, 0.01};
  double offset[3] = {0, 0, 0};
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
  std::vector<Vlr> vlrs, evlrs;
  std::vector<std::uint8_t> records;
  std::uint64_t waveform_start = 0;

  std::size_t
  headerSize () const
  {
    return minor <= 2 ? 227 : minor == 3 ? 235 : 375;
  }

  std::vector<std::uint8_t>
  bytes () const
  {
    std::vector<std::uint8_t> b (headerSize(), 0);
    putText (b, 0, "LASF");
    b[24] = 1;
    b[25] = static_cast<std::uint8_t> (minor);
    putText (b, 26, "TEST SYSTEM");
    putText (b, 58, "las_test_files.h");
    put<std::uint16_t> (b, 90, 100);
    put<std::uint16_t> (b, 92, 2024);
    put<std::uint16_t> (b, 94, static_cast<std::uint16_t> (headerSize()));
    std::size_t offset_to_points = headerSize();
    for (const auto& v : vlrs)
      offset_to_points += 54 + v.data.size();
    put<std::uint32_t> (b, 96, static_cast<std::uint32_t> (offset_to_points));
    put<std::uint32_t> (b, 100, static_cast<std::uint32_t> (vlrs.size()));
    b[104] = format_byte;
    put<std::uint16_t> (b, 105, record_length);
    put<std::uint32_t> (
        b, 107, minor < 4 || (format_byte & 0x3F) < 6 ? std::uint32_t (count) : 0u);
    for (int a = 0; a < 3; ++a) {
      put<double> (b, 131 + 8 * a, scale[a]);
      put<double> (b, 155 + 8 * a, offset[a]);
      put<double> (b, 179 + 16 * a, max[a]);
      put<double> (b, 187 + 16 * a, min[a]);
    }
    if (minor >= 3)
      put<std::uint64_t> (b, 227, waveform_start);
    if (minor >= 4) {
      put<std::uint64_t> (
          b, 235, evlrs.empty() ? 0 : offset_to_points + records.size());
      put<std::uint32_t> (b, 243, static_cast<std::uint32_t> (evlrs.size()));
      put<std::uint64_t> (b, 247, count);
    }
    for (const auto& v : vlrs) {
      const std::size_t at = b.size();
      b.resize (at + 54);
      putText (b, at + 2, v.user_id);
      put<std::uint16_t> (b, at + 18, v.record_id);
      put<std::uint16_t> (b, at + 20, static_cast<std::uint16_t> (v.data.size()));
      putText (b, at + 22, v.description);
      b.insert (b.end(), v.data.begin(), v.data.end());
    }
    b.insert (b.end(), records.begin(), records.end());
    for (const auto& v : evlrs) {
      const std::size_t at = b.size();
      b.resize (at + 60);
      putText (b, at + 2, v.user_id);
      put<std::uint16_t> (b, at + 18, v.record_id);
      put<std::uint64_t> (b, at + 20, v.data.size());
      putText (b, at + 28, v.description);
      b.insert (b.end(), v.data.begin(), v.data.end());
    }
    return b;
  }

  /** \a n records of random bytes (every bit field takes random values). */
  void
  randomRecords (std::size_t n, unsigned seed)
  {
    std::mt19937 rng (seed);
    records.resize (n * record_length);
    for (auto& byte : records)
      byte = static_cast<std::uint8_t> (rng());
    count = n;
  }
};

inline void
writeBytes (const std::string& path, const std::vector<std::uint8_t>& bytes)
{
  std::ofstream out (path, std::ios::binary);
  out.write (reinterpret_cast<const char*> (bytes.data()), bytes.size());
}

inline std::vector<std::uint8_t>
readBytes (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  return std::vector<std::uint8_t> ((std::istreambuf_iterator<char> (in)),
                                    std::istreambuf_iterator<char>());
}

/** The field \a name of \a cloud; fails the test when absent. */
inline const pcl::PCLPointField*
field (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (const auto& f : cloud.fields)
    if (f.name == name)
      return &f;
  ADD_FAILURE() << "no field " << name;
  return nullptr;
}

inline bool
hasField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (const auto& f : cloud.fields)
    if (f.name == name)
      return true;
  return false;
}

/** The value of field \a name of point \a i (first element plus \a element). */
template <typename T>
inline T
value (const pcl::PCLPointCloud2& cloud,
       const std::string& name,
       std::size_t i,
       std::size_t element = 0)
{
  const pcl::PCLPointField* f = field (cloud, name);
  if (f == nullptr)
    return T();
  return get<T> (cloud.data.data() + i * cloud.point_step + f->offset +
                 element * sizeof (T));
}

/** An extra-bytes descriptor (192 bytes, LAS 1.4 R15 Table 24). */
inline std::vector<std::uint8_t>
extraBytesDescriptor (std::uint8_t type,
                      const std::string& name,
                      std::uint8_t options = 0,
                      double scale = 1.0,
                      double offset = 0.0)
{
  std::vector<std::uint8_t> d (192, 0);
  d[2] = type;
  d[3] = options;
  putText (d, 4, name);
  for (int e = 0; e < 3; ++e) {
    put<double> (d, 112 + 8 * e, scale);
    put<double> (d, 136 + 8 * e, offset);
  }
  putText (d, 160, "test " + name);
  return d;
}
} // namespace las_test
