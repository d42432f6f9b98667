/*
 * pcl_ext: an app's input cloud, loaded with a timing line.
 */
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/io/cloud_io.h>

#include <pcl/conversions.h>

namespace pcl_ext {
namespace apps {
bool
loadInput (const std::string& path,
           pcl::PCLPointCloud2& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz)
{
  StageTimer timer ("Loading " + path);
  if (!io::loadCloud (path, input))
    return false;
  pcl::fromPCLPointCloud2 (input, xyz);
  timer.done (xyz.size());
  return true;
}
} // namespace apps
} // namespace pcl_ext
