/*
 * pcl_ext: one loader and one writer for every point file format the tools handle.
 */
#pragma once

#include <pcl_ext/io/las_header.h>
#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/read_error.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief The point file formats loadPointFile reads. */
enum class PointFileFormat {
  Unknown,
  PCD,   ///< PCL's point cloud data
  PLY,   ///< Stanford polygon file (vertices)
  LAS,   ///< ASPRS LAS 1.0-1.4, uncompressed
  LAZ,   ///< LAS with LASzip-compressed points (COPC included)
  E57,   ///< ASTM E2807
  PTX,   ///< Leica PTX (gridded scans with poses)
  PTS,   ///< Leica PTS
  ASCII, ///< one point a line, whitespace or comma separated
};

/** \brief Upper-case name of \a format ("LAS", "PCD", ...; "unknown"). */
const char*
formatName (PointFileFormat format);

/** \brief Tell the format of \a path from its content, falling back on its extension.
 *
 * Magic bytes win over the extension: "LASF" (LAS, or LAZ when the point format's
 * compression bit 7 or 6 is set or the extension is .laz), "ASTM-E57", "ply" followed
 * by an end of line, a PCD header (a first keyword VERSION or FIELDS after '#'
 * comments). Text files are PTX when their first two non-blank lines each hold a
 * single integer (columns, rows), PTS when only the first does (the point count) or
 * the extension is .pts, ASCII otherwise. \return Unknown for a file that is binary
 * and none of the above, or that cannot be opened
 */
PointFileFormat
detectPointFileFormat (const std::string& path);

/** \brief Options of loadPointFile. */
struct PointFileOptions {
  /** ASCII column spec (see parseColumnSpec); empty (default) reads the header line or
   * guesses from the values (see loadAsciiPoints). Ignored for other formats. */
  std::string ascii_columns;
};

/** \brief A point file as loadPointFile read it: what the methods work on and what
 * savePointFile needs to write the result back in the file's frame.
 *
 * The file coordinate of a point is \a origin + (x, y, z): the coordinates are local
 * float, the origin double (see kFloatSafeCoordinate: 0 per axis for data within
 * +-8192 m, else a round value near the data).
 */
struct PointFile {
  /** Fields x y z (FLOAT32, first, relative to \a origin) followed by every other
   * field of the file (LAS: the fields of LasReader; E57 / PTX / PTS / ASCII: those of
   * toPCLPointCloud2; PCD / PLY: the file's own fields, unchanged). */
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< file coordinate = origin + xyz
  PointFileFormat format = PointFileFormat::Unknown; ///< the format read
  std::optional<LasFileInfo> las;    ///< header, VLRs, extra bytes of a LAS / LAZ input
  std::vector<ScanStation> stations; ///< the scans of an E57 / PTX input
  /** The coordinate reference system an E57 input declares (its coordinateMetadata,
   * see textCoordinateSystem); empty when none, and for other formats (LAS: \a las). */
  std::string coordinate_metadata;
  /** The file stored x y z as FLOAT64 (a PCD or PLY written by PDAL, or by
   * savePointFile): PCD / PLY output then stores them as FLOAT64 too. */
  bool double_coordinates = false;
};

/** \brief Read any point file pcl_ext knows into \a file.
 *
 * The format comes from detectPointFileFormat (content first). LAS / LAZ through
 * loadLas (origin: LasReader's), E57 through loadE57, PTX / PTS through loadPTX /
 * loadPTS, ASCII through loadAsciiPoints (origin: computeLocalOrigin), PCD / PLY
 * through PCL's readers. PCD / PLY coordinates of any numeric type (PDAL writes
 * `property double x`) are converted to the local origin of computeLocalOrigin's rule
 * and stored as FLOAT32 x y z at the start of the point; the other fields are kept as
 * they are. A FLOAT32 PCD / PLY with coordinates beyond kFloatSafeCoordinate (where a
 * float's step exceeds 1 mm: the file already lost that precision) gets a PCL_WARN;
 * its points are shifted to the local origin too (exactly: the origin is a multiple of
 * their step). NaN coordinates stay NaN.
 *
 * \param[in] path the file \param[out] file the points and what is needed to write
 * them back; untouched when an exception is thrown \param[in] options see
 * PointFileOptions \throw ReadError naming the file when it is missing, a folder, of
 * no known format, malformed (see each reader), when a PCD / PLY lacks x, y or z, or
 * when it holds no point
 */
void
loadPointFile (const std::string& path,
               PointFile& file,
               const PointFileOptions& options = {});

/** \brief Whether savePointFile can write \a path's format (by extension: .las, .pcd,
 * .ply); does not look at the folder (see checkWritable). \param[out] reason when not
 * null and the answer is false: why, naming the path (.laz: writing LAZ is not
 * supported, write .las; .e57, .ptx, .pts and others: not an output format). Does not
 * print. */
bool
canWritePointFile (const std::string& path, std::string* reason = nullptr);

/** \brief Write \a cloud (coordinates relative to \a origin, as PointFile::cloud) by
 * the extension of \a path, atomically.
 *
 * - .las: saveLas (path, cloud, origin, like->las): with a LAS / LAZ input, its
 *   version, point format, scale, offset and VLRs (CRS); otherwise LAS 1.4, scale 1
 *   mm, offset = \a origin.
 * - .pcd (binary compressed) / .ply (binary): every field; x y z FLOAT32 as they are
 *   when \a origin is 0 and the input did not store doubles, else FLOAT64 holding
 *   origin + x (the file's coordinates, to the double's precision). The LAS integers
 *   `las_x las_y las_z` are dropped (they only serve LAS output).
 *
 * \param[in] like the input the cloud came from (may be null)
 * \param[in] ascii PCD / PLY output as text rather than binary (ignored for .las)
 * \return false (PCL_ERROR names the reason; nothing written) when the format cannot
 * be written (see canWritePointFile), the cloud has no x y z, or writing fails
 */
bool
savePointFile (const std::string& path,
               const pcl::PCLPointCloud2& cloud,
               const Eigen::Vector3d& origin,
               const PointFile* like = nullptr,
               bool ascii = false);

/** \brief \a cloud with x y z as FLOAT64 holding origin + x y z (the other fields as
 * they are, `las_x las_y las_z` dropped): what savePointFile writes to PCD / PLY. */
void
toDoubleCoordinates (const pcl::PCLPointCloud2& cloud,
                     const Eigen::Vector3d& origin,
                     pcl::PCLPointCloud2& result);
} // namespace io
} // namespace pcl_ext
