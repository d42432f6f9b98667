/*
 * pcl_ext: loading and saving PCD and PLY clouds, with clear errors and atomic output.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_ext {
namespace io {
/** \brief Load a PCD or PLY file (by extension) as a PCLPointCloud2.
 * Reports an error (PCL_ERROR) naming the file and returns false when it is missing,
 * not a regular file (a folder), unreadable, malformed, has no x, y, z fields or no
 * points. */
bool
loadCloud (const std::string& path, pcl::PCLPointCloud2& cloud);

/** \brief Load a PCD or PLY file into a typed cloud (fields not in the file stay
 * default). */
template <typename PointT>
bool
loadCloud (const std::string& path, pcl::PointCloud<PointT>& cloud);

/** \brief Save a PCD (binary-compressed unless \a ascii) or PLY file atomically. */
bool
saveCloud (const std::string& path,
           const pcl::PCLPointCloud2& cloud,
           bool ascii = false);

/** \brief Save a typed cloud as PCD or PLY atomically. */
template <typename PointT>
bool
saveCloud (const std::string& path,
           const pcl::PointCloud<PointT>& cloud,
           bool ascii = false);
} // namespace io
} // namespace pcl_ext

#include <pcl_ext/io/impl/cloud_io.hpp>
