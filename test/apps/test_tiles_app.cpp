/*
 * pcl_ext_tiles run as a command: a georeferenced scene classified tile by tile, in one
 * command, in steps and shared among MPI ranks, gives pcl_ext_classify_variance's
 * output point for point, for any tile size, order of the tiles and number of ranks;
 * bad input is refused without output.
 */
#include "../app_test.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {
/** The point records of a LAS file and its scale and offset bytes. */
struct LasContent {
  std::vector<char> scale_and_offset;
  std::vector<char> records;
};

LasContent
readLas (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  const std::vector<char> b ((std::istreambuf_iterator<char> (in)),
                             std::istreambuf_iterator<char>());
  LasContent c;
  if (b.size() < 375)
    return c;
  std::uint32_t offset;
  std::memcpy (&offset, &b[96], 4);
  c.scale_and_offset.assign (b.begin() + 131, b.begin() + 179);
  if (offset <= b.size())
    c.records.assign (b.begin() + offset, b.end());
  return c;
}

class TilesApp : public pcl_ext::test::AppTest {
protected:
  TilesApp() : AppTest (PCL_EXT_TILES_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // An indoor scan at UTM-like coordinates: the tiles must keep the input's frame.
    const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) +
                                 " indoor '" + path ("scene.pcd") +
                                 "' -points 60000 -seed 2 -offset 500000,6000000,100 "
                                 "> /dev/null 2>&1";
    ASSERT_EQ (std::system (generate.c_str()), 0);
    const std::string whole = std::string (PCL_EXT_CLASSIFY_VARIANCE_EXE) + " '" +
                              path ("scene.pcd") + "' '" + path ("whole.las") +
                              "' > /dev/null 2>&1";
    ASSERT_EQ (std::system (whole.c_str()), 0);
    whole_ = readLas (path ("whole.las"));
    ASSERT_FALSE (whole_.records.empty());
  }

  void
  expectSameAsWhole (const std::string& output)
  {
    const LasContent tiled = readLas (path (output));
    EXPECT_TRUE (tiled.scale_and_offset == whole_.scale_and_offset) << output;
    EXPECT_EQ (tiled.records.size(), whole_.records.size()) << output;
    EXPECT_TRUE (tiled.records == whole_.records) << output;
  }

  LasContent whole_;
};
} // namespace

TEST_F (TilesApp, AnyTileSizeGivesTheWholeCloudsClasses)
{
  ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("t3.las") +
                  " -tile_size 3 -threads 1"),
             0)
      << output_;
  EXPECT_NE (output_.find ("tiles ("), std::string::npos) << output_;
  EXPECT_NE (output_.find ("peak memory"), std::string::npos) << output_;
  expectSameAsWhole ("t3.las");
  ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("t7.las") +
                  " -tile_size 7 -halo 0.05"),
             0)
      << output_;
  expectSameAsWhole ("t7.las"); // a halo far too small: the tiles widen themselves
  EXPECT_FALSE (exists ("t7.las.tiles")); // the work folder is removed
}

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesApp, MpiRanksShareTheTilesAndGiveTheSameOutput)
{
  for (const int ranks : {2, 4}) {
    const std::string out = "mpi" + std::to_string (ranks) + ".las";
    const std::string command =
        std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " +
        std::to_string (ranks) + " " + PCL_EXT_TILES_EXE + " classify_variance '" +
        path ("scene.pcd") + "' '" + path (out) + "' -tile_size 3 -threads 1 > '" +
        path ("mpi.log") + "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0) << ranks << " ranks";
    std::ifstream log (path ("mpi.log"));
    const std::string text ((std::istreambuf_iterator<char> (log)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE (text.find ("Rank " + std::to_string (ranks - 1) + ": done"),
               std::string::npos)
        << text;
    expectSameAsWhole (out);
  }
}
#endif

TEST_F (TilesApp, StepsInAnyOrderGiveTheSameOutput)
{
  const std::string work = " -workdir " + path ("work");
  ASSERT_EQ (
      run ("plan classify_variance " + path ("scene.pcd") + work + " -tile_size 4"), 0)
      << output_;
  std::ifstream plan (path ("work/plan.txt"));
  ASSERT_TRUE (plan.good());
  std::size_t tiles = 0;
  while (exists ("work/tile_" + std::to_string (tiles) + ".points"))
    ++tiles;
  ASSERT_GT (tiles, 2u);
  ASSERT_EQ (run ("merge " + path ("early.las") + work), 1); // no tile has run
  EXPECT_NE (output_.find ("have not run"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("early.las"));
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("estimate " + std::to_string (t) + work), 0) << output_;
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("tile " + std::to_string (t) + work + " -threads 2"), 0) << output_;
  ASSERT_EQ (run ("merge " + path ("steps.las") + work), 0) << output_;
  expectSameAsWhole ("steps.las");
  EXPECT_EQ (run ("tile " + std::to_string (tiles) + work), 1); // no such tile
  EXPECT_EQ (run ("tile x" + work), 1);
}

TEST_F (TilesApp, BadUsageIsRefusedWithoutOutput)
{
  const std::string scene = path ("scene.pcd");
  EXPECT_EQ (run ("no_method " + scene + " " + path ("a.las")), 1);
  EXPECT_NE (output_.find ("unknown method"), std::string::npos) << output_;
  EXPECT_EQ (run ("classify_variance " + scene + " " + path ("a.laz")),
             1); // not written
  EXPECT_EQ (
      run ("classify_variance " + scene + " " + path ("a.las") + " -tile_size -2"), 1);
  EXPECT_EQ (run ("classify_variance " + scene + " " + path ("a.las") + " -k 2"), 1);
  EXPECT_EQ (run ("classify_variance " + path ("none.las") + " " + path ("a.las")), 1);
  EXPECT_EQ (run ("tile 0"), 1); // no work folder
  EXPECT_EQ (run ("tile 0 -workdir " + path ("nowhere")), 1);
  EXPECT_FALSE (exists ("a.las"));
  EXPECT_FALSE (exists ("a.laz"));
}
