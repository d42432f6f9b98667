/*
 * pcl_ext: Leica's ASCII scan exchange formats, PTX (gridded scans with their poses)
 * and PTS (plain point lists).
 */
#pragma once

#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/read_error.h>

#include <string>

namespace pcl_ext {
namespace io {
/** \brief Options of loadPTX. */
struct PtxOptions {
  /** Leave every scan's points in its scanner frame instead of applying the header's
   * transform; the stations still carry the pose (ScanStation::points_in_scanner_frame
   * is set). Default false: all scans in the file's (registered) frame. */
  bool keep_scanner_frame = false;
};

/** \brief Read a Leica PTX file: one or more scans, each a header and a grid of points.
 *
 * Layout of one scan (Leica Cyclone's PTX export, as documented by Leica and P.
 * Bourke's format notes): the number of columns; the number of rows; the scanner's
 * registered position (3 values); its registered axes (3 lines of 3 values); the 4x4
 * transform from the scanner frame to the registered frame, written transposed
 * (row-vector convention: the fourth line holds the translation and a 1); then columns
 * x rows point lines `x y z intensity [r g b]`, column after column (point k has column
 * k / rows and row k % rows). Scans follow each other to the end of the file.
 *
 * Points `0 0 0 ...` are no-returns of the grid and are dropped; the others keep their
 * \a row and \a column. Each point is mapped through its scan's transform (unless
 * \a options.keep_scanner_frame); intensity is kept as written (Leica writes 0..1),
 * colour channels must be integers in [0, 255]. One ScanStation per scan: position =
 * the transform's translation, orientation = its rotation (axes normalised), rows and
 * columns of the grid; \a scan holds each point's station. A scan without colour in a
 * file where another has colour gets black points; one without intensity gets NaN.
 *
 * \param[in] path the file \param[out] table the points; untouched when an exception
 * is thrown \param[in] options see PtxOptions
 * \throw ReadError naming the file and line when it cannot be opened, has no scan, a
 * header value is missing, not a number or not finite, a grid size is negative or
 * larger than 2^31 - 1 points, a point line has a wrong number of values, or the file
 * ends before a scan's columns x rows points
 */
void
loadPTX (const std::string& path, PointTable& table, const PtxOptions& options = {});

/** \brief Read a Leica PTS file: an optional first line with the point count, then one
 * point a line, `x y z`, `x y z intensity`, `x y z r g b` or `x y z intensity r g b`.
 *
 * A first line holding a single non-negative integer is the count (Leica's layout);
 * otherwise the file has no count and every line is a point. With a count, the file
 * must hold exactly that many points (several count-and-points blocks may follow each
 * other, as merged exports have). Every point line must have as many values as the
 * first. Intensity is kept as written (Leica writes -2048..2047); colour channels must
 * be in [0, 255]. No station table (PTS has no scanner pose).
 *
 * \throw ReadError naming the file and line when it cannot be opened, has no point, a
 * count does not match the points that follow it, a line has a wrong number of values
 * or a value that is not a number
 */
void
loadPTS (const std::string& path, PointTable& table);
} // namespace io
} // namespace pcl_ext
