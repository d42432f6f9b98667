/*
 * pcl_ext: an app's input cloud, loaded with a timing line.
 */
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>

#include <pcl/conversions.h>

#include <iostream>

namespace pcl_ext {
namespace apps {
bool
loadInput (const std::string& path,
           io::PointFile& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz,
           const io::PointFileOptions& options)
{
  StageTimer timer ("Loading " + path);
  try {
    io::loadPointFile (path, input, options);
  }
  catch (const io::ReadError& e) {
    std::cerr << "\nError: " << e.what() << '\n';
    return false;
  }
  pcl::fromPCLPointCloud2 (input.cloud, xyz);
  timer.done (xyz.size());
  if (!input.origin.isZero())
    std::cout << "  " << io::formatName (input.format) << ", local origin "
              << std::fixed << input.origin.x() << ' ' << input.origin.y() << ' '
              << input.origin.z() << std::defaultfloat
              << " (added back to the output's coordinates)\n";
  return true;
}
} // namespace apps
} // namespace pcl_ext
