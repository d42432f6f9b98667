/*
 * pcl_ext: loading and saving PCD and PLY clouds.
 */
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/io/file_output.h>

#include "pcd_header.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <sys/stat.h>

#include <fstream>
#include <sstream>

namespace pcl_ext {
namespace io {
bool
detail::hasPcdHeader (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::string line;
  bool fields = false;
  for (int i = 0; i < 64 && std::getline (in, line); ++i) {
    std::istringstream words (line);
    std::string key, first;
    words >> key;
    if (key == "FIELDS")
      fields = static_cast<bool> (words >> first);
    else if (key == "DATA")
      return fields;
  }
  return false;
}

bool
loadCloud (const std::string& path, pcl::PCLPointCloud2& cloud)
{
  cloud = pcl::PCLPointCloud2();
  // Only regular files: PCL's PCD reader loops forever on a folder (reads fail without
  // EOF), and a FIFO would block.
  struct stat st;
  if (::stat (path.c_str(), &st) != 0) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] cannot open %s: no such file.\n",
               path.c_str());
    return false;
  }
  if (!S_ISREG (st.st_mode)) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] cannot read %s: %s.\n",
               path.c_str(),
               S_ISDIR (st.st_mode) ? "it is a folder" : "not a regular file");
    return false;
  }
  if (!std::ifstream (path).good()) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] cannot open %s for reading.\n", path.c_str());
    return false;
  }
  const std::string ext = fileExtension (path);
  // PCL prints its own parse errors; silence them and report once, naming the file.
  const auto level = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  int result = -1;
  try {
    if (ext == "pcd")
      result = detail::hasPcdHeader (path) ? pcl::io::loadPCDFile (path, cloud) : -1;
    else if (ext == "ply")
      result = pcl::io::loadPLYFile (path, cloud);
    else {
      pcl::console::setVerbosityLevel (level);
      PCL_ERROR (
          "[pcl_ext::io::loadCloud] %s: unsupported extension '%s' (expected .pcd or "
          ".ply).\n",
          path.c_str(),
          ext.c_str());
      return false;
    }
  }
  catch (const std::exception&) {
    result = -1; // reported below, naming the file
  }
  pcl::console::setVerbosityLevel (level);
  if (result < 0) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] %s is not a valid %s file.\n",
               path.c_str(),
               ext.c_str());
    cloud = pcl::PCLPointCloud2();
    return false;
  }
  if (pcl::getFieldIndex (cloud, "x") < 0 || pcl::getFieldIndex (cloud, "y") < 0 ||
      pcl::getFieldIndex (cloud, "z") < 0) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] %s has no x, y, z fields.\n", path.c_str());
    cloud = pcl::PCLPointCloud2();
    return false;
  }
  if (static_cast<std::size_t> (cloud.width) * cloud.height == 0) {
    PCL_ERROR ("[pcl_ext::io::loadCloud] %s has no points.\n", path.c_str());
    cloud = pcl::PCLPointCloud2();
    return false;
  }
  return true;
}

bool
saveCloud (const std::string& path, const pcl::PCLPointCloud2& cloud, bool ascii)
{
  const std::string ext = fileExtension (path);
  if (ext != "pcd" && ext != "ply") {
    PCL_ERROR ("[pcl_ext::io::saveCloud] cannot write %s: unsupported extension '%s' "
               "(expected "
               ".pcd or .ply).\n",
               path.c_str(),
               ext.c_str());
    return false;
  }
  return writeFileAtomically (path, [&] (const std::string& temporary) {
    if (ext == "ply")
      return pcl::io::savePLYFile (temporary,
                                   cloud,
                                   Eigen::Vector4f::Zero(),
                                   Eigen::Quaternionf::Identity(),
                                   !ascii) == 0;
    pcl::PCDWriter writer;
    if (ascii)
      return writer.writeASCII (temporary, cloud) == 0;
    return writer.writeBinaryCompressed (temporary, cloud) == 0;
  });
}
} // namespace io
} // namespace pcl_ext
