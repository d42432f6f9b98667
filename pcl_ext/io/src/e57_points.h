/*
 * pcl_ext: E57 records turned into points of a table (private header).
 */
#pragma once

#include <pcl_ext/io/e57_format.h>
#include <pcl_ext/io/e57_reader.h>

#include "table_builder.h"

#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace detail {
/** Converts the decoded records of one scan: coordinates (cartesian, or spherical to
 * cartesian), invalid states, pose, intensity and colour scaling, grid indices. */
class E57PointConverter {
public:
  /** \param[in] where names the scan in errors (with \a path) */
  E57PointConverter (const E57ScanInfo& scan,
                     const E57Options& options,
                     std::uint16_t station,
                     const std::string& path,
                     const std::string& where);

  /** Adds the valid points of \a count records (see E57RecordSink) to \a out. */
  void
  convert (const std::vector<double>& values, std::size_t count, TableBuilder& out);

private:
  /** Index of the prototype field \a name, -1 when absent. */
  int
  find (const char* name) const;

  const E57ScanInfo& scan_;
  std::string path_, where_;
  bool apply_pose_;
  std::uint16_t station_;
  std::size_t width_;
  bool spherical_;
  int coordinate_[3], invalid_state_;
  int intensity_, intensity_invalid_;
  int colour_[3], colour_invalid_;
  int row_, column_;
  double intensity_minimum_ = 0.0, intensity_range_ = 0.0; ///< range 0: kept raw
  double colour_minimum_[3], colour_range_[3];
  Eigen::Matrix3d rotation_;
};
} // namespace detail
} // namespace io
} // namespace pcl_ext
