/*
 * pcl_ext: the building blocks of ASTM E2807 (E57) files that the E57 reader is made
 * of: the page checksum, the scan descriptions of the XML section and the bit-packed
 * bytestreams of compressed vectors.
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Physical page size of an E57 file (ASTM E2807 section 9.3): every page ends
 * with a 4-byte checksum of the 1020 bytes before it. */
constexpr std::uint64_t kE57PageSize = 1024;
/** \brief Bytes of payload ("logical" bytes) per physical page. */
constexpr std::uint64_t kE57PagePayload = 1020;

/** \brief CRC-32C (Castagnoli: reflected polynomial 0x82F63B78, initial value and final
 * xor 0xFFFFFFFF), the page checksum of ASTM E2807 section 9.3. E57 stores it in the
 * last 4 bytes of each page most significant byte first. CRC-32C("123456789") is
 * 0xE3069283. */
std::uint32_t
crc32c (const std::uint8_t* data, std::size_t size);

/** \brief Logical offset (payload bytes only) of physical offset \a physical. */
inline std::uint64_t
e57LogicalOffset (std::uint64_t physical)
{
  return physical / kE57PageSize * kE57PagePayload + physical % kE57PageSize;
}

/** \brief The element types a compressed-vector prototype may hold (ASTM E2807 section
 * 8.3: Integer, ScaledInteger and Float; String is not supported by this reader). */
enum class E57FieldType { Integer, ScaledInteger, Float };

/** \brief One terminal element of a compressed vector's prototype: its name, type and
 * declared range, which fix its bit width in the bytestream (section 9.9). */
struct E57Field {
  std::string name;                        ///< element name, e.g. "cartesianX"
  E57FieldType type = E57FieldType::Float; ///< element type
  /** Integer / ScaledInteger: declared raw bounds (defaults: the int64 range). */
  std::int64_t minimum = INT64_MIN, maximum = INT64_MAX;
  double scale = 1.0, offset = 0.0; ///< ScaledInteger: value = raw * scale + offset
  bool single_precision = false;    ///< Float: 32-bit ("single") instead of 64-bit
  /** Both minimum and maximum were written in the file (for Float: as finite values);
   * the bounds below then hold them as values. */
  bool has_bounds = false;
  double value_minimum = 0.0, value_maximum = 0.0; ///< declared bounds as values

  /** \brief Bits per record in the bytestream: 32 or 64 for Float, otherwise the bits
   * of maximum - minimum (0 for a constant). */
  unsigned
  bits () const;
};

/** \brief One data3D scan as the XML section describes it (ASTM E2807 section 8.4). */
struct E57ScanInfo {
  std::string name; ///< the scan's name, empty when absent
  std::string guid; ///< its guid, empty when absent
  /** The pose (section 8.4.3): p_file = rotation * p_scan + translation; identity
   * when absent. The rotation is normalised. */
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  bool has_intensity_limits = false; ///< intensityLimits present
  double intensity_minimum = 0.0, intensity_maximum = 0.0;
  bool has_color_limits = false;             ///< colorLimits present
  double color_minimum[3] = {0.0, 0.0, 0.0}; ///< red, green, blue
  double color_maximum[3] = {0.0, 0.0, 0.0};
  std::uint64_t file_offset = 0;   ///< physical offset of the points' binary section
  std::uint64_t record_count = 0;  ///< declared number of records
  std::vector<E57Field> prototype; ///< terminal elements, in bytestream order
};

/** \brief Parse an E57 XML section (through libexpat): the data3D scans with their
 * pose, limits and point prototype.
 *
 * Prototype elements are flattened depth-first (that is the bytestream order of section
 * 9.9); a nested element is named by its leaf name. Missing numeric values take the
 * standard's defaults (0, the type's range, scale 1).
 *
 * \param[in] xml the XML section's text \param[in] path the file, named in errors
 * \param[out] coordinate_metadata when not null: the root's coordinateMetadata string
 * (section 8.4.1, the file's coordinate reference system), empty when absent
 * \throw ReadError naming \a path when the XML is not well-formed or nested deeper
 * than 64 levels, has no e57Root, when a data3D child has no points CompressedVector
 * (or its fileOffset / recordCount are missing or not numbers), when a prototype holds
 * a String or an unknown type, declares minimum > maximum or a precision other than
 * single / double, has neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation, or
 * when a pose rotation is zero or not finite
 */
std::vector<E57ScanInfo>
parseE57Xml (const std::string& xml,
             const std::string& path,
             std::string* coordinate_metadata = nullptr);

/** \brief Reads values of one bit width from a bytestream (ASTM E2807 section 9.9):
 * value i occupies bits [i * bits, (i + 1) * bits) of the stream, bit k being bit k % 8
 * of byte k / 8 (least significant first). A stream arrives in pieces (one per data
 * packet) and values straddle the pieces, so bytes are appended and values taken as
 * they complete; consumed bytes are dropped.
 */
class E57BitUnpacker {
public:
  /** \param[in] bits the width, 0..64 (0: a constant; every value is 0). */
  explicit E57BitUnpacker (unsigned bits);

  /** \brief Append \a size bytes of the stream. */
  void
  append (const std::uint8_t* data, std::size_t size);

  /** \brief Complete values not yet taken (for width 0: as many as asked). */
  std::uint64_t
  available () const;

  /** \brief The next value, zero-extended; requires available () > 0. */
  std::uint64_t
  next ();

  /** \brief Bits appended and not yet taken. */
  std::uint64_t
  bitsLeft () const
  {
    return buffer_.size() * 8 - position_;
  }

private:
  unsigned bits_;
  std::vector<std::uint8_t> buffer_;
  std::uint64_t position_ = 0; ///< next bit to read in buffer_
};
} // namespace io
} // namespace pcl_ext
