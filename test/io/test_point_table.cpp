/*
 * Tests of PointTable: the local origin of georeferenced coordinates and the conversion
 * to PCL clouds (fields, offsets, attributes, precision).
 */
#include <pcl_ext/io/point_table.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

using pcl_ext::io::PointTable;

namespace {
/** Two points with every attribute, the first at RD New / NAP coordinates. */
PointTable
georeferenced ()
{
  PointTable t;
  t.xyz = {Eigen::Vector3d (119345.678, 487123.456, 2.5),
           Eigen::Vector3d (119399.001, 487100.002, -1.25)};
  t.intensity = {0.25f, 0.75f};
  t.rgb = {{{255, 128, 0}}, {{1, 2, 3}}};
  t.label = {6, 4000000000u};
  return t;
}
} // namespace

TEST (PointTable, LocalOriginOnlyWhereFloatLosesTheMillimetre)
{
  PointTable t = georeferenced();
  EXPECT_EQ (t.size(), 2u);
  EXPECT_FALSE (t.empty());
  // x and y beyond 8192 m: their minimum rounded down to 100 m; z local: 0.
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (t),
             Eigen::Vector3d (119300.0, 487100.0, 0.0));
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (t, 1000.0),
             Eigen::Vector3d (119000.0, 487000.0, 0.0));
  // Rounded down also below zero; one large coordinate moves its whole axis.
  t.xyz[1].x() = -9000.5;
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (t).x(), -9100.0);
  PointTable local;
  local.xyz = {Eigen::Vector3d (8191.0, -8000.0, 12.0),
               Eigen::Vector3d (10.0, 20.0, 30.0)};
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (local), Eigen::Vector3d::Zero());
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (PointTable()), Eigen::Vector3d::Zero());
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (t, 0.0), Eigen::Vector3d::Zero());
}

TEST (PointTable, BlobHasXyzThenTheAttributesPresent)
{
  const PointTable t = georeferenced();
  const Eigen::Vector3d origin (119300.0, 487100.0, 0.0);
  pcl::PCLPointCloud2 blob;
  pcl_ext::io::toPCLPointCloud2 (t, origin, blob);
  ASSERT_EQ (blob.fields.size(), 6u);
  const char* names[] = {"x", "y", "z", "intensity", "rgb", "label"};
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ (blob.fields[f].name, names[f]);
    EXPECT_EQ (blob.fields[f].offset, 4 * f);
    EXPECT_EQ (blob.fields[f].count, 1u);
    EXPECT_EQ (blob.fields[f].datatype,
               f == 5 ? pcl::PCLPointField::UINT32 : pcl::PCLPointField::FLOAT32);
  }
  EXPECT_EQ (blob.point_step, 24u);
  EXPECT_EQ (blob.width, 2u);
  EXPECT_EQ (blob.height, 1u);
  EXPECT_EQ (blob.row_step, 48u);
  EXPECT_EQ (blob.data.size(), 48u);
  EXPECT_TRUE (blob.is_dense);
  // Colour packed as pcl::PointXYZRGB packs it: 0x00RRGGBB.
  std::uint32_t packed;
  std::memcpy (&packed, blob.data.data() + 16, 4);
  EXPECT_EQ (packed, 0xff8000u);

  // Attributes without one value per point are left out; a non-finite point clears
  // is_dense.
  PointTable partial;
  partial.xyz = {Eigen::Vector3d (1, 2, 3),
                 Eigen::Vector3d (std::numeric_limits<double>::quiet_NaN(), 0, 0)};
  partial.intensity = {1.f};
  partial.label = {1, 2};
  pcl_ext::io::toPCLPointCloud2 (partial, Eigen::Vector3d::Zero(), blob);
  ASSERT_EQ (blob.fields.size(), 4u);
  EXPECT_EQ (blob.fields[3].name, "label");
  EXPECT_EQ (blob.fields[3].offset, 12u);
  EXPECT_EQ (blob.point_step, 16u);
  EXPECT_FALSE (blob.is_dense);
}

TEST (PointTable, TypedCloudsKeepTheMillimetreAndTheirOwnFields)
{
  const PointTable t = georeferenced();
  const Eigen::Vector3d origin = pcl_ext::io::computeLocalOrigin (t);
  pcl::PointCloud<pcl::PointXYZRGBL> coloured;
  pcl_ext::io::toPointCloud (t, origin, coloured);
  ASSERT_EQ (coloured.size(), 2u);
  EXPECT_NEAR (coloured[0].x, 45.678, 1e-4);
  EXPECT_NEAR (coloured[0].y, 23.456, 1e-4);
  EXPECT_NEAR (coloured[1].x, 99.001, 1e-4);
  EXPECT_NEAR (coloured[1].y, 0.002, 1e-4);
  EXPECT_EQ (coloured[1].z, -1.25f);
  EXPECT_EQ (coloured[0].r, 255);
  EXPECT_EQ (coloured[0].g, 128);
  EXPECT_EQ (coloured[0].b, 0);
  EXPECT_EQ (coloured[1].b, 3);
  EXPECT_EQ (coloured[0].label, 6u);
  EXPECT_EQ (coloured[1].label, 4000000000u);
  // A type without the attributes takes the coordinates; one with a field the table
  // lacks keeps its default.
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl_ext::io::toPointCloud (t, origin, xyz);
  ASSERT_EQ (xyz.size(), 2u);
  EXPECT_EQ (xyz[1].z, -1.25f);
  PointTable bare;
  bare.xyz = t.xyz;
  pcl::PointCloud<pcl::PointXYZI> intensity;
  pcl_ext::io::toPointCloud (bare, origin, intensity);
  ASSERT_EQ (intensity.size(), 2u);
  EXPECT_EQ (intensity[0].intensity, 0.f);
}

TEST (PointTable, ScanGridAndStationFieldsAndTheSensorOfAPoint)
{
  PointTable t;
  t.xyz = {Eigen::Vector3d (1, 2, 3), Eigen::Vector3d (4, 5, 6)};
  t.row = {7, -1};
  t.column = {-2, 2147483647};
  t.scan = {1, 0};
  pcl_ext::io::ScanStation a, b;
  a.position = Eigen::Vector3d (10, 20, 30);
  b.position = Eigen::Vector3d (-1, -2, -3);
  b.points_in_scanner_frame = true;
  t.stations = {a, b};
  pcl::PCLPointCloud2 blob;
  pcl_ext::io::toPCLPointCloud2 (t, Eigen::Vector3d::Zero(), blob);
  ASSERT_EQ (blob.fields.size(), 6u);
  EXPECT_EQ (blob.fields[3].name, "row");
  EXPECT_EQ (blob.fields[3].datatype, pcl::PCLPointField::INT32);
  EXPECT_EQ (blob.fields[4].name, "column");
  EXPECT_EQ (blob.fields[4].offset, 16u);
  EXPECT_EQ (blob.fields[5].name, "scan");
  EXPECT_EQ (blob.fields[5].datatype, pcl::PCLPointField::UINT16);
  EXPECT_EQ (blob.fields[5].offset, 20u);
  // 22 bytes of fields padded to 24.
  EXPECT_EQ (blob.point_step, 24u);
  ASSERT_EQ (blob.data.size(), 48u);
  std::int32_t row, column;
  std::uint16_t scan;
  std::memcpy (&row, blob.data.data() + 24 + 12, 4);
  std::memcpy (&column, blob.data.data() + 24 + 16, 4);
  std::memcpy (&scan, blob.data.data() + 20, 2);
  EXPECT_EQ (row, -1);
  EXPECT_EQ (column, 2147483647);
  EXPECT_EQ (scan, 1u);

  // Point 1 comes from station 0 (file frame); point 0 from station 1, whose points
  // stayed in the scanner frame: its sensor is at their origin.
  Eigen::Vector3d sensor (9, 9, 9);
  ASSERT_TRUE (pcl_ext::io::sensorPosition (t, 1, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d (10, 20, 30));
  ASSERT_TRUE (pcl_ext::io::sensorPosition (t, 0, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d::Zero());
  EXPECT_FALSE (pcl_ext::io::sensorPosition (t, 2, sensor));
  t.scan[0] = 2;
  EXPECT_FALSE (pcl_ext::io::sensorPosition (t, 0, sensor));
  t.scan.clear();
  EXPECT_FALSE (pcl_ext::io::sensorPosition (t, 0, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d::Zero());
}
