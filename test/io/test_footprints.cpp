/*
 * Footprint polygons: WKT, GeoJSON and the plain text format, including malformed
 * input.
 */
#include <pcl_ext/io/footprints.h>

#include "test_helpers.h"

using pcl_ext::io::Footprint;
using pcl_ext::io::signedArea;

namespace {
double
area (const pcl_ext::io::FootprintPolygon& p)
{
  double a = signedArea (p.outer);
  for (const auto& h : p.holes)
    a += signedArea (h);
  return a;
}
} // namespace

TEST (Footprints, ParseWktNormalisesOrientation)
{
  Footprint f;
  // Clockwise outer ring in the text: stored counter-clockwise and open.
  pcl_ext::io::parseWkt ("POLYGON((0 0, 0 4, 3 4, 3 0, 0 0))", f);
  ASSERT_EQ (f.polygons.size(), 1u);
  EXPECT_EQ (f.polygons[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ (signedArea (f.polygons[0].outer), 12.0);
  // Repeated vertices are dropped.
  pcl_ext::io::parseWkt ("POLYGON((0 0, 3 0, 3 0, 3 4, 0 4, 0 0))", f);
  EXPECT_EQ (f.polygons[0].outer.size(), 4u);
  EXPECT_THROW (pcl_ext::io::parseWkt ("POINT(1 2)", f), pcl_ext::io::ReadError);
  EXPECT_THROW (pcl_ext::io::parseWkt ("POLYGON((0 0, 1 1, 0 0))", f),
                pcl_ext::io::ReadError);
}

TEST (Footprints, WktFile)
{
  std::vector<Footprint> fp;
  pcl_ext::io::loadWktFootprints (fixture ("footprints.wkt"), fp);
  ASSERT_EQ (fp.size(), 3u);
  EXPECT_EQ (fp[0].id, "house_a");
  EXPECT_EQ (fp[0].line, 2u);
  ASSERT_EQ (fp[0].polygons.size(), 1u);
  ASSERT_EQ (fp[0].polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].outer), 100.0);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].holes[0]), -4.0); // holes clockwise
  EXPECT_DOUBLE_EQ (area (fp[0].polygons[0]), 96.0);
  EXPECT_EQ (fp[1].id, "house_b");
  ASSERT_EQ (fp[1].polygons.size(), 2u);
  EXPECT_DOUBLE_EQ (signedArea (fp[1].polygons[1].outer), 12.5);
  // A Z polygon keeps x, y in full double precision; it has no id, so its line is its
  // id.
  EXPECT_EQ (fp[2].id, "4");
  EXPECT_EQ (fp[2].polygons[0].outer[0], Eigen::Vector2d (119300.0, 485100.0));
  EXPECT_DOUBLE_EQ (signedArea (fp[2].polygons[0].outer), 50.0);
}

TEST (Footprints, WktErrors)
{
  std::vector<Footprint> fp;
  pcl_ext::io::loadWktFootprints (fixture ("footprints.wkt"), fp);
  std::string p = fixture ("footprint_unclosed.wkt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 2, "is not closed");
  p = fixture ("footprint_bowtie.wkt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 1, "not a valid polygon");
  p = fixture ("footprint_syntax.wkt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 3, "WKT syntax error");
  p = fixture ("points_bad_number.txt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 1, "expected a WKT POLYGON");
  p = fixture ("empty.txt");
  expectReadError ([&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 0, "empty file");
  p = fixture ("nothing_here.wkt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 0, "no such file");
  EXPECT_EQ (fp.size(), 3u); // untouched by the failures
}

TEST (Footprints, GeoJsonFile)
{
  std::vector<Footprint> fp;
  pcl_ext::io::loadGeoJsonFootprints (fixture ("footprints.geojson"), fp);
  ASSERT_EQ (fp.size(), 2u); // the null geometry is skipped
  EXPECT_EQ (fp[0].id, "pand.1");
  EXPECT_EQ (fp[0].line, 4u);
  ASSERT_EQ (fp[0].polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].outer), 100.0);
  EXPECT_DOUBLE_EQ (area (fp[0].polygons[0]), 98.0);
  EXPECT_EQ (fp[0].polygons[0].outer[0].x(), 119300.0);
  EXPECT_EQ (fp[1].id, "42");
  ASSERT_EQ (fp[1].polygons.size(), 2u);
  EXPECT_DOUBLE_EQ (signedArea (fp[1].polygons[0].outer), 6.0);
  EXPECT_DOUBLE_EQ (signedArea (fp[1].polygons[1].outer), 4.0);

  // Dispatch by extension and by content agree.
  std::vector<Footprint> by_name;
  pcl_ext::io::loadFootprints (fixture ("footprints.geojson"), by_name);
  EXPECT_EQ (by_name.size(), 2u);
}

TEST (Footprints, GeoJsonErrors)
{
  std::vector<Footprint> fp;
  std::string p = fixture ("footprint_syntax.geojson");
  expectReadError (
      [&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); }, p, 5, "JSON syntax error");
  p = fixture ("footprint_unclosed.geojson");
  expectReadError ([&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); },
                   p,
                   4,
                   "feature 1: polygon outer ring is not closed");
  p = fixture ("footprint_linestring.geojson");
  expectReadError ([&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); },
                   p,
                   1,
                   "\"LineString\" is not Polygon");
  p = fixture ("empty.txt");
  expectReadError (
      [&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); }, p, 0, "empty file");
  p = fixture ("absent.geojson");
  expectReadError (
      [&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); }, p, 0, "no such file");
  EXPECT_TRUE (fp.empty());
}

TEST (Footprints, TextFormat)
{
  std::vector<Footprint> fp;
  pcl_ext::io::loadTextFootprints (fixture ("footprints_local.txt"), fp);
  ASSERT_EQ (fp.size(), 2u);
  EXPECT_EQ (fp[0].id, "0");
  EXPECT_EQ (fp[1].id, "7");
  EXPECT_EQ (fp[1].line, 3u);
  EXPECT_EQ (fp[0].polygons[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ (signedArea (fp[0].polygons[0].outer), 100.0);
  EXPECT_DOUBLE_EQ (signedArea (fp[1].polygons[0].outer), 0.5 * 4.5 * 4.0);

  pcl_ext::io::translateFootprints (fp, Eigen::Vector2d (100.0, -5.0));
  EXPECT_EQ (fp[0].polygons[0].outer[0], Eigen::Vector2d (100.0, -5.0));

  std::string p = fixture ("footprint_bad_count.txt");
  expectReadError ([&] { pcl_ext::io::loadTextFootprints (p, fp); },
                   p,
                   2,
                   "expected 10 coordinates for 5 vertices, found 8");
  p = fixture ("footprint_unclosed.txt");
  expectReadError (
      [&] { pcl_ext::io::loadTextFootprints (p, fp); }, p, 1, "is not closed");
  p = fixture ("points_bad_number.txt"); // "7 8 nine": 8 vertices announced
  expectReadError (
      [&] { pcl_ext::io::loadTextFootprints (p, fp); }, p, 1, "expected 4 coordinates");
  p = fixture ("comments_only.txt");
  expectReadError (
      [&] { pcl_ext::io::loadTextFootprints (p, fp); }, p, 0, "no polygons");
  EXPECT_EQ (fp.size(), 2u);
}

TEST (Footprints, HugeCoordinatesAndNumberOverflowAreReadErrors)
{
  // Boost.Geometry's validity check throws boost::numeric::positive_overflow on a
  // coordinate of 1e49, and nlohmann/json an out_of_range on 1e15500123: the readers
  // must turn both into a ReadError (the crash_* seeds of the footprint fuzz corpora
  // are inputs of this kind).
  std::vector<pcl_ext::io::Footprint> fp (1);
  std::string p = fixture ("footprint_huge_coordinate.wkt");
  expectReadError (
      [&] { pcl_ext::io::loadWktFootprints (p, fp); }, p, 1, "beyond 1e9 m");
  p = fixture ("footprint_huge_coordinate.txt");
  expectReadError (
      [&] { pcl_ext::io::loadTextFootprints (p, fp); }, p, 1, "beyond 1e9 m");
  p = fixture ("footprint_number_overflow.geojson");
  expectReadError (
      [&] { pcl_ext::io::loadGeoJsonFootprints (p, fp); }, p, 0, "JSON error");
  EXPECT_EQ (fp.size(), 1u);
  // Just inside the bound is fine.
  pcl_ext::io::Footprint f;
  EXPECT_NO_THROW (
      pcl_ext::io::parseWkt ("POLYGON((0 0, 999999999 0, 999999999 1, 0 0))", f));
}
