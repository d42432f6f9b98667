/*
 * pcl_ext: an app's input cloud, loaded with a timing line.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Load an app's input: the file as it is in \a input (kept so that the output
 * can carry every input field) and its x, y, z in \a xyz, with a "Loading <path>"
 * timing line. Errors as pcl_ext::io::loadCloud. */
bool
loadInput (const std::string& path,
           pcl::PCLPointCloud2& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz);
} // namespace apps
} // namespace pcl_ext
