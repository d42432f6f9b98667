/*
 * pcl_ext_tiles run as a command on inputs that cannot go into one output: LAS files in
 * two coordinate reference systems are refused before any tile runs, and so is a tile
 * size far too small for the data.
 */
#include "../app_test.h"

#include <pcl_ext/io/point_file.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {
class TilesInputsApp : public pcl_ext::test::AppTest {
protected:
  TilesInputsApp() : AppTest (PCL_EXT_TILES_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // A small indoor scan at UTM-like coordinates.
    const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) +
                                 " indoor '" + path ("scene.pcd") +
                                 "' -points 20000 -seed 2 -offset 500000,6000000,100 "
                                 "> /dev/null 2>&1";
    ASSERT_EQ (std::system (generate.c_str()), 0);
  }
};
} // namespace

TEST_F (TilesInputsApp, InputsInDifferentCoordinateSystemsAreRefused)
{
  // The scene as two LAS files over the same ground, one declaring UTM 31N as WKT,
  // the other the Dutch national grid as GeoTIFF keys: refused before any tile runs,
  // without output. The same UTM as GeoTIFF keys goes with the WKT; a PCD (no CRS)
  // beside them is warned of.
  pcl_ext::io::PointFile file;
  pcl_ext::io::loadPointFile (path ("scene.pcd"), file);
  ASSERT_TRUE (
      pcl_ext::io::savePointFile (path ("plain.las"), file.cloud, file.origin));
  pcl_ext::io::loadPointFile (path ("plain.las"), file);
  ASSERT_TRUE (file.las.has_value());
  const auto saveWith = [&file, this] (const std::string& name,
                                       std::uint16_t record,
                                       const std::vector<std::uint8_t>& data) {
    pcl_ext::io::PointFile like = file;
    like.las->vlrs.push_back ({0, "LASF_Projection", record, "", data});
    return pcl_ext::io::savePointFile (path (name), file.cloud, file.origin, &like);
  };
  const std::string wkt =
      "PROJCS[\"WGS 84 / UTM zone 31N\",GEOGCS[\"WGS 84\","
      "AUTHORITY[\"EPSG\",\"4326\"]],AUTHORITY[\"EPSG\",\"32631\"]]";
  const auto keys = [] (std::uint16_t code) {
    // Directory 1.1.0 of one key, ProjectedCSTypeGeoKey (3072), little-endian.
    const std::uint16_t words[] = {1, 1, 0, 1, 3072, 0, 1, code};
    std::vector<std::uint8_t> data;
    for (const std::uint16_t w : words)
      data.insert (
          data.end(),
          {static_cast<std::uint8_t> (w & 0xFF), static_cast<std::uint8_t> (w >> 8)});
    return data;
  };
  ASSERT_TRUE (
      saveWith ("utm.las", 2112, std::vector<std::uint8_t> (wkt.begin(), wkt.end())));
  ASSERT_TRUE (saveWith ("rd.las", 34735, keys (28992)));
  ASSERT_TRUE (saveWith ("utm_keys.las", 34735, keys (32631)));
  EXPECT_EQ (run ("classify_variance " + path ("utm.las") + " " + path ("rd.las") +
                  " " + path ("out.las") + " -tile_size 4"),
             1);
  EXPECT_NE (output_.find ("declares EPSG:28992"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("different coordinate reference systems"), std::string::npos)
      << output_;
  EXPECT_FALSE (exists ("out.las"));
  const std::string work = " -workdir " + path ("work") + " -tile_size 4";
  ASSERT_EQ (run ("plan classify_variance " + path ("utm.las") + " " +
                  path ("utm_keys.las") + work),
             0)
      << output_;
  EXPECT_EQ (output_.find ("Warning"), std::string::npos) << output_;
  ASSERT_EQ (run ("plan classify_variance " + path ("utm.las") + " " +
                  path ("scene.pcd") + work),
             0)
      << output_;
  EXPECT_NE (output_.find ("declares no coordinate reference system"),
             std::string::npos)
      << output_;
}

TEST_F (TilesInputsApp, ATileSizeFarTooSmallIsRefused)
{
  // 20,000 points over a room of several metres in 2 cm tiles: more than a thousand
  // tiles would hold points, a few each. Refused with the reason, without output and
  // without a file per tile; with the tile size fitted to the data the run goes
  // through.
  EXPECT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("out.las") +
                  " -tile_size 0.02 -workdir " + path ("work")),
             1);
  EXPECT_NE (output_.find ("give a larger tile size"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("out.las"));
  EXPECT_FALSE (exists ("work/plan.txt"));
  EXPECT_FALSE (exists ("work/tile_0.points"));
  EXPECT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("out.las") +
                  " -workdir " + path ("work2")),
             0)
      << output_;
  EXPECT_TRUE (exists ("out.las"));
}
