/*
 * Saving and loading synthetic scenes: determinism of the bytes and the side files.
 */
#include <pcl_ext/simulation/scene_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace pcl_ext;
using namespace pcl_ext::simulation;
namespace fs = std::filesystem;

namespace {
std::string
readBytes (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

struct TempDir {
  fs::path path;
  TempDir()
  {
    path = fs::temp_directory_path() / ("pcl_ext_sim_" + std::to_string (::getpid()));
    fs::create_directories (path);
  }
  ~TempDir() { fs::remove_all (path); }
  std::string
  file (const std::string& name) const
  {
    return (path / name).string();
  }
};
} // namespace

TEST (SceneIo, DeterministicBytesForASeedAndAnyThreadCount)
{
  TempDir dir;
  SceneParameters parameters;
  parameters.seed = 7;
  parameters.points = 30000;
  parameters.threads = 1;
  for (const std::string name : {"street", "tree", "pipes"}) {
    SyntheticScene a, b, c;
    ASSERT_TRUE (generateScene (name, parameters, a));
    parameters.threads = 2;
    ASSERT_TRUE (generateScene (name, parameters, b));
    parameters.threads = 1;
    parameters.seed = 8;
    ASSERT_TRUE (generateScene (name, parameters, c));
    parameters.seed = 7;
    ASSERT_TRUE (saveScene (dir.file (name + "_a.pcd"), a));
    ASSERT_TRUE (saveScene (dir.file (name + "_b.pcd"), b));
    ASSERT_TRUE (saveScene (dir.file (name + "_c.pcd"), c));
    const std::string bytes = readBytes (dir.file (name + "_a.pcd"));
    EXPECT_GT (bytes.size(), 100000u);
    EXPECT_EQ (bytes, readBytes (dir.file (name + "_b.pcd"))) << name;
    EXPECT_NE (bytes, readBytes (dir.file (name + "_c.pcd"))) << name;
  }
}

TEST (SceneIo, FieldsAndRoundTrip)
{
  TempDir dir;
  SceneParameters parameters;
  parameters.points = 20000;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("indoor", parameters, scene));
  const std::string path = dir.file ("indoor.pcd");
  ASSERT_TRUE (saveScene (path, scene));
  pcl::PCLPointCloud2 blob;
  sceneToPointCloud2 (scene, blob);
  std::vector<std::string> names;
  for (const auto& f : blob.fields)
    names.push_back (f.name);
  EXPECT_EQ (
      names,
      (std::vector<std::string>{
          "x", "y", "z", "rgb", "intensity", "segment", "object", "class", "label"}));
  pcl::PointCloud<SimulatedPoint> loaded;
  ASSERT_TRUE (loadScene (path, loaded));
  ASSERT_EQ (loaded.size(), scene.cloud.size());
  for (std::size_t i = 0; i < loaded.size(); i += 97) {
    EXPECT_EQ (loaded[i].x, scene.cloud[i].x);
    EXPECT_EQ (loaded[i].rgba, scene.cloud[i].rgba);
    EXPECT_EQ (loaded[i].segment, scene.cloud[i].segment);
    EXPECT_EQ (loaded[i].object, scene.cloud[i].object);
    EXPECT_EQ (loaded[i].point_class, scene.cloud[i].point_class);
    EXPECT_EQ (loaded[i].label, scene.cloud[i].label);
  }

  // Scenes without colour have only x y z segment object class.
  SyntheticScene cubes;
  ASSERT_TRUE (generateScene ("cubes", parameters, cubes));
  sceneToPointCloud2 (cubes, blob);
  names.clear();
  for (const auto& f : blob.fields)
    names.push_back (f.name);
  EXPECT_EQ (names,
             (std::vector<std::string>{"x", "y", "z", "segment", "object", "class"}));
  EXPECT_FALSE (fs::exists (dir.file ("cubes.footprint.wkt")));
}

TEST (SceneIo, BuildingSideFiles)
{
  TempDir dir;
  SceneParameters parameters;
  parameters.points = 20000;
  parameters.offset = Vec3 (1000, 2000, 0);
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("building", parameters, scene));
  const std::string path = dir.file ("b.pcd");
  ASSERT_TRUE (saveScene (path, scene));
  const std::string wkt = readBytes (dir.file ("b.footprint.wkt"));
  EXPECT_EQ (wkt.rfind ("POLYGON((1000.000000 2000.000000, 1012.000000 2000.000000", 0),
             0u)
      << wkt;
  EXPECT_NE (wkt.find ("1000.000000 2000.000000))"), std::string::npos); // closed ring
  std::istringstream text (readBytes (dir.file ("b.transform.txt")));
  Eigen::Matrix4d T;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      ASSERT_TRUE (text >> T (r, c));
  EXPECT_TRUE (T.isApprox (scene.scan_to_map, 1e-15));
}

TEST (SceneIo, UnwritableAndMissingFiles)
{
  SceneParameters parameters;
  parameters.points = 5000;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("cubes", parameters, scene));
  EXPECT_FALSE (saveScene ("/nonexistent_folder/x.pcd", scene));
  pcl::PointCloud<SimulatedPoint> cloud;
  EXPECT_FALSE (loadScene ("/nonexistent_folder/x.pcd", cloud));
  EXPECT_TRUE (cloud.empty());
}
