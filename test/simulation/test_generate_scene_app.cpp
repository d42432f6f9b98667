/*
 * The pcl_ext_generate_scene command line: outputs, help and bad usage.
 */
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace
{
int
run (const std::string& arguments)
{
  const std::string command = std::string (GENERATE_SCENE_EXE) + " " + arguments + " > /dev/null 2>&1";
  const int status = std::system (command.c_str ());
  return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
}

fs::path
tempDir ()
{
  const fs::path dir = fs::temp_directory_path () / ("pcl_ext_gen_" + std::to_string (::getpid ()));
  fs::create_directories (dir);
  return dir;
}
}  // namespace

TEST (GenerateSceneApp, WritesTheSceneAndSideFiles)
{
  const fs::path dir = tempDir ();
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_EQ (run ("building " + (dir / "b.pcd").string () + " -points 20000 -noise 0.2 -superfluous 2"), 0);
  EXPECT_TRUE (fs::exists (dir / "b.pcd"));
  EXPECT_TRUE (fs::exists (dir / "b.footprint.wkt"));
  EXPECT_TRUE (fs::exists (dir / "b.transform.txt"));
  EXPECT_EQ (run ("cubes " + (dir / "c.pcd").string () + " -seed 3 -step 0.5 -offset 100,200,0"), 0);
  EXPECT_TRUE (fs::exists (dir / "c.pcd"));
  fs::remove_all (dir);
}

TEST (GenerateSceneApp, BadUsageFailsWithoutOutput)
{
  const fs::path dir = tempDir ();
  const std::string out = (dir / "x.pcd").string ();
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
