/*
 * pcl_ext: Leica PTX and PTS files.
 */
#include <pcl_ext/io/ptx_reader.h>

#include "table_builder.h"
#include "text_lines.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <limits>

namespace pcl_ext {
namespace io {
namespace {
using detail::TableBuilder;
using detail::TextLines;

/** Next data line split into values; fails with \a what when the file ends. */
void
nextValues (TextLines& lines,
            std::vector<std::string_view>& values,
            const std::string& what)
{
  std::string_view line;
  if (!lines.nextData (line, false))
    throw ReadError (lines.path(), 0, "the file ends before " + what);
  detail::splitBlanks (line, values);
}

/** A header line of exactly \a count finite numbers. */
void
headerNumbers (TextLines& lines,
               double* out,
               std::size_t count,
               const std::string& what)
{
  std::vector<std::string_view> values;
  nextValues (lines, values, what);
  if (values.size() != count)
    lines.fail (what + ": expected " + std::to_string (count) + " values, found " +
                std::to_string (values.size()));
  for (std::size_t i = 0; i < count; ++i)
    if (!detail::parseDouble (values[i], out[i]) || !std::isfinite (out[i]))
      lines.fail (what + ": " + detail::quote (values[i]) + " is not a finite number");
}

/** A header line holding one grid size, 0 .. 2^31 - 1. */
std::int64_t
gridSize (TextLines& lines, const std::string& what)
{
  double v = 0.0;
  headerNumbers (lines, &v, 1, what);
  if (!(v >= 0.0) || v > std::numeric_limits<std::int32_t>::max() ||
      v != std::floor (v))
    lines.fail (what + " is not an integer in [0, 2^31 - 1]");
  return static_cast<std::int64_t> (v);
}

/** Intensity as float: finite and within float range. */
float
intensityValue (TextLines& lines, std::string_view text)
{
  double v = 0.0;
  if (!detail::parseDouble (text, v) || !std::isfinite (v) ||
      std::abs (v) > std::numeric_limits<float>::max())
    lines.fail ("intensity " + detail::quote (text) + " is not a finite number");
  return static_cast<float> (v);
}

std::uint8_t
colourValue (TextLines& lines, std::string_view text)
{
  double v = 0.0;
  if (!detail::parseDouble (text, v) || !(v >= 0.0 && v <= 255.0))
    lines.fail ("colour " + detail::quote (text) + " is not a value in [0, 255]");
  return static_cast<std::uint8_t> (std::lround (v));
}

Eigen::Vector3d
coordinates (TextLines& lines, const std::vector<std::string_view>& values)
{
  Eigen::Vector3d p;
  for (int c = 0; c < 3; ++c)
    if (!detail::parseDouble (values[c], p[c]) || !std::isfinite (p[c]))
      lines.fail ("coordinate " + detail::quote (values[c]) +
                  " is not a finite number");
  return p;
}

/** Rotation of a linear map whose columns are the scanner axes: columns normalised (a
 * PTX may scale an axis), then the nearest rotation. */
Eigen::Quaterniond
axesRotation (const Eigen::Matrix3d& linear)
{
  Eigen::Matrix3d axes = linear;
  for (int c = 0; c < 3; ++c)
    if (axes.col (c).norm() > 0.0)
      axes.col (c).normalize();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd (
      axes, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0.0)
    r = svd.matrixU() * Eigen::Vector3d (1, 1, -1).asDiagonal() *
        svd.matrixV().transpose();
  return Eigen::Quaterniond (r).normalized();
}

/** Reads one scan's header and points; false when the file has no further scan. */
bool
readPtxScan (TextLines& lines, const PtxOptions& options, TableBuilder& out)
{
  std::string_view first;
  if (!lines.nextData (first, false))
    return false;
  const std::size_t index = out.table.stations.size();
  const std::string scan = "scan " + std::to_string (index + 1);
  double columns_value = 0.0;
  if (!detail::parseDouble (first, columns_value) || !(columns_value >= 0.0) ||
      columns_value > std::numeric_limits<std::int32_t>::max() ||
      columns_value != std::floor (columns_value))
    lines.fail (scan + ": the number of columns " + detail::quote (first) +
                " is not an integer in [0, 2^31 - 1]");
  if (index > std::numeric_limits<std::uint16_t>::max())
    lines.fail ("more than 65536 scans");
  const std::int64_t columns = static_cast<std::int64_t> (columns_value);
  const std::int64_t rows = gridSize (lines, scan + ": the number of rows");
  if (rows * columns > std::numeric_limits<std::int32_t>::max())
    lines.fail (scan + ": a grid of " + std::to_string (columns) + " x " +
                std::to_string (rows) + " points is too large");
  double position[3], axes[9], transform[16];
  headerNumbers (lines, position, 3, scan + ": the scanner position");
  for (int a = 0; a < 3; ++a)
    headerNumbers (lines, axes + 3 * a, 3, scan + ": the scanner axes");
  for (int r = 0; r < 4; ++r)
    headerNumbers (lines, transform + 4 * r, 4, scan + ": the transform");
  // Written transposed: line r holds column r of the usual column-vector matrix.
  Eigen::Matrix4d pose;
  for (int line = 0; line < 4; ++line)
    for (int c = 0; c < 4; ++c)
      pose (c, line) = transform[4 * line + c];
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3>();
  const Eigen::Vector3d translation = pose.topRightCorner<3, 1>();

  ScanStation station;
  station.name = scan;
  station.position = translation;
  station.orientation = axesRotation (linear);
  station.rows = static_cast<std::int32_t> (rows);
  station.columns = static_cast<std::int32_t> (columns);
  station.points_in_scanner_frame = options.keep_scanner_frame;
  out.table.stations.push_back (station);

  std::vector<std::string_view> values;
  std::size_t width = 0;
  const std::int64_t count = rows * columns;
  for (std::int64_t k = 0; k < count; ++k) {
    nextValues (lines,
                values,
                scan + "'s " + std::to_string (count) + " points (found " +
                    std::to_string (k) + ")");
    if (values.size() != 3 && values.size() != 4 && values.size() != 7)
      lines.fail (scan + ": expected x y z intensity [r g b], found " +
                  std::to_string (values.size()) + " values");
    const Eigen::Vector3d p = coordinates (lines, values);
    if (p.isZero (0.0))
      continue; // a no-return of the grid
    if (width == 0)
      width = values.size();
    else if (values.size() != width)
      lines.fail (scan + ": expected " + std::to_string (width) + " values, found " +
                  std::to_string (values.size()));
    float intensity = 0.f;
    std::array<std::uint8_t, 3> rgb{0, 0, 0};
    if (values.size() >= 4)
      intensity = intensityValue (lines, values[3]);
    if (values.size() == 7)
      for (int c = 0; c < 3; ++c)
        rgb[c] = colourValue (lines, values[4 + c]);
    const Eigen::Vector3d q =
        options.keep_scanner_frame ? p : Eigen::Vector3d (linear * p + translation);
    if (!q.allFinite())
      lines.fail (scan + ": the transformed point is not finite");
    const std::int32_t row = static_cast<std::int32_t> (k % rows);
    const std::int32_t column = static_cast<std::int32_t> (k / rows);
    out.add (q,
             values.size() >= 4 ? &intensity : nullptr,
             width == 7 ? &rgb : nullptr,
             &row,
             &column);
    out.table.scan.push_back (static_cast<std::uint16_t> (index));
  }
  return true;
}
} // namespace

void
loadPTX (const std::string& path, PointTable& table, const PtxOptions& options)
{
  TextLines lines (path);
  TableBuilder out;
  while (readPtxScan (lines, options, out)) {
  }
  if (out.table.stations.empty())
    throw ReadError (path, 0, "empty file, no scan");
  table = std::move (out.table);
}

void
loadPTS (const std::string& path, PointTable& table)
{
  TextLines lines (path);
  TableBuilder out;
  std::vector<std::string_view> values;
  std::string_view line;
  std::size_t width = 0;
  // Points still expected from the last count line; -1 while the file has no count.
  std::int64_t expected = -1;
  std::size_t count_line = 0;
  bool first = true;
  while (lines.nextData (line, false)) {
    detail::splitBlanks (line, values);
    double v = 0.0;
    const bool is_count = values.size() == 1 && detail::parseDouble (values[0], v) &&
                          v >= 0.0 && v == std::floor (v) && v < 9.0e15;
    if (is_count && (first || expected == 0)) {
      expected = static_cast<std::int64_t> (v);
      count_line = lines.lineNumber();
      first = false;
      continue;
    }
    first = false;
    if (expected == 0)
      lines.fail ("more points than the count on line " + std::to_string (count_line) +
                  " declares");
    if (width == 0) {
      width = values.size();
      if (width != 3 && width != 4 && width != 6 && width != 7)
        lines.fail ("expected x y z [intensity] [r g b], found " +
                    std::to_string (width) + " values");
    }
    else if (values.size() != width)
      lines.fail ("expected " + std::to_string (width) + " values, found " +
                  std::to_string (values.size()));
    const Eigen::Vector3d p = coordinates (lines, values);
    float intensity = 0.f;
    std::array<std::uint8_t, 3> rgb{0, 0, 0};
    if (width == 4 || width == 7)
      intensity = intensityValue (lines, values[3]);
    if (width >= 6)
      for (int c = 0; c < 3; ++c)
        rgb[c] = colourValue (lines, values[width - 3 + c]);
    out.add (p,
             width == 4 || width == 7 ? &intensity : nullptr,
             width >= 6 ? &rgb : nullptr);
    if (expected > 0)
      --expected;
  }
  if (expected > 0)
    throw ReadError (path,
                     0,
                     "the count on line " + std::to_string (count_line) + " declares " +
                         std::to_string (expected) +
                         " more points than the file holds");
  if (out.table.empty())
    throw ReadError (path, 0, "no points");
  table = std::move (out.table);
}
} // namespace io
} // namespace pcl_ext
