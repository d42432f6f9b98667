/*
 * pcl_ext: the public header block, variable length records and extra-bytes descriptors
 * of LAS 1.0-1.4 files (ASPRS LAS 1.4 R15).
 */
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief The public header block of a LAS 1.0-1.4 file (LAS 1.4 R15, section 2.4).
 *
 * Fields a version does not have keep their defaults (0): the 1.3 waveform start and
 * the 1.4 EVLR and 64-bit counts. The 64-bit point_count and points_by_return are
 * filled for every version (from the legacy 32-bit fields before 1.4, so that callers
 * read one place); legacy_* keep what the file says.
 */
struct LasHeader {
  std::uint16_t file_source_id = 0;
  /** Bit 0 GPS time is adjusted standard GPS time, bit 1 waveform data internal (1.3),
   * bit 2 external, bit 3 synthetic return numbers, bit 4 CRS is WKT (1.4). */
  std::uint16_t global_encoding = 0;
  std::array<std::uint8_t, 16> project_guid{}; ///< the 16 GUID bytes as stored
  std::uint8_t version_major = 1;
  std::uint8_t version_minor = 4;
  std::string system_identifier;   ///< up to 32 characters
  std::string generating_software; ///< up to 32 characters
  std::uint16_t creation_day = 0;  ///< day of the year, 1-366
  std::uint16_t creation_year = 0;
  std::uint16_t header_size = 375; ///< as stored; at least lasHeaderSize (version)
  std::uint32_t offset_to_point_data = 375;
  std::uint32_t number_of_vlrs = 0;
  /** The point data record format byte as stored, compression bits included. */
  std::uint8_t point_format_byte = 6;
  std::uint16_t record_length = 30; ///< bytes per point record, extra bytes included
  std::uint32_t legacy_point_count = 0;
  std::array<std::uint32_t, 5> legacy_points_by_return{};
  Eigen::Vector3d scale = Eigen::Vector3d::Constant (0.001);
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  std::uint64_t waveform_data_start = 0; ///< 1.3 and later
  std::uint64_t evlr_start = 0;          ///< 1.4
  std::uint32_t evlr_count = 0;          ///< 1.4
  std::uint64_t point_count = 0;         ///< the number of points (every version)
  std::array<std::uint64_t, 15> points_by_return{}; ///< every version
  /** Bytes of the header beyond the standard size of its version (header_size larger
   * than lasHeaderSize: user data kept as it is). */
  std::vector<std::uint8_t> extra_header_bytes;

  /** \brief The point data record format, 0-10, compression bits (7 and 6) cleared. */
  int
  pointFormat () const
  {
    return point_format_byte & 0x3F;
  }

  /** \brief Whether the point data is LAZ-compressed: bit 7 (or bit 6, used by some
   * writers) of the point format byte is set. */
  bool
  isCompressed () const
  {
    return (point_format_byte & 0xC0) != 0;
  }
};

/** \brief A variable length record (LAS 1.4 R15, section 2.5) or an extended one
 * (section 2.7). */
struct LasVariableLengthRecord {
  std::uint16_t reserved = 0;
  std::string user_id; ///< up to 16 characters, e.g. "LASF_Projection"
  std::uint16_t record_id = 0;
  std::string description; ///< up to 32 characters
  std::vector<std::uint8_t> data;
  bool extended = false; ///< an EVLR (64-bit length, after the point data)
};

/** \brief One extra-bytes descriptor (LAS 1.4 R15, section 2.6.3: user id "LASF_Spec",
 * record id 4, 192 bytes each).
 *
 * data_type 0 is an undocumented run of \a options bytes; 1-10 are uchar, char,
 * ushort, short, ulong, long, ulonglong, longlong, float, double; the deprecated 11-30
 * (LAS 1.4 R13 and earlier) are arrays of 2 (11-20) or 3 (21-30) of those, read and
 * written as such.
 */
struct LasExtraBytesDescriptor {
  std::array<std::uint8_t, 2> reserved{};
  std::uint8_t data_type = 0;
  /** Bit 0 no_data, 1 min, 2 max, 3 scale, 4 offset are meaningful; for data_type 0 the
   * number of bytes. */
  std::uint8_t options = 0;
  std::string name; ///< up to 32 characters
  std::array<std::uint8_t, 4> unused{};
  /** no_data, min and max as stored: 8 bytes per element, read as the type says. */
  std::array<std::array<std::uint8_t, 8>, 3> no_data{}, min{}, max{};
  std::array<double, 3> scale{}, offset{};
  std::string description; ///< up to 32 characters

  /** \brief 1-3 elements (1 for data_type 0: one run of bytes). */
  int
  elements () const;

  /** \brief Bytes of one element: 1, 2, 4 or 8 (data_type 0: the run's length). */
  std::size_t
  elementSize () const;

  /** \brief Bytes it takes in a point record. */
  std::size_t
  size () const
  {
    return elementSize() * static_cast<std::size_t> (elements());
  }

  /** \brief The base type 1-10 (0 for undocumented bytes). */
  int
  baseType () const;

  bool
  hasScale () const
  {
    return (options & 0x08) != 0;
  }

  bool
  hasOffset () const
  {
    return (options & 0x10) != 0;
  }

  /** \brief Whether the PCL field carries value * scale + offset (FLOAT64) rather than
   * the raw value: when the scale or the offset bit is set. */
  bool
  isScaled () const
  {
    return hasScale() || hasOffset();
  }
};

/** \brief Everything a LAS file holds besides its points, as the reader found it and
 * as the writer takes it to write a file like it. */
struct LasFileInfo {
  LasHeader header;
  std::vector<LasVariableLengthRecord> vlrs;
  std::vector<LasVariableLengthRecord> evlrs; ///< except waveform data packets
  std::vector<LasExtraBytesDescriptor> extra_bytes;
  /** Bytes between the last VLR and the point data (e.g. the 1.0 start-of-data
   * signature 0xDD 0xCC), kept as they are. */
  std::vector<std::uint8_t> pre_point_bytes;
  /** The origin subtracted from the coordinates of the cloud read (see LasReader). */
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/** \brief Size of the standard header of LAS 1.\a minor (LAS 1.4 R15, section 2.4 and
 * the earlier versions' header tables): 227 bytes (1.0-1.2), 235 (1.3), 375 (1.4); 0
 * for any other version. */
std::size_t
lasHeaderSize (int major, int minor);

/** \brief Standard record length of point data record format \a format (0-10, LAS 1.4
 * R15, sections 2.6.1-2.6.11): 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67; 0 for an
 * unknown format. */
std::size_t
lasPointRecordLength (int format);

/** \brief Parse and check the public header block (LAS 1.4 R15, section 2.4).
 *
 * \param[in] data the first \a size bytes of the file (at least the header's own
 * size) \param[in] file_size the size of the whole file, against which every offset
 * and count is checked \param[in] path the file, named in errors \throw ReadError when
 * the file is shorter than a header, the signature is not "LASF", the version is not
 * 1.0-1.4, the header size is smaller than the version's, the offset to point data lies
 * inside the header or past the end, the point format is not 0-10, the record length is
 * smaller than the format's, a scale is 0 or a scale or offset is not finite, the
 * points (uncompressed) or the EVLRs do not fit in the file
 */
LasHeader
parseLasHeader (const std::uint8_t* data,
                std::size_t size,
                std::uint64_t file_size,
                const std::string& path);

/** \brief The header as LAS \a header.version_minor stores it: header_size bytes
 * (extra_header_bytes last). Legacy and 64-bit counts are written as given. */
std::vector<std::uint8_t>
encodeLasHeader (const LasHeader& header);

/** \brief Whether \a vlr is the extra-bytes record (LAS 1.4 R15, section 2.6.3: user
 * id "LASF_Spec", record id 4). */
bool
isExtraBytesRecord (const LasVariableLengthRecord& vlr);

/** \brief Whether \a vlr is the LASzip record (user id "laszip encoded", record id
 * 22204: the LASzip format's, not the LAS specification's). */
bool
isLaszipRecord (const LasVariableLengthRecord& vlr);

/** \brief The descriptors of an extra-bytes record (LAS 1.4 R15, section 2.6.3).
 *
 * \throw ReadError naming \a path when the payload is not a multiple of 192 bytes or a
 * data type is above 30 or 0 with a length of 0
 */
std::vector<LasExtraBytesDescriptor>
parseExtraBytes (const LasVariableLengthRecord& vlr, const std::string& path);

/** \brief The 192-byte form of each descriptor (LAS 1.4 R15, section 2.6.3), in order:
 * the payload of the extra-bytes record. */
std::vector<std::uint8_t>
encodeExtraBytes (const std::vector<LasExtraBytesDescriptor>& descriptors);
} // namespace io
} // namespace pcl_ext
