/*
 * pcl_ext: one writer for the point file formats the tools write.
 */
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_writer.h>
#include <pcl_ext/io/point_file.h>

#include "cloud_repack.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>

namespace pcl_ext {
namespace io {
namespace {
/** The LAS integers the reader adds: meaningful to a LAS output only. */
const std::vector<std::string> kLasIntegers = {"las_x", "las_y", "las_z"};
} // namespace

bool
canWritePointFile (const std::string& path, std::string* reason)
{
  const std::string extension = fileExtension (path);
  if (extension == "las" || extension == "pcd" || extension == "ply")
    return true;
  if (reason) {
    if (extension == "laz")
      *reason = path + ": writing LAZ is not supported; write .las (uncompressed LAS, "
                       "which LAStools or PDAL compress if needed)";
    else
      *reason = path + ": cannot write " +
                (extension.empty() ? std::string ("a file without extension")
                                   : "'." + extension + "' files") +
                "; the output formats are .las, .pcd and .ply";
  }
  return false;
}

void
toDoubleCoordinates (const pcl::PCLPointCloud2& cloud,
                     const Eigen::Vector3d& origin,
                     pcl::PCLPointCloud2& result)
{
  std::vector<Eigen::Vector3d> xyz;
  if (!detail::readCoordinates (cloud, xyz)) {
    result = pcl::PCLPointCloud2();
    return;
  }
  detail::rebuildCoordinates (
      cloud, xyz, origin, pcl::PCLPointField::FLOAT64, kLasIntegers, result);
}

bool
savePointFile (const std::string& path,
               const pcl::PCLPointCloud2& cloud,
               const Eigen::Vector3d& origin,
               const PointFile* like,
               bool ascii)
{
  std::string reason;
  if (!canWritePointFile (path, &reason)) {
    PCL_ERROR ("[pcl_ext::io::savePointFile] %s.\n", reason.c_str());
    return false;
  }
  std::vector<Eigen::Vector3d> xyz;
  if (!detail::readCoordinates (cloud, xyz)) {
    PCL_ERROR ("[pcl_ext::io::savePointFile] cannot write %s: the cloud has no x, y, z "
               "fields or its data is shorter than its size.\n",
               path.c_str());
    return false;
  }
  if (fileExtension (path) == "las")
    return saveLas (path, cloud, origin, like && like->las ? &*like->las : nullptr);
  const bool has_las_integers = pcl::getFieldIndex (cloud, "las_x") >= 0 ||
                                pcl::getFieldIndex (cloud, "las_y") >= 0 ||
                                pcl::getFieldIndex (cloud, "las_z") >= 0;
  const bool doubles = !origin.isZero() || (like && like->double_coordinates);
  if (!doubles && !has_las_integers)
    return saveCloud (path, cloud, ascii);
  pcl::PCLPointCloud2 out;
  detail::rebuildCoordinates (cloud,
                              xyz,
                              origin,
                              doubles ? pcl::PCLPointField::FLOAT64
                                      : pcl::PCLPointField::FLOAT32,
                              kLasIntegers,
                              out);
  return saveCloud (path, out, ascii);
}
} // namespace io
} // namespace pcl_ext
