/*
 * pcl_ext: the LAS public header block (ASPRS LAS 1.4 R15, section 2.4).
 */
#include <pcl_ext/io/las_header.h>
#include <pcl_ext/io/read_error.h>

#include "las_bytes.h"

#include <cmath>

namespace pcl_ext {
namespace io {
namespace {
using las::get;
using las::put;

// Offsets of the fields of the public header block (LAS 1.4 R15, Table 3).
constexpr std::size_t kVersionMajor = 24, kSystemIdentifier = 26,
                      kGeneratingSoftware = 58, kCreationDay = 90, kHeaderSize = 94,
                      kOffsetToPoints = 96, kNumberOfVlrs = 100, kPointFormat = 104,
                      kRecordLength = 105, kLegacyCount = 107, kLegacyByReturn = 111,
                      kScale = 131, kOffset = 155, kBounds = 179, kWaveformStart = 227,
                      kEvlrStart = 235, kEvlrCount = 243, kPointCount = 247,
                      kByReturn = 255;
constexpr std::size_t kEvlrHeaderSize = 60;

std::string
number (std::uint64_t n)
{
  return std::to_string (n);
}
} // namespace

std::size_t
lasHeaderSize (int major, int minor)
{
  if (major != 1 || minor < 0 || minor > 4)
    return 0;
  return minor <= 2 ? 227 : minor == 3 ? 235 : 375;
}

std::size_t
lasPointRecordLength (int format)
{
  static const std::size_t lengths[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  return format >= 0 && format <= 10 ? lengths[format] : 0;
}

LasHeader
parseLasHeader (const std::uint8_t* data,
                std::size_t size,
                std::uint64_t file_size,
                const std::string& path)
{
  if (size < 4)
    throw ReadError (path, 0, "truncated LAS header (" + number (size) + " bytes)");
  if (std::string (reinterpret_cast<const char*> (data), 4) != "LASF")
    throw ReadError (path, 0, "not a LAS file (no \"LASF\" signature)");
  if (size < 227 || file_size < 227)
    throw ReadError (
        path, 0, "truncated LAS header (" + number (file_size) + " bytes)");
  LasHeader h;
  h.file_source_id = get<std::uint16_t> (data + 4);
  h.global_encoding = get<std::uint16_t> (data + 6);
  std::copy (data + 8, data + 24, h.project_guid.begin());
  h.version_major = data[kVersionMajor];
  h.version_minor = data[kVersionMajor + 1];
  const std::size_t standard = lasHeaderSize (h.version_major, h.version_minor);
  if (standard == 0)
    throw ReadError (path,
                     0,
                     "unsupported LAS version " + number (h.version_major) + "." +
                         number (h.version_minor) + " (1.0-1.4 are read)");
  h.system_identifier = las::getString (data + kSystemIdentifier, 32);
  h.generating_software = las::getString (data + kGeneratingSoftware, 32);
  h.creation_day = get<std::uint16_t> (data + kCreationDay);
  h.creation_year = get<std::uint16_t> (data + kCreationDay + 2);
  h.header_size = get<std::uint16_t> (data + kHeaderSize);
  h.offset_to_point_data = get<std::uint32_t> (data + kOffsetToPoints);
  h.number_of_vlrs = get<std::uint32_t> (data + kNumberOfVlrs);
  h.point_format_byte = data[kPointFormat];
  h.record_length = get<std::uint16_t> (data + kRecordLength);
  h.legacy_point_count = get<std::uint32_t> (data + kLegacyCount);
  for (std::size_t i = 0; i < 5; ++i)
    h.legacy_points_by_return[i] = get<std::uint32_t> (data + kLegacyByReturn + 4 * i);
  for (int a = 0; a < 3; ++a) {
    h.scale[a] = get<double> (data + kScale + 8 * a);
    h.offset[a] = get<double> (data + kOffset + 8 * a);
    h.max[a] = get<double> (data + kBounds + 16 * a);
    h.min[a] = get<double> (data + kBounds + 16 * a + 8);
  }

  if (h.header_size < standard)
    throw ReadError (path,
                     0,
                     "header size " + number (h.header_size) + " is smaller than the " +
                         number (standard) + " bytes of LAS 1." +
                         number (h.version_minor));
  if (h.header_size > size || h.header_size > file_size)
    throw ReadError (path,
                     0,
                     "truncated LAS header (header size " + number (h.header_size) +
                         ", file " + number (file_size) + " bytes)");
  if (h.version_minor >= 3)
    h.waveform_data_start = get<std::uint64_t> (data + kWaveformStart);
  if (h.version_minor >= 4) {
    h.evlr_start = get<std::uint64_t> (data + kEvlrStart);
    h.evlr_count = get<std::uint32_t> (data + kEvlrCount);
    h.point_count = get<std::uint64_t> (data + kPointCount);
    for (std::size_t i = 0; i < 15; ++i)
      h.points_by_return[i] = get<std::uint64_t> (data + kByReturn + 8 * i);
  }
  // Before 1.4, and in 1.4 files whose writer filled only the legacy fields.
  if (h.point_count == 0 && h.legacy_point_count != 0) {
    h.point_count = h.legacy_point_count;
    for (std::size_t i = 0; i < 5; ++i)
      h.points_by_return[i] = h.legacy_points_by_return[i];
  }
  h.extra_header_bytes.assign (data + standard, data + h.header_size);

  if (h.offset_to_point_data < h.header_size)
    throw ReadError (path,
                     0,
                     "offset to point data " + number (h.offset_to_point_data) +
                         " lies inside the " + number (h.header_size) + "-byte header");
  if (h.offset_to_point_data > file_size)
    throw ReadError (path,
                     0,
                     "offset to point data " + number (h.offset_to_point_data) +
                         " is past the end of the file (" + number (file_size) +
                         " bytes)");
  const int format = h.pointFormat();
  if (lasPointRecordLength (format) == 0)
    throw ReadError (path,
                     0,
                     "unknown point data record format " + number (format) +
                         " (0-10 are defined)");
  if (h.record_length < lasPointRecordLength (format))
    throw ReadError (path,
                     0,
                     "point record length " + number (h.record_length) +
                         " is shorter than the " +
                         number (lasPointRecordLength (format)) + " bytes of format " +
                         number (format));
  // A coordinate (int32 * scale + offset) must stay far from the float range, so that
  // local coordinates are finite whatever the origin.
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite (h.scale[a]) && h.scale[a] != 0.0 &&
          std::isfinite (h.offset[a]) &&
          std::abs (h.scale[a]) * 2147483648.0 + std::abs (h.offset[a]) < 1e37))
      throw ReadError (path,
                       0,
                       std::string ("invalid ") + "xyz"[a] +
                           " scale or offset (a scale must be non-zero and both must "
                           "keep coordinates below 1e37)");
  const std::uint64_t room = file_size - h.offset_to_point_data;
  if (!h.isCompressed() && h.point_count > room / h.record_length)
    throw ReadError (path,
                     0,
                     "point count " + number (h.point_count) +
                         " is larger than the file holds (" + number (room) +
                         " bytes of " + number (h.record_length) + "-byte records)");
  if (h.evlr_count > 0) {
    const std::uint64_t points_end =
        h.isCompressed() ? h.offset_to_point_data
                         : h.offset_to_point_data + h.point_count * h.record_length;
    if (h.evlr_start < points_end || h.evlr_start > file_size ||
        (file_size - h.evlr_start) / kEvlrHeaderSize < h.evlr_count)
      throw ReadError (
          path,
          0,
          "the " + number (h.evlr_count) + " EVLRs at " + number (h.evlr_start) +
              " do not lie between the point data and the end of the file");
  }
  return h;
}

std::vector<std::uint8_t>
encodeLasHeader (const LasHeader& h)
{
  const std::size_t standard = lasHeaderSize (h.version_major, h.version_minor);
  std::vector<std::uint8_t> out (
      std::max<std::size_t> (h.header_size, standard + h.extra_header_bytes.size()));
  std::uint8_t* p = out.data();
  std::copy_n ("LASF", 4, p);
  put (p + 4, h.file_source_id);
  put (p + 6, h.global_encoding);
  std::copy (h.project_guid.begin(), h.project_guid.end(), p + 8);
  p[kVersionMajor] = h.version_major;
  p[kVersionMajor + 1] = h.version_minor;
  las::putString (p + kSystemIdentifier, 32, h.system_identifier);
  las::putString (p + kGeneratingSoftware, 32, h.generating_software);
  put (p + kCreationDay, h.creation_day);
  put (p + kCreationDay + 2, h.creation_year);
  put (p + kHeaderSize, static_cast<std::uint16_t> (out.size()));
  put (p + kOffsetToPoints, h.offset_to_point_data);
  put (p + kNumberOfVlrs, h.number_of_vlrs);
  p[kPointFormat] = h.point_format_byte;
  put (p + kRecordLength, h.record_length);
  put (p + kLegacyCount, h.legacy_point_count);
  for (std::size_t i = 0; i < 5; ++i)
    put (p + kLegacyByReturn + 4 * i, h.legacy_points_by_return[i]);
  for (int a = 0; a < 3; ++a) {
    put (p + kScale + 8 * a, h.scale[a]);
    put (p + kOffset + 8 * a, h.offset[a]);
    put (p + kBounds + 16 * a, h.max[a]);
    put (p + kBounds + 16 * a + 8, h.min[a]);
  }
  if (h.version_minor >= 3)
    put (p + kWaveformStart, h.waveform_data_start);
  if (h.version_minor >= 4) {
    put (p + kEvlrStart, h.evlr_start);
    put (p + kEvlrCount, h.evlr_count);
    put (p + kPointCount, h.point_count);
    for (std::size_t i = 0; i < 15; ++i)
      put (p + kByReturn + 8 * i, h.points_by_return[i]);
  }
  std::copy (h.extra_header_bytes.begin(), h.extra_header_bytes.end(), p + standard);
  return out;
}
} // namespace io
} // namespace pcl_ext
