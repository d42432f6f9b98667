/*
 * pcl_ext: pcl::PCLPointCloud2 written as an uncompressed LAS file (ASPRS LAS 1.4 R15).
 */
#pragma once

#include <pcl_ext/io/las_header.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <string>

namespace pcl_ext {
namespace io {
/** \brief Write \a cloud as an uncompressed LAS file (ASPRS LAS 1.4 R15, sections
 * 2.4-2.7), atomically (writeFileAtomically: the file is written whole or not at all).
 *
 * The file's coordinates are \a origin + x y z (the fields LasReader produces; any
 * numeric type). With \a like (the info of a file read by LasReader or loadLas), the
 * file gets its version, point format, scale, offset, header fields (system
 * identifier, generating software, GUID, dates, global encoding), VLRs and EVLRs (the
 * coordinate system carried over) and the bytes between VLRs and points; the LASzip VLR
 * is dropped (the points are written uncompressed) and waveform data is not written
 * (waveform start 0, global encoding bit 1 cleared). Without \a like: LAS 1.4, point
 * format 8 when the cloud has `nir`, 7 when it has colour (`red green blue` or
 * `rgb`), else 6; scale 0.001 m; offset = \a origin; global encoding bit 4 (WKT) set as
 * the specification asks of formats 6-10.
 *
 * Fields: each standard dimension of the format is taken from the field of the name
 * LasReader gives it (converted, rounded and clamped to the stored type; bit fields
 * masked), or 0 when absent (1 for return_number and number_of_returns); colour from
 * `red green blue`, else from the packed `rgb` (8-bit * 257). Every other field
 * becomes an extra-bytes dimension (LASF_Spec record 4): with \a like, a field of the
 * name and type LasReader gives an extra-bytes dimension of \a like keeps its
 * descriptor (a FLOAT64 field of a scaled one is stored as round ((v - offset) /
 * scale)); any other gets a new descriptor of its type (count 2 or 3 as the deprecated
 * array types, UINT8 x n as n undocumented bytes). The extra-bytes VLR of \a like is
 * kept as it is when the descriptors are unchanged, else replaced in place (or added,
 * or removed when there are none). A UINT8 field `extra_bytes` is written as it is at
 * the end of the record, without a descriptor. `rgb` (when the format has colour or
 * red green blue are present), `las_x las_y las_z` and fields named "_" are not extra
 * bytes.
 *
 * Integers: X = round ((x + origin - offset) / scale); with \a like, the field `las_x`
 * (INT32) is taken instead when converting it as LasReader does (float (las_x * scale +
 * (offset - origin))) gives exactly x: points that were not moved keep the integers
 * of the file read even where a float cannot hold the file's resolution. Likewise y, z.
 *
 * The header's bounding box, point counts (legacy and 64-bit) and counts per return
 * are recomputed (the legacy fields are 0 in LAS 1.4 files of formats 6-10 and above
 * 2^32 - 1 points).
 *
 * \return false (PCL_ERROR names the reason; no file is written) when a coordinate
 * field is missing, a coordinate is not finite or does not fit a 32-bit integer at the
 * scale, a field cannot be an extra-bytes dimension (an unsupported count), the cloud's
 * data is shorter than its size, a file before LAS 1.4 would hold more than 2^32 - 1
 * points, or the file cannot be written
 */
bool
saveLas (const std::string& path,
         const pcl::PCLPointCloud2& cloud,
         const Eigen::Vector3d& origin,
         const LasFileInfo* like = nullptr);

/** \brief Writes an uncompressed LAS file chunk by chunk, with the rules of saveLas,
 * so that a file larger than memory can be written (e.g. the chunks of a LasReader with
 * a result field added).
 *
 * open() takes the layout of the chunks (their fields; the points of \a layout are not
 * written), write() appends the points of a chunk of that layout, close() writes the
 * EVLRs and the header's counts and bounds and renames the temporary file over the
 * path. Nothing is visible at the path before close() succeeds: a writer destroyed
 * without close(), or one whose write() or close() failed, removes its temporary file
 * and leaves the path as it was.
 *
 * \code
 * pcl_ext::io::LasWriter writer;
 * if (!writer.open ("out.las", first_chunk, reader.getOrigin (), &reader.getFileInfo
 * ())) return false; do ok = writer.write (chunk); while (ok && reader.read (1000000,
 * chunk) > 0); ok = ok && writer.close (); \endcode
 */
class LasWriter {
public:
  LasWriter();
  ~LasWriter();
  LasWriter (const LasWriter&) = delete;
  LasWriter&
  operator= (const LasWriter&) = delete;

  /** \brief Start writing \a path (see saveLas for \a origin and \a like). \return
   * false (PCL_ERROR names the reason, nothing is written) when the folder is not
   * writable, the origin is not finite or a field of \a layout cannot be stored */
  bool
  open (const std::string& path,
        const pcl::PCLPointCloud2& layout,
        const Eigen::Vector3d& origin,
        const LasFileInfo* like = nullptr);

  /** \brief Append the points of \a chunk, whose fields must be those of the layout
   * given to open(). \return false (PCL_ERROR names the reason; the file will not be
   * written) when no file is open, the fields differ, the data is shorter than the
   * points, a coordinate cannot be stored or the disk is full */
  bool
  write (const pcl::PCLPointCloud2& chunk);

  /** \brief Finish the file and move it to the path given to open(). \return false
   * (PCL_ERROR names the reason; nothing is left at the path) when a write failed, a
   * file before LAS 1.4 would hold more than 2^32 - 1 points or the file cannot be
   * finished */
  bool
  close ();

  /** \brief The points written so far. */
  std::uint64_t
  getPointsWritten () const;

private:
  struct State;
  std::unique_ptr<State> state_;
};
} // namespace io
} // namespace pcl_ext
