/*
 * pcl_ext: one loader for every point file format the tools read.
 */
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/e57_reader.h>
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/io/ptx_reader.h>

#include "cloud_repack.h"
#include "pcd_header.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace pcl_ext {
namespace io {
namespace {
/** Reads a PCD or PLY file through PCL (its own messages silenced: the ReadError
 * thrown names the file). */
void
loadPclFile (const std::string& path, PointFileFormat format, pcl::PCLPointCloud2& raw)
{
  const char* name = formatName (format);
  if (format == PointFileFormat::PCD && !detail::hasPcdHeader (path))
    throw ReadError (path, 0, "not a valid PCD file (no FIELDS before DATA)");
  const auto level = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  int result = -1;
  try {
    result = format == PointFileFormat::PCD ? pcl::io::loadPCDFile (path, raw)
                                            : pcl::io::loadPLYFile (path, raw);
  }
  catch (const std::exception&) {
    result = -1;
  }
  pcl::console::setVerbosityLevel (level);
  if (result < 0)
    throw ReadError (path, 0, std::string ("not a valid ") + name + " file");
}

/** The rule of computeLocalOrigin for coordinates that may hold NaN. */
Eigen::Vector3d
localOrigin (const std::vector<Eigen::Vector3d>& xyz, Eigen::Vector3d& max_abs)
{
  Eigen::Vector3d min = Eigen::Vector3d::Constant (INFINITY);
  max_abs.setZero();
  for (const auto& p : xyz)
    if (p.allFinite()) {
      min = min.cwiseMin (p);
      max_abs = max_abs.cwiseMax (p.cwiseAbs());
    }
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis)
    if (max_abs[axis] > kFloatSafeCoordinate)
      origin[axis] = std::floor (min[axis] / 100.0) * 100.0;
  return origin;
}

/** A PCD / PLY file as a PointFile: x y z FLOAT32 local first. */
void
loadPcdOrPly (const std::string& path, PointFileFormat format, PointFile& file)
{
  pcl::PCLPointCloud2 raw;
  loadPclFile (path, format, raw);
  int index[3];
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis)
    if ((index[axis] = pcl::getFieldIndex (raw, names[axis])) < 0)
      throw ReadError (path,
                       0,
                       std::string ("has no '") + names[axis] + "' field (" +
                           formatName (format) + " files need x, y and z)");
  if (std::size_t (raw.width) * raw.height == 0)
    throw ReadError (path, 0, "has no points");
  std::vector<Eigen::Vector3d> xyz;
  if (!detail::readCoordinates (raw, xyz))
    throw ReadError (path, 0, "its data is shorter than its header declares");
  bool all_float = true, as_pcl = true;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& f = raw.fields[index[axis]];
    all_float = all_float && f.datatype == pcl::PCLPointField::FLOAT32;
    as_pcl = as_pcl && f.offset == 4u * axis;
    file.double_coordinates =
        file.double_coordinates || f.datatype == pcl::PCLPointField::FLOAT64;
  }
  Eigen::Vector3d max_abs;
  file.origin = localOrigin (xyz, max_abs);
  if (all_float && max_abs.maxCoeff() > kFloatSafeCoordinate)
    PCL_WARN ("[pcl_ext::io::loadPointFile] %s stores float coordinates up to %.0f m, "
              "where a float's step is %.0f mm: the file has already lost that "
              "precision (store double x y z, or LAS).\n",
              path.c_str(),
              max_abs.maxCoeff(),
              1000.0 * std::ldexp (1.0, std::ilogb (max_abs.maxCoeff()) - 23));
  if (all_float && as_pcl && file.origin.isZero())
    file.cloud = std::move (raw); // as PCL wrote it: nothing to convert
  else
    detail::rebuildCoordinates (
        raw, xyz, -file.origin, pcl::PCLPointField::FLOAT32, {}, file.cloud);
}

/** A PointTable reader's result as a PointFile. */
void
fromTable (const std::string& path, PointTable& table, PointFile& file)
{
  if (table.empty())
    throw ReadError (path, 0, "has no points");
  file.origin = computeLocalOrigin (table);
  toPCLPointCloud2 (table, file.origin, file.cloud);
  file.stations = std::move (table.stations);
  file.coordinate_metadata = std::move (table.coordinate_metadata);
}
} // namespace

void
loadPointFile (const std::string& path,
               PointFile& file,
               const PointFileOptions& options)
{
  struct stat st;
  if (::stat (path.c_str(), &st) != 0)
    throw ReadError (path, 0, "no such file");
  if (!S_ISREG (st.st_mode))
    throw ReadError (path,
                     0,
                     S_ISDIR (st.st_mode) ? "is a folder, not a file"
                                          : "not a regular file");
  if (!std::ifstream (path).good())
    throw ReadError (path, 0, "cannot be opened for reading");
  if (st.st_size == 0)
    throw ReadError (path, 0, "empty file, no points");
  const PointFileFormat format = detectPointFileFormat (path);
  const std::string extension = fileExtension (path);
  const bool binary_extension = extension == "las" || extension == "laz" ||
                                extension == "e57" || extension == "pcd" ||
                                extension == "ply";
  if (format == PointFileFormat::Unknown ||
      (binary_extension &&
       (format == PointFileFormat::ASCII || format == PointFileFormat::PTS ||
        format == PointFileFormat::PTX)))
    throw ReadError (path,
                     0,
                     "not a point file pcl_ext reads (none of the LAS, LAZ, E57, PCD, "
                     "PLY signatures" +
                         std::string (binary_extension ? ", whatever its extension "
                                                         "says)"
                                                       : ")"));
  PointFile result;
  result.format = format;
  switch (format) {
  case PointFileFormat::LAS:
  case PointFileFormat::LAZ: {
    LasFileInfo info;
    loadLas (path, result.cloud, info);
    if (std::size_t (result.cloud.width) * result.cloud.height == 0)
      throw ReadError (path, 0, "has no points");
    result.origin = info.origin;
    result.las = std::move (info);
    break;
  }
  case PointFileFormat::E57: {
    PointTable table;
    loadE57 (path, table);
    fromTable (path, table, result);
    break;
  }
  case PointFileFormat::PTX:
  case PointFileFormat::PTS:
  case PointFileFormat::ASCII: {
    PointTable table;
    if (format == PointFileFormat::PTX)
      loadPTX (path, table);
    else if (format == PointFileFormat::PTS)
      loadPTS (path, table);
    else
      loadAsciiPoints (path, table, options.ascii_columns);
    fromTable (path, table, result);
    break;
  }
  default:
    loadPcdOrPly (path, format, result);
    break;
  }
  file = std::move (result);
}
} // namespace io
} // namespace pcl_ext
