/*
 * A small LAZ point data block for the record source tests: one chunk of point format 3
 * (a raw record and zero bytes, whose second point follows from the item definitions,
 * see test_laz_chunk_decoder.cpp) with the chunk table of simple.laz, which gives that
 * chunk 17,862 bytes, and the LASzip VLR that describes it.
 */
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace laz_chunk {
constexpr std::uint64_t point_data_offset = 100;
constexpr std::size_t chunk_bytes = 17862; // what simple.laz's chunk table encodes

inline void
put (std::vector<std::uint8_t>& v, std::uint64_t x, int bytes)
{
  for (int i = 0; i < bytes; ++i)
    v.push_back (static_cast<std::uint8_t> (x >> (8 * i)));
}

inline std::vector<std::uint8_t>
vlr (std::uint16_t compressor, std::uint32_t chunk_size, int point_format)
{
  std::vector<std::uint8_t> v;
  put (v, compressor, 2);
  put (v, 0, 2);
  put (v, 0x0003'0403, 4); // LASzip 3.4 revision 3
  put (v, 0, 4);
  put (v, chunk_size, 4);
  put (v, ~std::uint64_t (0), 8);
  put (v, ~std::uint64_t (0), 8);
  if (point_format == 3) {
    put (v, 3, 2);
    for (const std::uint16_t item : {6, 20, 2, 7, 8, 2, 8, 6, 2})
      put (v, item, 2);
  }
  else {
    put (v, 1, 2);
    for (const std::uint16_t item : {10, 30, 3})
      put (v, item, 2);
  }
  return v;
}

inline std::vector<std::uint8_t>
firstRecord ()
{
  std::vector<std::uint8_t> r (34, 0);
  const std::int32_t xyz[3] = {1000, -2000, 300};
  std::memcpy (r.data(), xyz, 12);
  r[12] = 0x2B; // intensity 555
  r[13] = 0x02;
  r[14] = 1 | (2 << 3);
  r[15] = 2;
  const double gps = 1234.5;
  std::memcpy (r.data() + 20, &gps, 8);
  const std::uint16_t rgb[3] = {0x0102, 0x0304, 0x0506};
  std::memcpy (r.data() + 28, rgb, 6);
  return r;
}

/** The second point a zero stream decodes: z 0, intensity 0, green = blue = red. */
inline std::vector<std::uint8_t>
secondRecord ()
{
  std::vector<std::uint8_t> r = firstRecord();
  std::memset (r.data() + 8, 0, 6);
  r[30] = r[32] = 0x02;
  r[31] = r[33] = 0x01;
  return r;
}

/** File bytes: filler up to the point data, the table offset, the chunk, the table. */
inline std::vector<std::uint8_t>
lazBytes (std::int64_t table_offset_field)
{
  std::vector<std::uint8_t> f (point_data_offset, 0);
  put (f, static_cast<std::uint64_t> (table_offset_field), 8);
  const std::vector<std::uint8_t> record = firstRecord();
  f.insert (f.end(), record.begin(), record.end());
  f.resize (point_data_offset + 8 + chunk_bytes, 0);
  put (f, 0, 4); // chunk table version
  put (f, 1, 4); // one chunk
  for (const std::uint8_t b : {0x78, 0x96, 0x05, 0x00, 0x00, 0x00})
    f.push_back (b);
  return f;
}

constexpr std::int64_t table_offset = point_data_offset + 8 + chunk_bytes;
} // namespace laz_chunk
