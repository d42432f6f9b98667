/*
 * Tests of PCD and PLY loading and saving: round trips, refused inputs, atomic output.
 */
#include "temp_folder.h"

#include <pcl_ext/io/cloud_io.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

TEST (CloudIo, RoundTripAndMalformedInput)
{
  const std::string dir = freshFolder ("cloud_io");
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 10; ++i) {
    pcl::PointXYZI p;
    p.x = i;
    p.y = 2 * i;
    p.z = 6000000.0f;
    p.intensity = 0.5f * i;
    cloud.push_back (p);
  }
  for (const std::string ext : {"pcd", "ply"}) {
    const std::string path = dir + "/c." + ext;
    ASSERT_TRUE (pcl_ext::io::saveCloud (path, cloud));
    pcl::PointCloud<pcl::PointXYZI> back;
    ASSERT_TRUE (pcl_ext::io::loadCloud (path, back));
    ASSERT_EQ (back.size(), cloud.size());
    EXPECT_EQ (back[7].y, 14.0f);
    EXPECT_EQ (back[7].intensity, 3.5f);
    std::remove (path.c_str());
  }
  testing::internal::CaptureStderr();
  pcl::PCLPointCloud2 blob;
  EXPECT_FALSE (pcl_ext::io::loadCloud (dir + "/missing.pcd", blob));
  const std::string garbage = dir + "/garbage.pcd";
  std::ofstream (garbage) << "VERSION .7\nFIELDS x y z\nSIZE 4 4\nnonsense\n";
  EXPECT_FALSE (pcl_ext::io::loadCloud (garbage, blob));
  const std::string truncated = dir + "/truncated.pcd";
  std::ofstream (truncated)
      << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
         "COUNT 1 1 1\nWIDTH 5\nHEIGHT 1\nPOINTS 5\nDATA binary\n\x01\x02";
  EXPECT_FALSE (pcl_ext::io::loadCloud (truncated, blob));
  // Files without a PCD header (PCL 1.13's reader crashes on them unless they are
  // refused).
  const std::string empty = dir + "/empty.pcd", text = dir + "/text.pcd";
  const std::string no_fields = dir + "/nofields.pcd";
  std::ofstream (empty) << "";
  std::ofstream (text) << "not a point cloud\n";
  std::ofstream (no_fields)
      << "VERSION 0.7\nFIELDS\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1\n";
  for (const auto& f : {empty, text, no_fields}) {
    EXPECT_FALSE (pcl_ext::io::loadCloud (f, blob)) << f;
    std::remove (f.c_str());
  }
  const std::string no_xyz = dir + "/noxyz.pcd";
  std::ofstream (no_xyz)
      << "# .PCD v0.7\nVERSION 0.7\nFIELDS a\nSIZE 4\nTYPE F\nCOUNT 1\n"
         "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1\n";
  EXPECT_FALSE (pcl_ext::io::loadCloud (no_xyz, blob));
  EXPECT_FALSE (pcl_ext::io::loadCloud (dir + "/c.xyz", blob));
  EXPECT_FALSE (pcl_ext::io::saveCloud (dir + "/out.txt", cloud));
  testing::internal::GetCapturedStderr();
  for (const auto& f : {garbage, truncated, no_xyz})
    std::remove (f.c_str());
  EXPECT_TRUE (listFolder (dir).empty());
  ::rmdir (dir.c_str());
}

TEST (CloudIo, FolderIsRefusedWithoutHanging)
{
  // PCL's PCD reader never returns on a folder (its reads fail without reaching EOF).
  const std::string dir = freshFolder ("cloud_io_folder");
  const std::string folder = dir + "/folder.pcd", ply_folder = dir + "/folder.ply";
  ASSERT_EQ (::mkdir (folder.c_str(), 0755), 0);
  ASSERT_EQ (::mkdir (ply_folder.c_str(), 0755), 0);
  testing::internal::CaptureStderr();
  pcl::PCLPointCloud2 blob;
  EXPECT_FALSE (pcl_ext::io::loadCloud (folder, blob));
  pcl::PointCloud<pcl::PointXYZ> typed;
  EXPECT_FALSE (pcl_ext::io::loadCloud (ply_folder, typed));
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_NE (message.find ("folder.pcd: it is a folder"), std::string::npos) << message;
  EXPECT_EQ (blob.width, 0u);
  ::rmdir (folder.c_str());
  ::rmdir (ply_folder.c_str());
}

TEST (CloudIo, AsciiAndBinaryFilesAndFieldsMissingFromThem)
{
  const std::string dir = freshFolder ("cloud_io_formats");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 4; ++i)
    cloud.push_back (pcl::PointXYZ (0.5f * i, -1.f * i, 2.f));
  // Each format as asked for; binary PCD is compressed.
  struct Case {
    std::string name;
    bool ascii;
    std::string header;
  };
  for (const Case& c : {Case{"a.pcd", true, "DATA ascii"},
                        Case{"b.pcd", false, "DATA binary_compressed"},
                        Case{"a.ply", true, "format ascii"},
                        Case{"b.ply", false, "format binary_little_endian"}}) {
    const std::string path = dir + "/" + c.name;
    ASSERT_TRUE (pcl_ext::io::saveCloud (path, cloud, c.ascii)) << c.name;
    EXPECT_NE (readAll (path).find (c.header), std::string::npos) << c.name;
    // A type with more fields than the file: those keep their defaults.
    pcl::PointCloud<pcl::PointXYZI> back;
    back.push_back (pcl::PointXYZI (7.f));
    ASSERT_TRUE (pcl_ext::io::loadCloud (path, back)) << c.name;
    ASSERT_EQ (back.size(), 4u) << c.name;
    EXPECT_EQ (back[3].x, 1.5f) << c.name;
    EXPECT_EQ (back[3].y, -3.f) << c.name;
    EXPECT_EQ (back[3].z, 2.f) << c.name;
    EXPECT_EQ (back[3].intensity, 0.f) << c.name;
    // The blob keeps the file's fields as they are.
    pcl::PCLPointCloud2 blob;
    ASSERT_TRUE (pcl_ext::io::loadCloud (path, blob)) << c.name;
    EXPECT_EQ (blob.width * blob.height, 4u) << c.name;
    ASSERT_EQ (blob.fields.size(), 3u) << c.name;
    EXPECT_EQ (blob.fields[0].name, "x") << c.name;
    std::remove (path.c_str());
  }
  ::rmdir (dir.c_str());
}

TEST (CloudIo, SavingIsAtomicAndRefusesUnwritableTargets)
{
  const std::string dir = freshFolder ("cloud_io_atomic");
  const std::string path = dir + "/out.pcd";
  pcl::PointCloud<pcl::PointXYZ> one, two;
  one.push_back (pcl::PointXYZ (1.f, 1.f, 1.f));
  two = one;
  two.push_back (pcl::PointXYZ (2.f, 2.f, 2.f));
  ASSERT_TRUE (pcl_ext::io::saveCloud (path, one));
  ASSERT_TRUE (
      pcl_ext::io::saveCloud (path, two)); // replaces the file, no temporary left
  EXPECT_EQ (listFolder (dir), std::vector<std::string>{"out.pcd"});
  pcl::PointCloud<pcl::PointXYZ> back;
  ASSERT_TRUE (pcl_ext::io::loadCloud (path, back));
  EXPECT_EQ (back.size(), 2u);
  testing::internal::CaptureStderr();
  // A missing folder, a folder in the way, an extension that is neither PCD nor PLY:
  // refused, and the folder holds what it held.
  EXPECT_FALSE (pcl_ext::io::saveCloud (dir + "/missing/out.pcd", one));
  const std::string folder = dir + "/folder.pcd";
  ASSERT_EQ (::mkdir (folder.c_str(), 0755), 0);
  EXPECT_FALSE (pcl_ext::io::saveCloud (folder, one));
  EXPECT_FALSE (pcl_ext::io::saveCloud (dir + "/out.xyz", one));
  testing::internal::GetCapturedStderr();
  auto names = listFolder (dir);
  std::sort (names.begin(), names.end());
  EXPECT_EQ (names, (std::vector<std::string>{"folder.pcd", "out.pcd"}));
  ASSERT_TRUE (pcl_ext::io::loadCloud (path, back));
  EXPECT_EQ (back.size(), 2u);
  ::rmdir (folder.c_str());
  std::remove (path.c_str());
  ::rmdir (dir.c_str());
}

TEST (CloudIo, CloudWithoutPointsIsRefused)
{
  const std::string dir = freshFolder ("cloud_io_empty");
  const std::string path = dir + "/empty.pcd";
  std::ofstream (path)
      << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
         "COUNT 1 1 1\nWIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n";
  testing::internal::CaptureStderr();
  pcl::PCLPointCloud2 blob;
  EXPECT_FALSE (pcl_ext::io::loadCloud (path, blob));
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_NE (message.find ("empty.pcd has no points"), std::string::npos) << message;
  EXPECT_TRUE (blob.fields.empty());
  std::remove (path.c_str());
  ::rmdir (dir.c_str());
}
