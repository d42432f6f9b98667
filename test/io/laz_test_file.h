/*
 * Helpers for the LAZ tests: just enough of a LAS header to find the point data, the
 * LASzip VLR and the records (ASPRS LAS 1.4 R15, table 3 and 2.5), and a whole file's
 * records decoded through makeLazRecordSource.
 */
#pragma once

#include <pcl_ext/io/laz_record_source.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

struct LasTestFile {
  std::vector<std::uint8_t> bytes;
  std::uint8_t version_minor = 0;
  std::uint32_t point_data_offset = 0;
  int point_format = 0; // compression bits cleared
  bool compressed = false;
  std::uint16_t record_length = 0;
  std::uint64_t point_count = 0;
  std::uint32_t points_by_return[5] = {0, 0, 0, 0, 0};
  double scale[3] = {0, 0, 0};
  double offset[3] = {0, 0, 0};
  double max_min[6] = {0, 0, 0, 0, 0, 0}; // max x, min x, max y, min y, max z, min z
  std::vector<std::uint8_t> laszip_vlr;
};

template <typename T>
T
lasField (const std::vector<std::uint8_t>& bytes, std::size_t at)
{
  if (at + sizeof (T) > bytes.size())
    throw std::runtime_error ("LAS header field past the end of the file");
  T v;
  std::memcpy (&v, bytes.data() + at, sizeof (T));
  return v;
}

inline LasTestFile
readLasTestFile (const std::string& path)
{
  LasTestFile f;
  std::ifstream in (path, std::ios::binary);
  f.bytes.assign (std::istreambuf_iterator<char> (in),
                  std::istreambuf_iterator<char>());
  const auto& b = f.bytes;
  f.version_minor = lasField<std::uint8_t> (b, 25);
  const auto header_size = lasField<std::uint16_t> (b, 94);
  f.point_data_offset = lasField<std::uint32_t> (b, 96);
  const auto vlr_count = lasField<std::uint32_t> (b, 100);
  const auto format = lasField<std::uint8_t> (b, 104);
  f.compressed = (format & 0xC0) != 0;
  f.point_format = format & 0x3F;
  f.record_length = lasField<std::uint16_t> (b, 105);
  f.point_count = lasField<std::uint32_t> (b, 107);
  for (int i = 0; i < 5; ++i)
    f.points_by_return[i] = lasField<std::uint32_t> (b, 111 + 4 * i);
  for (int i = 0; i < 3; ++i) {
    f.scale[i] = lasField<double> (b, 131 + 8 * i);
    f.offset[i] = lasField<double> (b, 155 + 8 * i);
  }
  for (int i = 0; i < 6; ++i)
    f.max_min[i] = lasField<double> (b, 179 + 8 * i);
  if (f.version_minor >= 4)
    f.point_count = lasField<std::uint64_t> (b, 247);
  std::size_t at = header_size;
  for (std::uint32_t i = 0; i < vlr_count; ++i) {
    const auto record_id = lasField<std::uint16_t> (b, at + 18);
    const auto length = lasField<std::uint16_t> (b, at + 20);
    const std::string user (
        reinterpret_cast<const char*> (b.data() + at + 2),
        ::strnlen (reinterpret_cast<const char*> (b.data() + at + 2), 16));
    if (user == "laszip encoded" && record_id == 22204 && at + 54 + length <= b.size())
      f.laszip_vlr.assign (b.begin() + at + 54, b.begin() + at + 54 + length);
    at += 54 + length;
  }
  return f;
}

/** The records of an uncompressed LAS file. */
inline std::vector<std::uint8_t>
lasRecords (const LasTestFile& f)
{
  const std::size_t size = f.point_count * f.record_length;
  if (f.point_data_offset + size > f.bytes.size())
    throw std::runtime_error ("LAS records past the end of the file");
  return {f.bytes.begin() + f.point_data_offset,
          f.bytes.begin() + f.point_data_offset + size};
}

/** The records of a LAZ file, decoded \a block records at a time. */
inline std::vector<std::uint8_t>
lazRecords (const std::string& path, const LasTestFile& f, std::size_t block = 1000)
{
  auto source = pcl_ext::io::makeLazRecordSource (path,
                                                  f.point_data_offset,
                                                  f.point_format,
                                                  f.record_length,
                                                  f.point_count,
                                                  f.laszip_vlr);
  std::vector<std::uint8_t> records (f.point_count * f.record_length);
  std::size_t done = 0;
  while (done < f.point_count) {
    const std::size_t n =
        source->readRecords (std::min<std::size_t> (block, f.point_count - done),
                             records.data() + done * f.record_length);
    if (n == 0)
      break;
    done += n;
  }
  records.resize (done * f.record_length);
  return records;
}
