/*
 * pcl_ext: ASTM E2807 (E57) files, the exchange format of terrestrial laser scans.
 */
#pragma once

#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/read_error.h>

#include <string>

namespace pcl_ext {
namespace io {
/** \brief Options of loadE57. */
struct E57Options {
  /** Leave every scan's points in its own frame instead of applying its pose; the
   * stations still carry the pose (ScanStation::points_in_scanner_frame is set).
   * Default false: all scans in the file's frame. */
  bool keep_scanner_frame = false;
  /** Map intensity to [0, 1] through the scan's intensityLimits (section 8.4.5), or,
   * without them, through the prototype's declared minimum and maximum; when neither
   * gives a range (or it is empty) the value is kept as written. false keeps every
   * value as written. Default true: scans with different limits become comparable. */
  bool normalise_intensity = true;
};

/** \brief Read every data3D scan of an E57 file (ASTM E2807) into one table.
 *
 * What is read (section numbers of ASTM E2807-11):
 * - the physical layer (9.3): 1024-byte pages, each page read is checked against its
 *   CRC-32C; the file header (9.4);
 * - the XML section (8) through libexpat: for each data3D child its name, guid, pose
 *   (8.4.3), intensityLimits, colorLimits and the points CompressedVector;
 * - the compressed-vector binary section (9.7 - 9.9): data packets and their bit-packed
 *   bytestreams of Integer, ScaledInteger and Float (single or double) fields.
 *
 * Per point: cartesianX/Y/Z, or sphericalRange/Azimuth/Elevation converted with
 * x = r cos(e) cos(a), y = r cos(e) sin(a), z = r sin(e) (cartesian wins when both are
 * present); the scan's pose applied (p = R p + t) unless \a options.keep_scanner_frame.
 * Points whose cartesianInvalidState (or, for spherical coordinates,
 * sphericalInvalidState) is not 0 are dropped: 1 means a direction without a range, 2
 * no measurement. Points with a non-finite coordinate are dropped too. intensity: see
 * E57Options::normalise_intensity; NaN where isIntensityInvalid is 1. Colour:
 * colorRed/Green/Blue mapped from colorLimits (or the prototype's bounds, or 0..255)
 * to 0..255, black where isColorInvalid is 1. rowIndex / columnIndex into \a row and
 * \a column. Attributes missing from some scans are padded (NaN intensity, black,
 * row / column -1). One ScanStation per data3D scan (name, guid, pose:
 * position = translation, orientation = rotation); \a scan gives each point's station.
 *
 * A file without data3D scans, or with scans of zero records, is valid (the standard
 * allows both): \a table is then empty (with its stations).
 *
 * \param[in] path the file \param[out] table the points; untouched when an exception
 * is thrown \param[in] options see E57Options
 * \throw ReadError naming the file when it cannot be opened; the signature is not
 * "ASTM-E57"; the major version is not 1; the page size is not 1024; the size is not
 * the declared physical length (truncated); a page's checksum is wrong; the XML
 * section lies outside the file or is malformed (see parseE57Xml); a compressed
 * vector's section header is invalid or outside the file; a packet points outside its
 * section; a recordCount exceeds the records its section holds; a packet type is
 * unknown; an integer lies outside its declared range; a row or column index does not
 * fit 32 bits; the file has more than 65536 scans
 */
void
loadE57 (const std::string& path, PointTable& table, const E57Options& options = {});
} // namespace io
} // namespace pcl_ext
