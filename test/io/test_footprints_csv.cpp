/*
 * Footprint polygons from CSV tables: WKT and JSON-coordinate geometry columns, RFC
 * 4180 quoting, delimiters, ids, and malformed tables.
 */
#include <pcl_ext/io/footprints.h>

#include "test_helpers.h"

#include <filesystem>
#include <fstream>

using pcl_ext::io::Footprint;
using pcl_ext::io::loadCsvFootprints;
using pcl_ext::io::signedArea;

namespace {
/** Writes \a text to a file of the test's temporary folder and returns its path. */
std::string
writeCsv (const std::string& name, const std::string& text)
{
  const auto dir =
      std::filesystem::temp_directory_path() / "pcl_ext_test_footprints_csv";
  std::filesystem::create_directories (dir);
  const std::string path = (dir / name).string();
  std::ofstream (path, std::ios::binary) << text;
  return path;
}

std::vector<Footprint>
load (const std::string& path)
{
  std::vector<Footprint> footprints;
  loadCsvFootprints (path, footprints);
  return footprints;
}
} // namespace

TEST (FootprintsCsv, JsonCoordinatesAsOpenDataPortalsWriteThem)
{
  // The layout of the Amsterdam BGT / BAG extracts: a quoted JSON ring, the bounding
  // box after it, no id column (the line number is the id). Coordinates keep full
  // double precision at 10^5 m.
  const std::string path = writeCsv (
      "bgt.csv",
      "bgt_type,polygon,x_min,y_max,x_max,y_min\n"
      "pand,\"[[119300.125, 485100.5], [119310.125, 485100.5], [119310.125, "
      "485105.5], [119300.125, 485105.5], [119300.125, 485100.5]]\",119300.125,"
      "485105.5,119310.125,485100.5\n"
      "\n"
      "pand,\"[[0, 0], [0, 3], [4, 3], [4, 0], [0, 0]]\",0,3,4,0\n");
  const auto fp = load (path);
  ASSERT_EQ (fp.size(), 2u);
  EXPECT_EQ (fp[0].id, "2");
  EXPECT_EQ (fp[0].line, 2u);
  ASSERT_EQ (fp[0].polygons.size(), 1u);
  EXPECT_EQ (fp[0].polygons[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].outer), 50.0);
  EXPECT_EQ (fp[0].polygons[0].outer[0], Eigen::Vector2d (119300.125, 485100.5));
  // Given clockwise, stored counter-clockwise; the blank line is skipped.
  EXPECT_EQ (fp[1].id, "4");
  EXPECT_DOUBLE_EQ (signedArea (fp[1].polygons[0].outer), 12.0);
  // loadFootprints tells the table by its extension.
  std::vector<Footprint> by_name;
  pcl_ext::io::loadFootprints (path, by_name);
  EXPECT_EQ (by_name.size(), 2u);
}

TEST (FootprintsCsv, WktColumnWithIdsQuotesAndSemicolons)
{
  // A QGIS-style export: a byte order mark, ';' as delimiter, the geometry column named
  // WKT in capitals, an id column, a quoted name holding the delimiter, a doubled quote
  // and a line break, an EWKT prefix, a polygon with a hole and a multipolygon.
  const std::string path = writeCsv (
      "qgis.csv",
      "\xEF\xBB\xBF"
      "WKT;fid;name\n"
      "\"SRID=28992;POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (4 4, 4 6, 6 6, 6 4, 4 "
      "4))\";"
      "17;\"Town \"\"hall\"\";\nwest wing\"\n"
      "MULTIPOLYGON(((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)));;plain\n");
  const auto fp = load (path);
  ASSERT_EQ (fp.size(), 2u);
  EXPECT_EQ (fp[0].id, "17");
  EXPECT_EQ (fp[0].line, 2u);
  ASSERT_EQ (fp[0].polygons.size(), 1u);
  ASSERT_EQ (fp[0].polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].outer), 100.0);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].holes[0]), -4.0);
  // The quoted line break belongs to record 2: record 3 starts on line 4. Its id is
  // empty, so the line number stands in.
  EXPECT_EQ (fp[1].id, "4");
  EXPECT_EQ (fp[1].line, 4u);
  EXPECT_EQ (fp[1].polygons.size(), 2u);
}

TEST (FootprintsCsv, JsonPolygonsWithHolesAndMultipolygons)
{
  const std::string path = writeCsv (
      "rings.csv",
      "id\tgeometry\n"
      "a\t[[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], [[4, 4], [6, 4], [6, "
      "6], [4, 6], [4, 4]]]\n"
      "b\t[[[[0, 0], [1, 0], [1, 1], [0, 0]]], [[[5, 5], [6, 5], [6, 6], [5, "
      "5]]]]\n"
      "c\t\n");
  const auto fp = load (path);
  ASSERT_EQ (fp.size(), 2u); // c has no geometry: skipped
  EXPECT_EQ (fp[0].id, "a");
  ASSERT_EQ (fp[0].polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].holes[0]), -4.0);
  EXPECT_EQ (fp[1].id, "b");
  EXPECT_EQ (fp[1].polygons.size(), 2u);
}

TEST (FootprintsCsv, MalformedTablesAreReadErrorsNamingTheLine)
{
  std::vector<Footprint> fp (1);
  fp[0].id = "previous";
  const auto expect = [&] (const std::string& name,
                           const std::string& text,
                           std::size_t line,
                           const std::string& fragment) {
    const std::string path = writeCsv (name, text);
    expectReadError ([&] { loadCsvFootprints (path, fp); }, path, line, fragment);
  };
  expect ("no_geometry.csv", "id,x,y\n1,2,3\n", 1, "no geometry column");
  expect (
      "fields.csv",
      "id,wkt\na,\"POLYGON((0 0, 1 0, 1 1, 0 0))\"\nb,POLYGON((0 0,1 0,1 1,0 0)),x\n",
      3,
      "6 fields, the header has 2");
  expect ("unclosed_quote.csv", "id,wkt\na,\"POLYGON((0 0, 1 0\n", 2, "not closed");
  expect ("after_quote.csv",
          "id,wkt\na,\"POLYGON((0 0, 1 0, 1 1, 0 0))\"x\n",
          2,
          "after the closing quote");
  expect (
      "open_ring.csv", "id,polygon\na,\"[[0, 0], [1, 0], [1, 1]]\"\n", 2, "not closed");
  expect ("not_numbers.csv",
          "id,polygon\na,\"[[0, 0], [\"\"x\"\", 0], [1, 1], [0, 0]]\"\n",
          2,
          "not [x, y] numbers");
  expect ("json_syntax.csv", "id,polygon\na,\"[[0, 0], [1, 0\"\n", 2, "parse");
  expect ("point.csv", "id,wkt\na,POINT(1 2)\n", 2, "");
  expect ("only_header.csv", "id,wkt\n", 0, "no polygons");
  expect ("empty.csv", "", 0, "empty file");
  const std::string absent = writeCsv ("x.csv", "") + ".absent";
  expectReadError ([&] { loadCsvFootprints (absent, fp); }, absent, 0, "no such file");
  ASSERT_EQ (fp.size(), 1u);
  EXPECT_EQ (fp[0].id, "previous"); // untouched by every failed read
}
