/*
 * Leica PTX and PTS files written in the test: several scans with their transforms,
 * no-return grid cells, colour or not, counts or not, and malformed files.
 */
#include <pcl_ext/io/ptx_reader.h>

#include "temp_folder.h"
#include "test_helpers.h"

#include <cmath>
#include <fstream>

using pcl_ext::io::PointTable;

namespace {
std::string
writeFile (const std::string& name, const std::string& text)
{
  static const std::string dir = freshFolder ("ptx_reader");
  const std::string path = dir + "/" + name;
  std::ofstream (path, std::ios::binary) << text;
  return path;
}

/** A PTX scan header: grid size, scanner position and axes, and the transform as PTX
 * writes it (transposed: the last line holds the translation). */
std::string
header (int columns,
        int rows,
        const std::string& position,
        const std::string& transposed_transform)
{
  return std::to_string (columns) + "\n" + std::to_string (rows) + "\n" + position +
         "\n1 0 0\n0 1 0\n0 0 1\n" + transposed_transform;
}

// Scan 1: a quarter turn about z (x -> y, y -> -x) and a translation (10, 20, 30).
const std::string kTurned = "0 1 0 0\n-1 0 0 0\n0 0 1 0\n10 20 30 1\n";
const std::string kIdentity = "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
} // namespace

TEST (PtxReader, TwoScansTransformedNoReturnsDroppedGridKept)
{
  // Scan 1: 2 columns x 2 rows, colour, the cell (row 1, column 0) a no-return.
  // Scan 2: 1 column x 3 rows, no colour, identity, its first cell a no-return.
  const std::string path = writeFile (
      "two.ptx",
      header (2, 2, "10 20 30", kTurned) +
          "1 0 0 0.5 10 20 30\n0 0 0 0.5 0 0 0\n0 2 0 0.25 1 2 3\n0 0 3 1 255 255 "
          "255\n" +
          header (1, 3, "0 0 0", kIdentity) + "0 0 0 0\n5 6 7 0.125\n-1 -2 -3 0.75\n");
  PointTable t;
  pcl_ext::io::loadPTX (path, t);
  ASSERT_EQ (t.size(), 5u);
  ASSERT_EQ (t.intensity.size(), 5u);
  ASSERT_EQ (t.rgb.size(), 5u);
  ASSERT_EQ (t.row.size(), 5u);
  ASSERT_EQ (t.column.size(), 5u);
  ASSERT_EQ (t.scan.size(), 5u);
  // (1, 0, 0) turned to (0, 1, 0), plus (10, 20, 30).
  EXPECT_TRUE (t.xyz[0].isApprox (Eigen::Vector3d (10, 21, 30)));
  EXPECT_TRUE (t.xyz[1].isApprox (Eigen::Vector3d (8, 20, 30)));
  EXPECT_TRUE (t.xyz[2].isApprox (Eigen::Vector3d (10, 20, 33)));
  EXPECT_EQ (t.xyz[3], Eigen::Vector3d (5, 6, 7));
  EXPECT_EQ (t.xyz[4], Eigen::Vector3d (-1, -2, -3));
  // Points run column after column: k -> (row k % rows, column k / rows).
  EXPECT_EQ (t.row, (std::vector<std::int32_t>{0, 0, 1, 1, 2}));
  EXPECT_EQ (t.column, (std::vector<std::int32_t>{0, 1, 1, 0, 0}));
  EXPECT_EQ (t.scan, (std::vector<std::uint16_t>{0, 0, 0, 1, 1}));
  EXPECT_EQ (t.intensity[1], 0.25f);
  EXPECT_EQ (t.intensity[3], 0.125f);
  EXPECT_EQ (t.rgb[0], (std::array<std::uint8_t, 3>{10, 20, 30}));
  EXPECT_EQ (t.rgb[2], (std::array<std::uint8_t, 3>{255, 255, 255}));
  // The scan without colour is black.
  EXPECT_EQ (t.rgb[4], (std::array<std::uint8_t, 3>{0, 0, 0}));

  ASSERT_EQ (t.stations.size(), 2u);
  EXPECT_EQ (t.stations[0].position, Eigen::Vector3d (10, 20, 30));
  EXPECT_EQ (t.stations[0].rows, 2);
  EXPECT_EQ (t.stations[0].columns, 2);
  EXPECT_EQ (t.stations[1].rows, 3);
  EXPECT_TRUE (t.stations[0].orientation.isApprox (
      Eigen::Quaterniond (Eigen::AngleAxisd (M_PI / 2, Eigen::Vector3d::UnitZ()))));
  EXPECT_TRUE (t.stations[1].orientation.isApprox (Eigen::Quaterniond::Identity()));
  Eigen::Vector3d sensor;
  ASSERT_TRUE (pcl_ext::io::sensorPosition (t, 2, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d (10, 20, 30));

  // In the scanner frame: the points as written, the pose still in the stations.
  pcl_ext::io::PtxOptions options;
  options.keep_scanner_frame = true;
  PointTable raw;
  pcl_ext::io::loadPTX (path, raw, options);
  ASSERT_EQ (raw.size(), 5u);
  EXPECT_EQ (raw.xyz[0], Eigen::Vector3d (1, 0, 0));
  EXPECT_TRUE (raw.stations[0].points_in_scanner_frame);
  EXPECT_EQ (raw.stations[0].position, Eigen::Vector3d (10, 20, 30));
  // Pose applied by hand gives the registered point.
  EXPECT_TRUE ((raw.stations[0].orientation * raw.xyz[0] + raw.stations[0].position)
                   .isApprox (t.xyz[0]));
  ASSERT_TRUE (pcl_ext::io::sensorPosition (raw, 2, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d::Zero());
}

TEST (PtxReader, WithoutColourAndWithAScaledTransform)
{
  // The transform scales z by 2 (as PDAL's multiple-and-transform sample does).
  const std::string path = writeFile (
      "scaled.ptx",
      header (1, 2, "600 800 400", "1 0 0 0\n0 1 0 0\n0 0 2 0\n600 800 400 1\n") +
          "1 2 3 0.5\n4 5 6 0.75\n");
  PointTable t;
  pcl_ext::io::loadPTX (path, t);
  ASSERT_EQ (t.size(), 2u);
  EXPECT_TRUE (t.rgb.empty());
  EXPECT_EQ (t.xyz[0], Eigen::Vector3d (601, 802, 406));
  EXPECT_EQ (t.xyz[1], Eigen::Vector3d (604, 805, 412));
  EXPECT_EQ (t.row, (std::vector<std::int32_t>{0, 1}));
  EXPECT_EQ (t.intensity, (std::vector<float>{0.5f, 0.75f}));
  // The scale does not leak into the orientation.
  EXPECT_TRUE (t.stations[0].orientation.isApprox (Eigen::Quaterniond::Identity()));
}

TEST (PtxReader, MalformedFilesNameTheirLine)
{
  const auto expectError = [] (const std::string& name,
                               const std::string& text,
                               std::size_t line,
                               const std::string& fragment) {
    const std::string path = writeFile (name, text);
    PointTable t;
    t.xyz.push_back (Eigen::Vector3d (1, 1, 1));
    expectReadError ([&] { pcl_ext::io::loadPTX (path, t); }, path, line, fragment);
    EXPECT_EQ (t.size(), 1u) << "the table is untouched";
  };
  expectError ("empty.ptx", "", 0, "no scan");
  expectError ("truncated.ptx",
               header (2, 2, "0 0 0", kIdentity) + "1 2 3 0.5\n",
               0,
               "4 points (found 1)");
  expectError ("header.ptx", "2\n2\n0 0\n", 3, "scanner position");
  expectError ("columns.ptx", "-2\n2\n", 1, "number of columns");
  expectError ("huge.ptx", "100000\n100000\n", 2, "too large");
  expectError ("nan.ptx",
               header (1, 1, "0 0 0", "1 0 0 0\n0 1 0 0\n0 0 1 0\nnan 0 0 1\n"),
               10,
               "not a finite number");
  expectError ("width.ptx",
               header (1, 2, "0 0 0", kIdentity) + "1 2 3 0.5 1 2 3\n1 2 3 0.5\n",
               12,
               "expected 7 values, found 4");
  expectError ("colour.ptx",
               header (1, 1, "0 0 0", kIdentity) + "1 2 3 0.5 1 2 300\n",
               11,
               "[0, 255]");
  expectError (
      "values.ptx", header (1, 1, "0 0 0", kIdentity) + "1 2\n", 11, "found 2");
}

TEST (PtsReader, WithCountWithoutCountAndMalformed)
{
  PointTable t;
  pcl_ext::io::loadPTS (
      writeFile ("count.pts", "2\n1 2 3 -1613 52 70 64\n4 5 6 7 8 9 10\n"), t);
  ASSERT_EQ (t.size(), 2u);
  EXPECT_EQ (t.xyz[1], Eigen::Vector3d (4, 5, 6));
  EXPECT_EQ (t.intensity, (std::vector<float>{-1613.f, 7.f}));
  EXPECT_EQ (t.rgb[0], (std::array<std::uint8_t, 3>{52, 70, 64}));
  EXPECT_TRUE (t.stations.empty());
  EXPECT_TRUE (t.scan.empty());

  pcl_ext::io::loadPTS (writeFile ("nocount.pts", "1.5 2 3\n4 5 6.25\n7 8 9\n"), t);
  ASSERT_EQ (t.size(), 3u);
  EXPECT_TRUE (t.intensity.empty());
  EXPECT_TRUE (t.rgb.empty());
  EXPECT_EQ (t.xyz[2], Eigen::Vector3d (7, 8, 9));
  EXPECT_EQ (t.xyz[0].x(), 1.5);

  // x y z r g b; and two count blocks one after the other.
  pcl_ext::io::loadPTS (writeFile ("rgb.pts", "1\n1 2 3 4 5 6\n1\n7 8 9 10 11 12\n"),
                        t);
  ASSERT_EQ (t.size(), 2u);
  EXPECT_TRUE (t.intensity.empty());
  EXPECT_EQ (t.rgb[1], (std::array<std::uint8_t, 3>{10, 11, 12}));

  const auto expectError = [] (const std::string& name,
                               const std::string& text,
                               std::size_t line,
                               const std::string& fragment) {
    const std::string path = writeFile (name, text);
    PointTable u;
    expectReadError ([&] { pcl_ext::io::loadPTS (path, u); }, path, line, fragment);
    EXPECT_TRUE (u.empty());
  };
  expectError ("short.pts", "3\n1 2 3\n", 0, "declares 2 more points");
  expectError ("long.pts", "1\n1 2 3\n4 5 6\n", 3, "more points than the count");
  expectError ("empty.pts", "", 0, "no points");
  expectError ("zero.pts", "0\n", 0, "no points");
  expectError ("width.pts", "1 2 3 4 5\n", 1, "found 5 values");
  expectError ("mixed.pts", "1 2 3\n1 2 3 4\n", 2, "expected 3 values");
  expectError ("text.pts", "1 2 z\n", 1, "not a finite number");
}
