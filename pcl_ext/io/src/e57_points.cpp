/*
 * pcl_ext: E57 records turned into points: spherical coordinates, invalid states,
 * the scan pose, intensity and colour scaling.
 */
#include "e57_points.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace pcl_ext {
namespace io {
namespace detail {
E57PointConverter::E57PointConverter (const E57ScanInfo& scan,
                                      const E57Options& options,
                                      std::uint16_t station,
                                      const std::string& path,
                                      const std::string& where)
: scan_ (scan)
, path_ (path)
, where_ (where)
, apply_pose_ (!options.keep_scanner_frame)
, station_ (station)
, width_ (scan.prototype.size())
, rotation_ (scan.rotation.toRotationMatrix())
{
  const char* cartesian[] = {"cartesianX", "cartesianY", "cartesianZ"};
  const char* spherical[] = {
      "sphericalRange", "sphericalAzimuth", "sphericalElevation"};
  spherical_ =
      find (cartesian[0]) < 0 || find (cartesian[1]) < 0 || find (cartesian[2]) < 0;
  for (int a = 0; a < 3; ++a)
    coordinate_[a] = find (spherical_ ? spherical[a] : cartesian[a]);
  invalid_state_ =
      find (spherical_ ? "sphericalInvalidState" : "cartesianInvalidState");
  intensity_ = find ("intensity");
  intensity_invalid_ = find ("isIntensityInvalid");
  const char* colours[] = {"colorRed", "colorGreen", "colorBlue"};
  for (int c = 0; c < 3; ++c)
    colour_[c] = find (colours[c]);
  // Colour needs all three channels.
  if (colour_[0] < 0 || colour_[1] < 0 || colour_[2] < 0)
    colour_[0] = colour_[1] = colour_[2] = -1;
  colour_invalid_ = find ("isColorInvalid");
  row_ = find ("rowIndex");
  column_ = find ("columnIndex");

  if (intensity_ >= 0 && options.normalise_intensity) {
    const E57Field& f = scan.prototype[intensity_];
    if (scan.has_intensity_limits && scan.intensity_maximum > scan.intensity_minimum) {
      intensity_minimum_ = scan.intensity_minimum;
      intensity_range_ = scan.intensity_maximum - scan.intensity_minimum;
    }
    else if (f.has_bounds && f.value_maximum > f.value_minimum) {
      intensity_minimum_ = f.value_minimum;
      intensity_range_ = f.value_maximum - f.value_minimum;
    }
    if (!std::isfinite (intensity_range_) || !std::isfinite (intensity_minimum_))
      intensity_range_ = 0.0; // no usable range: kept as written
  }
  for (int c = 0; c < 3; ++c) {
    colour_minimum_[c] = 0.0;
    colour_range_[c] = 255.0;
    if (colour_[c] < 0)
      continue;
    const E57Field& f = scan.prototype[colour_[c]];
    if (scan.has_color_limits && scan.color_maximum[c] > scan.color_minimum[c]) {
      colour_minimum_[c] = scan.color_minimum[c];
      colour_range_[c] = scan.color_maximum[c] - scan.color_minimum[c];
    }
    else if (f.has_bounds && f.value_maximum > f.value_minimum) {
      colour_minimum_[c] = f.value_minimum;
      colour_range_[c] = f.value_maximum - f.value_minimum;
    }
    if (!std::isfinite (colour_range_[c]) || !std::isfinite (colour_minimum_[c])) {
      colour_minimum_[c] = 0.0;
      colour_range_[c] = 255.0;
    }
  }
}

int
E57PointConverter::find (const char* name) const
{
  for (std::size_t i = 0; i < scan_.prototype.size(); ++i)
    if (scan_.prototype[i].name == name)
      return static_cast<int> (i);
  return -1;
}

void
E57PointConverter::convert (const std::vector<double>& values,
                            std::size_t count,
                            TableBuilder& out)
{
  const auto index = [this] (const double* record, int field, const char* what) {
    const double v = record[field];
    if (!(v >= std::numeric_limits<std::int32_t>::min() &&
          v <= std::numeric_limits<std::int32_t>::max()))
      throw ReadError (
          path_, 0, where_ + ": a " + what + " value does not fit 32 bits");
    return static_cast<std::int32_t> (v);
  };
  for (std::size_t r = 0; r < count; ++r) {
    const double* record = values.data() + r * width_;
    if (invalid_state_ >= 0 && record[invalid_state_] != 0.0)
      continue; // 1: direction only, 2: no measurement
    Eigen::Vector3d p (
        record[coordinate_[0]], record[coordinate_[1]], record[coordinate_[2]]);
    if (spherical_) {
      const double range = p[0], azimuth = p[1], elevation = p[2];
      p = range * Eigen::Vector3d (std::cos (elevation) * std::cos (azimuth),
                                   std::cos (elevation) * std::sin (azimuth),
                                   std::sin (elevation));
    }
    if (apply_pose_)
      p = rotation_ * p + scan_.translation;
    if (!p.allFinite())
      continue;

    float intensity = std::numeric_limits<float>::quiet_NaN();
    if (intensity_ >= 0 &&
        !(intensity_invalid_ >= 0 && record[intensity_invalid_] != 0.0)) {
      double v = record[intensity_];
      if (intensity_range_ > 0.0)
        v = (v - intensity_minimum_) / intensity_range_;
      if (std::isfinite (v) && std::abs (v) <= std::numeric_limits<float>::max())
        intensity = static_cast<float> (v);
    }
    std::array<std::uint8_t, 3> rgb{0, 0, 0};
    if (colour_[0] >= 0 && !(colour_invalid_ >= 0 && record[colour_invalid_] != 0.0))
      for (int c = 0; c < 3; ++c) {
        const double v =
            (record[colour_[c]] - colour_minimum_[c]) / colour_range_[c] * 255.0;
        rgb[c] = static_cast<std::uint8_t> (
            std::isfinite (v) ? std::lround (std::clamp (v, 0.0, 255.0)) : 0);
      }
    std::int32_t row = 0, column = 0;
    if (row_ >= 0)
      row = index (record, row_, "rowIndex");
    if (column_ >= 0)
      column = index (record, column_, "columnIndex");
    out.add (p,
             intensity_ >= 0 ? &intensity : nullptr,
             colour_[0] >= 0 ? &rgb : nullptr,
             row_ >= 0 ? &row : nullptr,
             column_ >= 0 ? &column : nullptr);
    out.table.scan.push_back (station_);
  }
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
