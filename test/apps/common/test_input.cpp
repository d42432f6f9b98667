/*
 * Tests of loadInput: an app's input cloud as the file has it and as x, y, z, with the
 * timing line, and the errors of pcl_ext::io::loadPointFile.
 */
#include <pcl_ext/apps/input.h>

#include <pcl/io/pcd_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace {
std::string
temporaryPath (const std::string& name)
{
  return testing::TempDir() + "/" + std::to_string (::getpid()) + "_" + name;
}
} // namespace

TEST (Input, LoadsEveryFieldAndTheCoordinates)
{
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZI p;
    p.x = static_cast<float> (i);
    p.y = 2.f * i;
    p.z = 3.f;
    p.intensity = 0.5f * i;
    cloud.push_back (p);
  }
  const std::string path = temporaryPath ("input.pcd");
  ASSERT_EQ (pcl::io::savePCDFileASCII (path, cloud), 0);
  pcl_ext::io::PointFile input;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  testing::internal::CaptureStdout();
  ASSERT_TRUE (pcl_ext::apps::loadInput (path, input, xyz));
  const std::string printed = testing::internal::GetCapturedStdout();
  std::remove (path.c_str());
  // "Loading <path> [done, X ms : 3 points]"
  EXPECT_EQ (printed.rfind ("Loading " + path + " [done, ", 0), 0u) << printed;
  EXPECT_NE (printed.find (" ms : 3 points]"), std::string::npos) << printed;
  ASSERT_EQ (xyz.size(), 3u);
  EXPECT_EQ (xyz[2].x, 2.f);
  EXPECT_EQ (xyz[2].y, 4.f);
  EXPECT_EQ (xyz[2].z, 3.f);
  // The file's fields are kept for the output.
  EXPECT_EQ (input.cloud.width * input.cloud.height, 3u);
  EXPECT_TRUE (input.origin.isZero());
  bool has_intensity = false;
  for (const auto& f : input.cloud.fields)
    has_intensity = has_intensity || f.name == "intensity";
  EXPECT_TRUE (has_intensity);
}

TEST (Input, MissingFileAndFolderAreRefused)
{
  pcl_ext::io::PointFile input;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::apps::loadInput (temporaryPath ("missing.pcd"), input, xyz));
  EXPECT_FALSE (pcl_ext::apps::loadInput (testing::TempDir(), input, xyz));
  const std::string errors = testing::internal::GetCapturedStderr();
  testing::internal::GetCapturedStdout();
  EXPECT_NE (errors.find ("missing.pcd: no such file"), std::string::npos) << errors;
  EXPECT_NE (errors.find ("is a folder"), std::string::npos) << errors;
  EXPECT_TRUE (xyz.empty());
  EXPECT_TRUE (input.cloud.data.empty());
}
