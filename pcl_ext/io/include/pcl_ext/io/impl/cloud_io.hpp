/*
 * pcl_ext: typed cloud loading and saving.
 */
#pragma once

#include <pcl_ext/io/cloud_io.h>

#include <pcl/conversions.h>

template <typename PointT>
bool
pcl_ext::io::loadCloud (const std::string& path, pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  if (!loadCloud (path, blob))
    return false;
  pcl::fromPCLPointCloud2 (blob, cloud);
  return true;
}

template <typename PointT>
bool
pcl_ext::io::saveCloud (const std::string& path,
                        const pcl::PointCloud<PointT>& cloud,
                        bool ascii)
{
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (cloud, blob);
  return saveCloud (path, blob, ascii);
}
