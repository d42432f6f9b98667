/*
 * pcl_ext: a PointTable filled scan by scan (private header).
 */
#pragma once

#include <pcl_ext/io/point_table.h>

#include <limits>

namespace pcl_ext {
namespace io {
namespace detail {
/** Fills a PointTable where attributes may be present in some scans only: an attribute
 * is created at its first value and padded for the points before it and for later
 * points without it (NaN intensity, black colour, row and column -1). */
class TableBuilder {
public:
  PointTable table;

  /** Adds a point; null attributes are absent for this point. */
  void
  add (const Eigen::Vector3d& p,
       const float* intensity,
       const std::array<std::uint8_t, 3>* colour,
       const std::int32_t* row = nullptr,
       const std::int32_t* column = nullptr)
  {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::array<std::uint8_t, 3> black{0, 0, 0};
    push (table.intensity, has_intensity_, intensity, nan);
    push (table.rgb, has_rgb_, colour, black);
    push (table.row, has_row_, row, -1);
    push (table.column, has_column_, column, -1);
    table.xyz.push_back (p);
  }

private:
  /** Appends \a value (or \a fill) to an attribute, creating it padded with \a fill
   * at its first value. */
  template <typename T>
  void
  push (std::vector<T>& attribute, bool& present, const T* value, const T& fill)
  {
    if (value && !present) {
      attribute.assign (table.size(), fill);
      present = true;
    }
    if (present)
      attribute.push_back (value ? *value : fill);
  }

  bool has_intensity_ = false, has_rgb_ = false, has_row_ = false, has_column_ = false;
};
} // namespace detail
} // namespace io
} // namespace pcl_ext
