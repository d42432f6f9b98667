/*
 * ASCII point files and the Oakland 3-D format, including malformed input.
 */
#include <pcl_ext/io/ascii_reader.h>

#include <pcl/point_types.h>

#include "test_helpers.h"

using pcl_ext::io::AsciiColumn;
using pcl_ext::io::PointTable;

TEST (AsciiReader, ColumnSpec)
{
  const auto c = pcl_ext::io::parseColumnSpec ("X, y z,i,R,g,b,label,_");
  ASSERT_EQ (c.size(), 9u);
  EXPECT_EQ (c[0], AsciiColumn::X);
  EXPECT_EQ (c[3], AsciiColumn::Intensity);
  EXPECT_EQ (c[4], AsciiColumn::Red);
  EXPECT_EQ (c[7], AsciiColumn::Label);
  EXPECT_EQ (c[8], AsciiColumn::Skip);
  EXPECT_THROW (pcl_ext::io::parseColumnSpec ("x,y"), std::invalid_argument);
  EXPECT_THROW (pcl_ext::io::parseColumnSpec ("x,y,z,w"), std::invalid_argument);
  EXPECT_THROW (pcl_ext::io::parseColumnSpec ("x,y,z,x"), std::invalid_argument);
  EXPECT_THROW (pcl_ext::io::parseColumnSpec ("x,y,z,r,g"), std::invalid_argument);
  EXPECT_NO_THROW (pcl_ext::io::parseColumnSpec ("x,y,z,_,_"));
  EXPECT_EQ (pcl_ext::io::defaultColumns (8).size(), 8u);
  EXPECT_TRUE (pcl_ext::io::defaultColumns (5).empty());
}

TEST (AsciiReader, WhitespaceWithAllColumns)
{
  PointTable t;
  pcl_ext::io::loadAsciiPoints (fixture ("points_xyzirgbl.txt"), t);
  ASSERT_EQ (t.size(), 3u);
  ASSERT_EQ (t.intensity.size(), 3u);
  ASSERT_EQ (t.rgb.size(), 3u);
  ASSERT_EQ (t.label.size(), 3u);
  EXPECT_EQ (t.xyz[1], Eigen::Vector3d (1.5, -2.0, 3.25));
  EXPECT_EQ (t.xyz[2],
             Eigen::Vector3d (-1e-3, 200.0, 4.0)); // tab, exponent, leading '+'
  EXPECT_FLOAT_EQ (t.intensity[1], 20.5f);
  EXPECT_EQ (t.rgb[0][0], 255);
  EXPECT_EQ (t.rgb[2][2], 255);
  EXPECT_EQ (t.label, (std::vector<std::uint32_t>{1, 2, 3}));

  // A column spec overrides the guess: skip intensity and colour.
  pcl_ext::io::loadAsciiPoints (
      fixture ("points_xyzirgbl.txt"), t, "x,y,z,_,_,_,_,class");
  EXPECT_TRUE (t.intensity.empty());
  EXPECT_TRUE (t.rgb.empty());
  EXPECT_EQ (t.label, (std::vector<std::uint32_t>{1, 2, 3}));
}

TEST (AsciiReader, CommaSeparatedWithCrLf)
{
  PointTable t;
  pcl_ext::io::loadAsciiPoints (fixture ("points_comma.csv"), t, "x,y,z,label");
  ASSERT_EQ (t.size(), 2u);
  EXPECT_EQ (t.xyz[0], Eigen::Vector3d (1, 2, 3));
  EXPECT_EQ (t.label[0], 7u);
  EXPECT_EQ (t.label[1], 0u);
  // Without a spec, the commented header "//X,Y,Z,label" names the columns.
  pcl_ext::io::loadAsciiPoints (fixture ("points_comma.csv"), t);
  EXPECT_TRUE (t.intensity.empty());
  EXPECT_EQ (t.label.size(), 2u);
  EXPECT_EQ (t.label[0], 7u);
}

TEST (AsciiReader, GeoreferencedKeepsDoublesAndLocalOrigin)
{
  PointTable t;
  pcl_ext::io::loadAsciiPoints (fixture ("points_georef.txt"), t, "x y z label");
  ASSERT_EQ (t.size(), 3u);
  EXPECT_EQ (t.xyz[2].y(), 485199.999);
  const Eigen::Vector3d origin = pcl_ext::io::computeLocalOrigin (t);
  EXPECT_EQ (origin, Eigen::Vector3d (119300.0, 485100.0, 0.0)); // z is small: kept
  EXPECT_EQ (pcl_ext::io::computeLocalOrigin (t, 1000.0),
             Eigen::Vector3d (119000.0, 485000.0, 0.0));

  pcl::PointCloud<pcl::PointXYZL> cloud;
  pcl_ext::io::toPointCloud (t, origin, cloud);
  ASSERT_EQ (cloud.size(), 3u);
  EXPECT_FLOAT_EQ (cloud[0].x, 5.125f);
  EXPECT_NEAR (cloud[2].y, 99.999f, 1e-5); // millimetres survive in float
  EXPECT_EQ (cloud[1].label, 6u);

  pcl::PCLPointCloud2 blob;
  pcl_ext::io::toPCLPointCloud2 (t, origin, blob);
  ASSERT_EQ (blob.fields.size(), 4u);
  EXPECT_EQ (blob.fields[3].name, "label");
  EXPECT_EQ (blob.width, 3u);
  EXPECT_TRUE (blob.is_dense);
}

TEST (AsciiReader, ColourAndIntensityReachTypedClouds)
{
  PointTable t;
  pcl_ext::io::loadAsciiPoints (fixture ("points_xyzirgbl.txt"), t);
  pcl::PointCloud<pcl::PointXYZRGBL> rgbl;
  pcl_ext::io::toPointCloud (t, Eigen::Vector3d::Zero(), rgbl);
  EXPECT_EQ (rgbl[0].r, 255);
  EXPECT_EQ (rgbl[1].g, 255);
  EXPECT_EQ (rgbl[2].b, 255);
  EXPECT_EQ (rgbl[2].label, 3u);
  pcl::PointCloud<pcl::PointXYZI> xyzi;
  pcl_ext::io::toPointCloud (t, Eigen::Vector3d::Zero(), xyzi);
  EXPECT_FLOAT_EQ (xyzi[2].intensity, 30.f);
}

TEST (AsciiReader, MalformedInputNamesFileAndLine)
{
  PointTable t;
  pcl_ext::io::loadAsciiPoints (fixture ("points_comma.csv"), t, "x,y,z,label");
  const PointTable before = t;
  const auto unchanged = [&] {
    EXPECT_EQ (t.xyz, before.xyz);
    EXPECT_EQ (t.label, before.label);
  };

  std::string p = fixture ("points_bad_number.txt");
  expectReadError (
      [&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 3, "'nine' is not a number");
  unchanged();
  p = fixture ("points_wrong_columns.txt");
  expectReadError (
      [&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 3, "expected 4 values, found 3");
  unchanged();
  p = fixture ("points_truncated.txt");
  expectReadError (
      [&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 3, "expected 3 values, found 2");
  unchanged();
  p = fixture ("empty.txt");
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 0, "empty file");
  p = fixture ("comments_only.txt");
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 0, "no points");
  p = fixture ("does_not_exist.txt");
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 0, "no such file");
  p = std::string (PCL_EXT_TEST_DATA_DIR);
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 0, "folder");
  unchanged();

  // Bad values in typed columns.
  p = fixture ("points_xyzirgbl.txt");
  expectReadError (
      [&] { pcl_ext::io::loadAsciiPoints (fixture ("points_bad_colour.txt"), t); },
      fixture ("points_bad_colour.txt"),
      2,
      "column 5 (green): '300' is not a colour value");
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t, "x,y,z,label,r,g,b,i"); },
                   p,
                   4,
                   "'20.5' is not a non-negative integer label");
  expectReadError ([&] { pcl_ext::io::loadAsciiPoints (p, t, "x,y,z,nonsense"); },
                   p,
                   0,
                   "unknown column");
  // Five values cannot be guessed.
  p = fixture ("oakland_sample.xyz_label_conf");
  expectReadError (
      [&] { pcl_ext::io::loadAsciiPoints (p, t); }, p, 4, "give a column spec");
  unchanged();
}

TEST (OaklandReader, SampleFile)
{
  PointTable t;
  pcl_ext::io::loadOaklandFile (fixture ("oakland_sample.xyz_label_conf"), t);
  ASSERT_EQ (t.size(), 6u);
  EXPECT_EQ (t.label, (std::vector<std::uint32_t>{1203, 1203, 1203, 1400, 1501, 1001}));
  EXPECT_EQ (t.xyz[0], Eigen::Vector3d (10.0, 20.0, -1.5));
  EXPECT_TRUE (t.intensity.empty());

  const std::string p = fixture ("oakland_bad_line.xyz_label_conf");
  expectReadError ([&] { pcl_ext::io::loadOaklandFile (p, t); }, p, 3, "'1203.5'");
  EXPECT_EQ (t.size(), 6u);
}
