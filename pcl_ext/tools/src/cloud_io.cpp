/*
 * pcl_ext: loading and saving clouds in apps.
 */
#include <pcl_ext/tools/cloud_io.h>
#include <pcl_ext/tools/command_line.h>
#include <pcl_ext/tools/file_output.h>

#include <pcl/conversions.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <sys/stat.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace pcl_ext
{
namespace tools
{
int
findField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (std::size_t i = 0; i < cloud.fields.size (); ++i)
    if (cloud.fields[i].name == name)
      return static_cast<int> (i);
  return -1;
}

namespace
{
/** Whether \a path starts like a PCD file: a FIELDS line naming at least one field before a
  * DATA line. PCL 1.13's reader crashes on files without fields (fixed upstream after 1.13),
  * so anything else is refused before it gets there. */
bool
hasPcdHeader (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::string line;
  bool fields = false;
  for (int i = 0; i < 64 && std::getline (in, line); ++i)
  {
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
}  // namespace

bool
loadCloud (const std::string& path, pcl::PCLPointCloud2& cloud)
{
  cloud = pcl::PCLPointCloud2 ();
  // Only regular files: PCL's PCD reader loops forever on a folder (reads fail without EOF),
  // and a FIFO would block.
  struct stat st;
  if (::stat (path.c_str (), &st) != 0)
  {
    std::cerr << "Error: cannot open " << path << ": no such file.\n";
    return false;
  }
  if (!S_ISREG (st.st_mode))
  {
    std::cerr << "Error: cannot read " << path << ": "
              << (S_ISDIR (st.st_mode) ? "it is a folder" : "not a regular file") << ".\n";
    return false;
  }
  if (!std::ifstream (path).good ())
  {
    std::cerr << "Error: cannot open " << path << " for reading.\n";
    return false;
  }
  const std::string ext = fileExtension (path);
  // PCL prints its own parse errors; silence them and report once, naming the file.
  const auto level = pcl::console::getVerbosityLevel ();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  int result = -1;
  try
  {
    if (ext == "pcd")
      result = hasPcdHeader (path) ? pcl::io::loadPCDFile (path, cloud) : -1;
    else if (ext == "ply")
      result = pcl::io::loadPLYFile (path, cloud);
    else
    {
      pcl::console::setVerbosityLevel (level);
      std::cerr << "Error: " << path << ": unsupported extension '" << ext
                << "' (expected .pcd or .ply).\n";
      return false;
    }
  }
  catch (const std::exception&)
  {
    result = -1;  // reported below, naming the file
  }
  pcl::console::setVerbosityLevel (level);
  if (result < 0)
  {
    std::cerr << "Error: " << path << " is not a valid " << ext << " file.\n";
    cloud = pcl::PCLPointCloud2 ();
    return false;
  }
  if (findField (cloud, "x") < 0 || findField (cloud, "y") < 0 || findField (cloud, "z") < 0)
  {
    std::cerr << "Error: " << path << " has no x, y, z fields.\n";
    cloud = pcl::PCLPointCloud2 ();
    return false;
  }
  if (static_cast<std::size_t> (cloud.width) * cloud.height == 0)
  {
    std::cerr << "Error: " << path << " has no points.\n";
    cloud = pcl::PCLPointCloud2 ();
    return false;
  }
  return true;
}

bool
saveCloud (const std::string& path, const pcl::PCLPointCloud2& cloud, bool ascii)
{
  const std::string ext = fileExtension (path);
  if (ext != "pcd" && ext != "ply")
  {
    std::cerr << "Error: cannot write " << path << ": unsupported extension '" << ext
              << "' (expected .pcd or .ply).\n";
    return false;
  }
  return writeFileAtomically (path, [&] (const std::string& temporary) {
    if (ext == "ply")
      return pcl::io::savePLYFile (temporary, cloud, Eigen::Vector4f::Zero (),
                                   Eigen::Quaternionf::Identity (), !ascii) == 0;
    pcl::PCDWriter writer;
    if (ascii)
      return writer.writeASCII (temporary, cloud) == 0;
    return writer.writeBinaryCompressed (temporary, cloud) == 0;
  });
}
bool
loadInput (const std::string& path, pcl::PCLPointCloud2& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz)
{
  StageTimer timer ("Loading " + path);
  if (!loadCloud (path, input))
    return false;
  pcl::fromPCLPointCloud2 (input, xyz);
  timer.done (xyz.size ());
  return true;
}

}  // namespace tools
}  // namespace pcl_ext
