/*
 * pcl_ext: loading and saving clouds in apps, with clear errors and atomic output.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_ext
{
namespace tools
{
/** \brief Load a PCD or PLY file (by extension) as a PCLPointCloud2.
  * Prints an error naming the file and returns false when it is missing, not a regular file
  * (a folder), unreadable, malformed, has no x, y, z fields or no points. */
bool
loadCloud (const std::string& path, pcl::PCLPointCloud2& cloud);

/** \brief Load a PCD or PLY file into a typed cloud (fields not in the file stay default). */
template <typename PointT> bool
loadCloud (const std::string& path, pcl::PointCloud<PointT>& cloud);

/** \brief Load an app's input: the file as it is in \a input (kept so that the output can carry
  * every input field) and its x, y, z in \a xyz, with a "Loading <path>" timing line. Errors as
  * loadCloud. */
bool
loadInput (const std::string& path, pcl::PCLPointCloud2& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz);

/** \brief Save a PCD (binary-compressed unless \a ascii) or PLY file atomically. */
bool
saveCloud (const std::string& path, const pcl::PCLPointCloud2& cloud, bool ascii = false);

/** \brief Save a typed cloud as PCD or PLY atomically. */
template <typename PointT> bool
saveCloud (const std::string& path, const pcl::PointCloud<PointT>& cloud, bool ascii = false);

/** \brief Index of field \a name in \a cloud, or -1. */
int
findField (const pcl::PCLPointCloud2& cloud, const std::string& name);
}  // namespace tools
}  // namespace pcl_ext

#include <pcl_ext/tools/impl/cloud_io.hpp>
