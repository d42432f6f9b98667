/*
 * pcl_ext: the index check every class runs before it reads the points its indices
 * name, and the grouping of a classifier's labels into one index list per class.
 */
#pragma once

#include <pcl/PCLHeader.h>
#include <pcl/PointIndices.h>
#include <pcl/console/print.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <cstddef>
#include <vector>

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

/** \brief True when \a values holds one entry per point of a cloud of \a size points.
 * Otherwise prints a PCL_ERROR with \a caller naming \a what is missing and the setter
 * that gives it (e.g. "segment label", "setSegmentLabels"), and returns false. */
template <typename Cloud>
inline bool
onePerPoint (const Cloud* values,
             std::size_t size,
             const char* caller,
             const char* what,
             const char* setter)
{
  if (values && values->size() == size)
    return true;
  PCL_ERROR ("%s Give one %s per point (%s): %zu for %zu points.\n",
             caller,
             what,
             setter,
             values ? static_cast<std::size_t> (values->size()) : std::size_t (0),
             size);
  return false;
}

/** \brief The points of \a labels grouped by class, as a classifier's extract() gives
 * them: \a classes lists, each with \a header. Row r of \a labels is the point
 * (*\a indices)[r], or r when \a indices is null; \a class_of maps a label to its class
 * (a value of \a classes or more leaves the point out). */
template <typename ClassOf>
void
groupByClass (const pcl::PointCloud<pcl::Label>& labels,
              const pcl::Indices* indices,
              std::size_t classes,
              const ClassOf& class_of,
              const pcl::PCLHeader& header,
              std::vector<pcl::PointIndices>& grouped)
{
  grouped.assign (classes, pcl::PointIndices());
  for (auto& c : grouped)
    c.header = header;
  for (std::size_t r = 0; r < labels.size(); ++r) {
    const std::size_t c = class_of (labels[r].label);
    if (c < classes)
      grouped[c].indices.push_back (indices ? (*indices)[r]
                                            : static_cast<pcl::index_t> (r));
  }
}
} // namespace pcl_ext
