/*
 * Reading a command-line tool's result field as the `label` of a typed cloud.
 */
#pragma once

#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>

#include <string>

namespace pcl_ext {
namespace test {
/** Load the PCD \a path with its field \a field read as `label` (an input `label` the
 * tool passed through is renamed out of the way). \return pcl::io::loadPCDFile's code,
 * or -2 when the file has no field \a field */
template <typename PointT>
int
loadResult (const std::string& path,
            const std::string& field,
            pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  if (const int code = pcl::io::loadPCDFile (path, blob); code != 0)
    return code;
  bool found = false;
  for (auto& f : blob.fields)
    if (f.name == "label")
      f.name = "input_label";
  for (auto& f : blob.fields)
    if (f.name == field || (field == "label" && f.name == "input_label")) {
      f.name = "label";
      found = true;
    }
  if (!found)
    return -2;
  pcl::fromPCLPointCloud2 (blob, cloud);
  return 0;
}
} // namespace test
} // namespace pcl_ext
