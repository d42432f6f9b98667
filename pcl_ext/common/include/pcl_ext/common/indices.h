/*
 * pcl_ext: the index check every class runs before it reads the points its indices
 * name.
 */
#pragma once

#include <pcl/console/print.h>
#include <pcl/types.h>

#include <cstddef>

namespace pcl_ext {
/** \brief True when every index names a point of a cloud of \a size points. Otherwise
 * prints a PCL_ERROR with \a caller (e.g. "[pcl_ext::Neighbourhoods::compute]") and the
 * first index out of range, and returns false. PCL's own initCompute() does not look at
 * the values, and an index past the end is a read (or write) outside the cloud. */
inline bool
indicesInRange (const pcl::Indices& indices, std::size_t size, const char* caller)
{
  for (const auto idx : indices)
    if (idx < 0 || static_cast<std::size_t> (idx) >= size) {
      PCL_ERROR ("%s Index %d is out of range for a cloud of %zu points.\n",
                 caller,
                 static_cast<int> (idx),
                 size);
      return false;
    }
  return true;
}
} // namespace pcl_ext
