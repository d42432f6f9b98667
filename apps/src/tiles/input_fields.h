/*
 * pcl_ext_tiles: the fields of several inputs in one output.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The fields of every input in one layout (io::unionOfFields over the fields
 * their reader gives): the output of a project whose scans carry different fields
 * keeps every field, 0 in the points of an input without it. \throw io::ReadError
 * naming an input that cannot be read \return false (message printed) when two inputs
 * give a field two types */
bool
unionOfInputFields (const std::vector<std::string>& inputs,
                    pcl::PCLPointCloud2& layout);

/** \brief Whether \a cloud's fields are those of \a layout (names, types, offsets). */
bool
hasLayout (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointCloud2& layout);
} // namespace apps
} // namespace pcl_ext
