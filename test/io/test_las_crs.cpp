/*
 * lasCoordinateSystem: the CRS of LAS files written by different programs (WKT 1 and
 * 2, GeoTIFF keys), compared by the EPSG code of the outermost CRS where there is one.
 */
#include <pcl_ext/io/las_crs.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {
using pcl_ext::io::LasCoordinateSystem;
using pcl_ext::io::LasFileInfo;

LasFileInfo
withWkt (const std::string& wkt, bool extended = false)
{
  LasFileInfo info;
  std::vector<std::uint8_t> data (wkt.begin(), wkt.end());
  data.push_back (0);
  data.push_back (0);
  (extended ? info.evlrs : info.vlrs)
      .push_back ({0, "LASF_Projection", 2112, "OGC WKT", data, extended});
  return info;
}

/** A GeoTIFF key directory of (key, value) SHORT keys held in the directory. */
LasFileInfo
withGeoKeys (const std::vector<std::pair<std::uint16_t, std::uint16_t>>& keys)
{
  std::vector<std::uint16_t> words{1, 1, 0, static_cast<std::uint16_t> (keys.size())};
  for (const auto& [key, value] : keys)
    words.insert (words.end(), {key, 0, 1, value});
  std::vector<std::uint8_t> data (2 * words.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    data[2 * i] = static_cast<std::uint8_t> (words[i] & 0xFF);
    data[2 * i + 1] = static_cast<std::uint8_t> (words[i] >> 8);
  }
  LasFileInfo info;
  info.vlrs.push_back (
      {0, "LASF_Projection", 34735, "GeoTIFF GeoKeyDirectoryTag", data});
  return info;
}

const std::string kRdNewWkt1 =
    "PROJCS[\"Amersfoort / RD New\",GEOGCS[\"Amersfoort\",DATUM[\"Amersfoort\","
    "SPHEROID[\"Bessel 1841\",6377397.155,299.1528128,AUTHORITY[\"EPSG\",\"7004\"]],"
    "AUTHORITY[\"EPSG\",\"6289\"]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\","
    "0.0174532925199433],AUTHORITY[\"EPSG\",\"4289\"]],PROJECTION[\"Oblique_"
    "Stereographic\"],PARAMETER[\"latitude_of_origin\",52.1561605555556],UNIT["
    "\"metre\","
    "1,AUTHORITY[\"EPSG\",\"9001\"]],AUTHORITY[\"EPSG\",\"28992\"]]";
} // namespace

TEST (LasCoordinateSystem, TheOutermostAuthorityOfAWktIsItsCode)
{
  const auto crs = pcl_ext::io::lasCoordinateSystem (withWkt (kRdNewWkt1));
  EXPECT_EQ (crs.kind, LasCoordinateSystem::Kind::Epsg);
  EXPECT_EQ (crs.value, "28992"); // not the datum's, ellipsoid's or unit's
  EXPECT_EQ (crs.describe(), "EPSG:28992");
  // WKT 2 names it ID[...], unquoted; an EVLR holds it as well as a VLR.
  const auto wkt2 = pcl_ext::io::lasCoordinateSystem (withWkt (
      "PROJCRS[\"Amersfoort / RD New\",BASEGEOGCRS[\"Amersfoort\",ID[\"EPSG\",4289]],\n"
      "  CONVERSION[\"RD New\",ID[\"EPSG\",19914]],\n  ID[\"EPSG\",28992]]",
      true));
  EXPECT_EQ (wkt2, crs);
  // A compound CRS: its own code, not its horizontal part's.
  const auto compound = pcl_ext::io::lasCoordinateSystem (
      withWkt ("COMPD_CS[\"Amersfoort / RD New + NAP height\"," + kRdNewWkt1 +
               ",VERT_CS[\"NAP height\",AUTHORITY[\"EPSG\",\"5709\"]],"
               "AUTHORITY[\"EPSG\",\"7415\"]]"));
  EXPECT_EQ (compound.value, "7415");
  EXPECT_NE (compound, crs);
}

TEST (LasCoordinateSystem, GeoTiffKeysAndWktOfOneCodeAreTheSame)
{
  const auto wkt = pcl_ext::io::lasCoordinateSystem (withWkt (kRdNewWkt1));
  const auto keys = pcl_ext::io::lasCoordinateSystem (
      withGeoKeys ({{1024, 1}, {3072, 28992}, {3076, 9001}}));
  EXPECT_EQ (keys, wkt);
  const auto utm = pcl_ext::io::lasCoordinateSystem (withGeoKeys ({{3072, 32631}}));
  EXPECT_EQ (utm.value, "32631");
  EXPECT_NE (utm, wkt);
  // Geographic only: its GeographicTypeGeoKey.
  EXPECT_EQ (pcl_ext::io::lasCoordinateSystem (withGeoKeys ({{2048, 4326}})).value,
             "4326");
}

TEST (LasCoordinateSystem, WithoutACodeTheNamesAreCompared)
{
  using pcl_ext::io::CrsMatch;
  using pcl_ext::io::lasCoordinateSystem;
  using pcl_ext::io::matchCoordinateSystems;
  // One CRS as two versions of one program wrote it (the datum's name and the
  // flattening spelt differently), without an authority: the same name.
  const std::string lcc =
      "PROJCS[\"NAD_1983_HARN_Lambert_Conformal_Conic\",GEOGCS[\"GCS_"
      "North_American_1983_HARN\",DATUM[\"NAD83_High_Accuracy_";
  const auto a = lasCoordinateSystem (withWkt (
      lcc + "Reference_Network\",SPHEROID[\"GRS 1980\",6378137,298.2572221010002]]]]"));
  const auto b = lasCoordinateSystem (withWkt (
      lcc + "Regional_Network\",\n SPHEROID[\"GRS_1980\",6378137,298.257222101]]]]"));
  EXPECT_EQ (a.kind, LasCoordinateSystem::Kind::Wkt);
  EXPECT_EQ (a.value, "NAD_1983_HARN_Lambert_Conformal_Conic");
  EXPECT_EQ (a.describe(), "the CRS named \"NAD_1983_HARN_Lambert_Conformal_Conic\"");
  EXPECT_EQ (matchCoordinateSystems (a, b), CrsMatch::Same);
  // Two names: two CRSs (a name's own spaces count).
  const auto grid =
      lasCoordinateSystem (withWkt ("LOCAL_CS[\"site grid\",UNIT[\"m\",1]]"));
  const auto other =
      lasCoordinateSystem (withWkt ("LOCAL_CS[\"sitegrid\",UNIT[\"m\",1]]"));
  EXPECT_EQ (matchCoordinateSystems (grid, other), CrsMatch::Different);
  // An EPSG code and a WKT without one cannot be compared; nor can no CRS.
  const auto rd = lasCoordinateSystem (withWkt (kRdNewWkt1));
  EXPECT_EQ (matchCoordinateSystems (rd, a), CrsMatch::Unknown);
  EXPECT_EQ (matchCoordinateSystems (rd, LasCoordinateSystem()), CrsMatch::Unknown);
  EXPECT_EQ (matchCoordinateSystems (rd, rd), CrsMatch::Same);
  EXPECT_EQ (
      matchCoordinateSystems (rd, lasCoordinateSystem (withGeoKeys ({{3072, 32631}}))),
      CrsMatch::Different);
  // User-defined GeoTIFF keys: the same records are the same CRS; other records may
  // spell the same one otherwise.
  const auto user = lasCoordinateSystem (withGeoKeys ({{3072, 32767}}));
  EXPECT_EQ (user.kind, LasCoordinateSystem::Kind::GeoTiff);
  EXPECT_EQ (matchCoordinateSystems (
                 user, lasCoordinateSystem (withGeoKeys ({{3072, 32767}}))),
             CrsMatch::Same);
  EXPECT_EQ (
      matchCoordinateSystems (
          user, lasCoordinateSystem (withGeoKeys ({{3072, 32767}, {3076, 9001}}))),
      CrsMatch::Unknown);
}

TEST (LasCoordinateSystem, NoRecordsOrBrokenOnesDeclareNone)
{
  EXPECT_FALSE (pcl_ext::io::lasCoordinateSystem (LasFileInfo()).declared());
  EXPECT_EQ (pcl_ext::io::lasCoordinateSystem (LasFileInfo()).describe(), "no CRS");
  LasFileInfo short_directory;
  short_directory.vlrs.push_back ({0, "LASF_Projection", 34735, "", {1, 0, 1}});
  EXPECT_FALSE (pcl_ext::io::lasCoordinateSystem (short_directory).declared());
  // A directory that claims more keys than it holds reads the ones it holds.
  LasFileInfo lying = withGeoKeys ({{3072, 28992}});
  lying.vlrs[0].data[6] = 200;
  EXPECT_EQ (pcl_ext::io::lasCoordinateSystem (lying).value, "28992");
  // An empty WKT record falls back to the keys.
  LasFileInfo both = withGeoKeys ({{3072, 28992}});
  both.vlrs.push_back ({0, "LASF_Projection", 2112, "", {0}});
  EXPECT_EQ (pcl_ext::io::lasCoordinateSystem (both).value, "28992");
  // Another user's record 2112 is not a CRS.
  LasFileInfo other;
  other.vlrs.push_back ({0, "someone", 2112, "", {'X', 0}});
  EXPECT_FALSE (pcl_ext::io::lasCoordinateSystem (other).declared());
}

TEST (LasCoordinateSystem, TextsGiveCodesWktOrThemselves)
{
  // What an E57 file's coordinateMetadata holds: an EPSG reference, a WKT, or prose.
  using pcl_ext::io::CrsMatch;
  using pcl_ext::io::textCoordinateSystem;
  using Kind = LasCoordinateSystem::Kind;
  EXPECT_EQ (textCoordinateSystem ("").kind, Kind::None);
  EXPECT_EQ (textCoordinateSystem ("  \n").kind, Kind::None);
  const LasCoordinateSystem code = textCoordinateSystem ("EPSG:28992");
  EXPECT_EQ (code.kind, Kind::Epsg);
  EXPECT_EQ (code.value, "28992");
  EXPECT_EQ (textCoordinateSystem (" urn:ogc:def:crs:EPSG::28992 "), code);
  EXPECT_EQ (textCoordinateSystem (kRdNewWkt1), code);
  EXPECT_EQ (pcl_ext::io::matchCoordinateSystems (
                 code, pcl_ext::io::lasCoordinateSystem (withWkt (kRdNewWkt1))),
             CrsMatch::Same);
  EXPECT_EQ (
      pcl_ext::io::matchCoordinateSystems (code, textCoordinateSystem ("EPSG:32631")),
      CrsMatch::Different);
  const LasCoordinateSystem named =
      textCoordinateSystem ("PROJCS[\"Local grid\",GEOGCS[\"WGS 84\"]]");
  EXPECT_EQ (named.kind, Kind::Wkt);
  EXPECT_EQ (named.value, "Local grid");
  // Prose is compared as it is written: the same text is one CRS, another cannot be
  // told apart from it.
  const LasCoordinateSystem prose = textCoordinateSystem ("UTM zone 31N, NAP heights");
  EXPECT_EQ (prose.kind, Kind::Text);
  EXPECT_NE (prose.describe().find ("UTM zone 31N"), std::string::npos);
  EXPECT_EQ (pcl_ext::io::matchCoordinateSystems (prose, prose), CrsMatch::Same);
  EXPECT_EQ (pcl_ext::io::matchCoordinateSystems (
                 prose, textCoordinateSystem ("WGS 84 / UTM 31N")),
             CrsMatch::Unknown);
  EXPECT_EQ (pcl_ext::io::matchCoordinateSystems (prose, code), CrsMatch::Unknown);
  EXPECT_EQ (textCoordinateSystem ("EPSG:").kind, Kind::Text);
}
