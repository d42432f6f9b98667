/*
 * pcl_ext: LAS 1.0-1.4 files read in chunks into pcl::PCLPointCloud2 (ASPRS LAS 1.4
 * R15).
 */
#pragma once

#include <pcl_ext/io/las_header.h>
#include <pcl_ext/io/las_record_source.h>
#include <pcl_ext/io/read_error.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Streams the points of a LAS 1.0-1.4 file (ASPRS LAS 1.4 R15,
 * sections 2.4-2.7) into pcl::PCLPointCloud2 chunks; LAZ files through
 * makeLazRecordSource.
 *
 * open() reads and checks the header, VLRs and EVLRs (every count and offset against
 * the file size); read() then returns the points in chunks, so that a file is never
 * held whole. Both the uncompressed and the compressed point data come from a
 * LasRecordSource (a file read in blocks, or the LAZ decoder) and are decoded a block
 * at a time with a layout computed once per file.
 *
 * Fields of each chunk (width = points, height = 1, is_dense = true):
 * - `x y z` FLOAT32: file coordinate - origin, computed as X * scale + (offset -
 *   origin) in double, then rounded to float. The origin (getOrigin) is, per axis, 0
 *   when the header's bounding box lies within +-8192 m (kFloatSafeCoordinate: local
 *   data stays as it is), else the box's centre rounded to a multiple of 100 m (the
 *   header offset rounded so when the box is not finite); setOrigin chooses another.
 * - `intensity` FLOAT32 (exact for uint16), `return_number`, `number_of_returns`,
 *   `scan_direction_flag`, `edge_of_flight_line`, `classification` (formats 0-5: the
 * low 5 bits), `flags` (bit 0 synthetic, 1 key-point, 2 withheld, 3 overlap),
 *   `scanner_channel` (formats 6-10), `user_data`: UINT8; `scan_angle_rank` INT8
 *   (formats 0-5, degrees) or `scan_angle` INT16 (formats 6-10, 0.006 degrees);
 *   `point_source_id` UINT16; `gps_time` FLOAT64; `red green blue` UINT16 and a packed
 *   FLOAT32 `rgb` (as pcl::PointXYZRGB: the 16-bit values / 256, or the values as
 *   they are when every colour of the first 8192 points is <= 255: files storing 8-bit
 *   colour); `nir` UINT16; `wave_packet_descriptor_index` UINT8, `wave_packet_offset`
 *   UINT64, `wave_packet_size` UINT32, `wave_return_location wave_x_t wave_y_t
 *   wave_z_t` FLOAT32.
 * - each extra-bytes dimension under its descriptor's name ("_extra" appended on a
 *   clash, "extra_bytes_<i>" when unnamed): its own type (count 2 or 3 for the
 *   deprecated array types, UINT8 x length for undocumented bytes), or FLOAT64 holding
 *   raw * scale + offset when the descriptor sets the scale or offset bit; no_data
 *   values are kept as they are. Record bytes no descriptor covers: UINT8
 * `extra_bytes`.
 * - `las_x las_y las_z` INT32: the record's integers. saveLas uses them instead of
 *   recomputing from x y z when the file is written with this file's scale and offset
 *   and the same origin and converting them as above gives x y z exactly, so that
 *   points that were not moved keep their integers (float x y z cannot always hold
 *   the file's resolution, e.g. a 1e-6 scale).
 *
 * Usage:
 * \code
 * pcl_ext::io::LasReader reader;
 * reader.open ("scan.las");
 * pcl::PCLPointCloud2 chunk;
 * while (reader.read (1000000, chunk) > 0)
 *   process (chunk); // coordinates relative to reader.getOrigin ()
 * \endcode
 */
class LasReader {
public:
  LasReader();
  ~LasReader();
  LasReader (const LasReader&) = delete;
  LasReader&
  operator= (const LasReader&) = delete;

  /** \brief Open \a path and read its header, VLRs and EVLRs (the points are read by
   * read()). \throw ReadError naming the file when it cannot be opened or is malformed
   * (see parseLasHeader: also a VLR or EVLR running past the point data or the file, an
   * invalid extra-bytes record or one describing more bytes than a record has, a
   * compressed file without a LASzip VLR, or LAZ decompression unavailable) */
  void
  open (const std::string& path);

  /** \brief The public header block. */
  const LasHeader&
  getHeader () const
  {
    return info_.header;
  }

  /** \brief The variable length records, in file order. */
  const std::vector<LasVariableLengthRecord>&
  getVariableLengthRecords () const
  {
    return info_.vlrs;
  }

  /** \brief The extended variable length records (LAS 1.4), waveform data packets
   * excepted (waveform data is not read). */
  const std::vector<LasVariableLengthRecord>&
  getExtendedVariableLengthRecords () const
  {
    return info_.evlrs;
  }

  /** \brief The extra-bytes descriptors (empty without an extra-bytes record). */
  const std::vector<LasExtraBytesDescriptor>&
  getExtraBytes () const
  {
    return info_.extra_bytes;
  }

  /** \brief Everything but the points, with the origin: what saveLas takes as \a like.
   */
  const LasFileInfo&
  getFileInfo () const
  {
    return info_;
  }

  /** \brief The origin subtracted from the coordinates (see the class comment). */
  const Eigen::Vector3d&
  getOrigin () const
  {
    return info_.origin;
  }

  /** \brief Use \a origin for the chunks read from now on (e.g. one origin for several
   * tiles). Default: see the class comment. Any finite value (coordinates far from it
   * lose float precision); a value that is not finite is refused (PCL_ERROR, the origin
   * is kept). */
  void
  setOrigin (const Eigen::Vector3d& origin);

  /** \brief The number of points of the file. */
  std::uint64_t
  getPointCount () const
  {
    return info_.header.point_count;
  }

  /** \brief The number of points returned by read() so far. */
  std::uint64_t
  getPointsRead () const
  {
    return points_read_;
  }

  /** \brief Read up to \a max_points further points into \a chunk (replacing its
   * content, reusing its memory; fields as in the class comment; at the end, no point
   * but the fields). \return the number read, 0 at the end \throw ReadError naming
   * the file when the point data is truncated or corrupt (\a chunk is then left empty
   * and the reader should not be read further) or no file is open */
  std::size_t
  read (std::size_t max_points, pcl::PCLPointCloud2& chunk);

private:
  /** Refills the block of raw records; false at the end. */
  bool
  fillBlock ();

  std::string path_;
  LasFileInfo info_;
  std::unique_ptr<LasRecordSource> source_;
  struct Decoding;
  std::unique_ptr<Decoding> decoding_;
  std::vector<std::uint8_t> block_;
  std::size_t block_points_ = 0, block_next_ = 0;
  std::uint64_t points_read_ = 0, points_fetched_ = 0;
  int colour_shift_ = 8;
  bool colour_checked_ = false;
};

/** \brief Read a whole LAS file (see LasReader for the fields).
 *
 * \param[in] path the file \param[out] cloud its points, coordinates relative to
 * info.origin \param[out] info header, VLRs, EVLRs, extra bytes and origin, to write a
 * file like it with saveLas. Both are untouched when an exception is thrown. \throw
 * ReadError naming the file (see LasReader::open and read)
 */
void
loadLas (const std::string& path, pcl::PCLPointCloud2& cloud, LasFileInfo& info);
} // namespace io
} // namespace pcl_ext
