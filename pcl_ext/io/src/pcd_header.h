/*
 * pcl_ext: the PCD header check both PCD loaders make before handing a file to PCL.
 */
#pragma once

#include <string>

namespace pcl_ext {
namespace io {
namespace detail {
/** \brief Whether \a path starts like a PCD file: a FIELDS line naming at least one
 * field before a DATA line. PCL 1.13's reader crashes on files without fields (fixed
 * upstream after 1.13), so anything else is refused before it gets there. */
bool
hasPcdHeader (const std::string& path);
} // namespace detail
} // namespace io
} // namespace pcl_ext
