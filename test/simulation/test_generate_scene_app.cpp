/*
 * The pcl_ext_generate_scene command line: outputs, help and bad usage.
 */
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
int
run (const std::string& arguments)
{
  const std::string command =
      std::string (GENERATE_SCENE_EXE) + " " + arguments + " > /dev/null 2>&1";
  const int status = std::system (command.c_str());
  return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
}

fs::path
tempDir ()
{
  const fs::path dir =
      fs::temp_directory_path() / ("pcl_ext_gen_" + std::to_string (::getpid()));
  fs::create_directories (dir);
  return dir;
}
} // namespace

TEST (GenerateSceneApp, WritesTheSceneAndSideFiles)
{
  const fs::path dir = tempDir();
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_EQ (run ("building " + (dir / "b.pcd").string() +
                  " -points 20000 -noise 0.2 -superfluous 2"),
             0);
  EXPECT_TRUE (fs::exists (dir / "b.pcd"));
  EXPECT_TRUE (fs::exists (dir / "b.footprint.wkt"));
  EXPECT_TRUE (fs::exists (dir / "b.transform.txt"));
  EXPECT_EQ (run ("cubes " + (dir / "c.pcd").string() +
                  " -seed 3 -step 0.5 -offset 100,200,0"),
             0);
  EXPECT_TRUE (fs::exists (dir / "c.pcd"));
  fs::remove_all (dir);
}

TEST (GenerateSceneApp, FootprintFromWktOrAFootprintFile)
{
  const fs::path dir = tempDir();
  const auto footprintOf = [&] (const std::string& stem) {
    std::ifstream in (dir / (stem + ".footprint.wkt"));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  // A 30 x 20 m box, inline as WKT and as a file in the text format: the same walls.
  EXPECT_EQ (run ("building " + (dir / "a.pcd").string() +
                  " -points 20000 -footprint 'POLYGON((0 0, 30 0, 30 20, 0 20, 0 0))'"),
             0);
  std::ofstream (dir / "box.txt") << "box 5 0 0 30 0 30 20 0 20 0 0\n";
  EXPECT_EQ (run ("building " + (dir / "b.pcd").string() +
                  " -points 20000 -footprint " + (dir / "box.txt").string()),
             0);
  EXPECT_NE (footprintOf ("a").find ("30"), std::string::npos);
  EXPECT_EQ (footprintOf ("a"), footprintOf ("b"));
  // Refused, as the footprint readers refuse them: an unclosed ring, two parts, a hole.
  const std::string out = (dir / "x.pcd").string();
  EXPECT_NE (
      run ("building " + out + " -footprint 'POLYGON((0 0, 30 0, 30 20, 0 20))'"), 0);
  EXPECT_NE (run ("building " + out +
                  " -footprint 'MULTIPOLYGON(((0 0, 9 0, 9 9, 0 0)), "
                  "((20 0, 29 0, 29 9, 20 0)))'"),
             0);
  EXPECT_NE (run ("building " + out +
                  " -footprint 'POLYGON((0 0, 30 0, 30 20, 0 20, 0 0), "
                  "(5 5, 6 5, 6 6, 5 5))'"),
             0);
  EXPECT_FALSE (fs::exists (out));
  fs::remove_all (dir);
}

TEST (GenerateSceneApp, BadUsageFailsWithoutOutput)
{
  const fs::path dir = tempDir();
  const std::string out = (dir / "x.pcd").string();
  EXPECT_NE (run (""), 0);
  EXPECT_NE (run ("no_such_scene " + out), 0);
  EXPECT_NE (run ("cubes " + out + " -noise -1"), 0);
  EXPECT_NE (run ("cubes " + out + " -noise nan"), 0);
  EXPECT_NE (run ("cubes " + out + " -points 0"), 0);
  EXPECT_NE (run ("cubes " + out + " -step 0"), 0);
  EXPECT_NE (run ("cubes " + out + " -offset 1,2"), 0);
  EXPECT_NE (run ("cubes " + out + " -unknown 3"), 0);
  EXPECT_NE (run ("building " + out + " -footprint 'POLYGON((0 0, 1 0))'"), 0);
  EXPECT_FALSE (fs::exists (out));
  fs::remove_all (dir);
}
