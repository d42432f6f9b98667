/*
 * pcl_ext: where each dimension of a LAS point record lies (ASPRS LAS 1.4 R15, sections
 * 2.6.1-2.6.11 and 2.6.3), which PCL field it becomes, and the decoding of records into
 * points with that layout precomputed.
 */
#pragma once

#include <pcl_ext/io/las_header.h>

#include <pcl/PCLPointField.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace las {
/** How a value is stored in a record: the PCL type codes are reused for it. */
using Type = std::uint8_t;

/** A standard dimension of a point format other than X, Y, Z. */
struct Dimension {
  const char* name;   ///< the PCL field name
  std::size_t offset; ///< byte in the record
  Type storage;       ///< the stored type (a PCL type code)
  int shift;          ///< bit fields: first bit
  int bits;           ///< bit fields: width; 0 for a whole value
  Type field;         ///< the PCL field type
};

/** The standard dimensions of point format \a format (0-10), X, Y, Z excepted, in
 * record order. Colour (formats 2, 3, 5, 7, 8, 10) is red, green, blue; the packed
 * `rgb` field is added by the layout. */
std::vector<Dimension>
standardDimensions (int format);

/** Whether \a format stores red, green and blue, and where. */
bool
hasColour (int format, std::size_t* red_offset = nullptr);

/** Bytes of a value of PCL type \a type. */
std::size_t
typeSize (Type type);

/** The PCL type of one element of extra bytes of base type \a base (0-10). */
Type
extraBytesFieldType (int base);

/** The PCL field name of each extra-bytes descriptor: its name, or "extra_bytes_<i>"
 * when empty, with "_extra" appended while it collides with a name in \a taken (to
 * which the chosen names are added). */
std::vector<std::string>
extraBytesFieldNames (const std::vector<LasExtraBytesDescriptor>& descriptors,
                      std::vector<std::string>& taken);

/** One step of the decoding: one field of every record of a block. */
struct DecodeStep {
  enum Kind {
    Copy,       ///< `bytes` bytes as they are
    Bits,       ///< (byte >> shift) & mask into a uint8
    Intensity,  ///< uint16 into float
    Coordinate, ///< int32 * scale + shift into float (axis)
    Rgb,        ///< three uint16 into PCL's packed float rgb
    Scaled      ///< an extra-bytes element of base type `base` * scale + offset
  };
  Kind kind;
  std::size_t src, dst, bytes = 0;
  int shift = 0, axis = 0, base = 0;
  std::uint8_t mask = 0;
  double scale = 1.0, offset = 0.0;
};

/** The fields of the cloud read from one file and how to fill them. */
struct PointLayout {
  std::vector<pcl::PCLPointField> fields;
  std::uint32_t point_step = 0;
  std::vector<DecodeStep> steps;
};

/** The layout of the points of a file with point format \a format, records of \a
 * record_length bytes and the extra bytes \a extra (already checked to fit): x y z,
 * intensity, the other standard dimensions, rgb, the extra-bytes fields, the record
 * integers las_x las_y las_z, and the bytes no descriptor covers as uint8
 * "extra_bytes". */
PointLayout
makePointLayout (int format,
                 std::size_t record_length,
                 const std::vector<LasExtraBytesDescriptor>& extra);

/** Coordinates: local = X * scale + shift, shift = header offset - origin. */
struct CoordinateTransform {
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
};

/** Decode \a n records of \a record_length bytes at \a records into \a n points of the
 * layout at \a out. \a colour_shift: 8 divides 16-bit colour by 256 for rgb, 0 takes
 * 8-bit colour as it is. */
void
decodeRecords (const PointLayout& layout,
               const CoordinateTransform& transform,
               int colour_shift,
               const std::uint8_t* records,
               std::size_t record_length,
               std::size_t n,
               std::uint8_t* out);
} // namespace las
} // namespace io
} // namespace pcl_ext
