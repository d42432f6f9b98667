/*
 * pcl_ext: conversion of point tables to PCL clouds.
 */
#include <pcl_ext/io/point_table.h>

#include <pcl/PCLPointField.h>

#include <cmath>
#include <cstring>

namespace pcl_ext {
namespace io {
Eigen::Vector3d
computeLocalOrigin (const PointTable& table, double grid)
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  if (table.empty() || !(grid > 0.0))
    return origin;
  Eigen::Vector3d min = table.xyz.front(), max_abs = table.xyz.front().cwiseAbs();
  for (const auto& p : table.xyz) {
    min = min.cwiseMin (p);
    max_abs = max_abs.cwiseMax (p.cwiseAbs());
  }
  for (int axis = 0; axis < 3; ++axis)
    if (max_abs[axis] > kFloatSafeCoordinate)
      origin[axis] = std::floor (min[axis] / grid) * grid;
  return origin;
}

bool
sensorPosition (const PointTable& table, std::size_t index, Eigen::Vector3d& position)
{
  if (index >= table.size() || table.scan.size() != table.size() ||
      table.scan[index] >= table.stations.size())
    return false;
  const ScanStation& station = table.stations[table.scan[index]];
  position =
      station.points_in_scanner_frame ? Eigen::Vector3d::Zero() : station.position;
  return true;
}

void
toPCLPointCloud2 (const PointTable& table,
                  const Eigen::Vector3d& origin,
                  pcl::PCLPointCloud2& cloud)
{
  cloud = pcl::PCLPointCloud2();
  const std::size_t n = table.size();
  const bool has_intensity = table.intensity.size() == n && n > 0;
  const bool has_rgb = table.rgb.size() == n && n > 0;
  const bool has_label = table.label.size() == n && n > 0;
  const bool has_row = table.row.size() == n && n > 0;
  const bool has_column = table.column.size() == n && n > 0;
  const bool has_scan = table.scan.size() == n && n > 0;
  std::uint32_t offset = 0;
  const auto add = [&cloud, &offset] (const std::string& name,
                                      std::uint8_t type,
                                      std::uint32_t size = 4) {
    pcl::PCLPointField f;
    f.name = name;
    f.offset = offset;
    f.datatype = type;
    f.count = 1;
    cloud.fields.push_back (f);
    offset += size;
    return f.offset;
  };
  add ("x", pcl::PCLPointField::FLOAT32);
  add ("y", pcl::PCLPointField::FLOAT32);
  add ("z", pcl::PCLPointField::FLOAT32);
  const std::uint32_t intensity_offset =
      has_intensity ? add ("intensity", pcl::PCLPointField::FLOAT32) : 0;
  // PCL stores packed colour in a float32 field named rgb (as pcl::PointXYZRGB does).
  const std::uint32_t rgb_offset =
      has_rgb ? add ("rgb", pcl::PCLPointField::FLOAT32) : 0;
  const std::uint32_t label_offset =
      has_label ? add ("label", pcl::PCLPointField::UINT32) : 0;
  const std::uint32_t row_offset = has_row ? add ("row", pcl::PCLPointField::INT32) : 0;
  const std::uint32_t column_offset =
      has_column ? add ("column", pcl::PCLPointField::INT32) : 0;
  const std::uint32_t scan_offset =
      has_scan ? add ("scan", pcl::PCLPointField::UINT16, 2) : 0;
  // Keep every point 4-byte aligned (a trailing uint16 leaves 2 bytes of padding).
  cloud.point_step = (offset + 3u) & ~3u;
  cloud.width = static_cast<std::uint32_t> (n);
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.is_dense = true;
  cloud.is_bigendian = false;
  cloud.data.resize (static_cast<std::size_t> (cloud.point_step) * n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    const Eigen::Vector3f p = (table.xyz[i] - origin).cast<float>();
    std::memcpy (point, p.data(), 3 * sizeof (float));
    if (!std::isfinite (p.x()) || !std::isfinite (p.y()) || !std::isfinite (p.z()))
      cloud.is_dense = false;
    if (has_intensity)
      std::memcpy (point + intensity_offset, &table.intensity[i], 4);
    if (has_rgb) {
      const auto& c = table.rgb[i];
      const std::uint32_t packed = (static_cast<std::uint32_t> (c[0]) << 16) |
                                   (static_cast<std::uint32_t> (c[1]) << 8) | c[2];
      std::memcpy (point + rgb_offset, &packed, 4);
    }
    if (has_label)
      std::memcpy (point + label_offset, &table.label[i], 4);
    if (has_row)
      std::memcpy (point + row_offset, &table.row[i], 4);
    if (has_column)
      std::memcpy (point + column_offset, &table.column[i], 4);
    if (has_scan)
      std::memcpy (point + scan_offset, &table.scan[i], 2);
  }
}
} // namespace io
} // namespace pcl_ext
