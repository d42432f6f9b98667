/*
 * Tests of SurfaceIntersectionPoint, the point type of local surface intersections: its
 * fields, defaults and PCD files.
 */
#include <pcl_ext/segmentation/surface_intersection_point.h>

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

using pcl_ext::SurfaceIntersectionPoint;

TEST (SurfaceIntersectionPoint, FieldsAndDefaults)
{
  std::vector<std::string> names;
  std::vector<std::uint8_t> types;
  for (const auto& f : pcl::getFields<SurfaceIntersectionPoint>()) {
    names.push_back (f.name);
    types.push_back (f.datatype);
  }
  EXPECT_EQ (names,
             (std::vector<std::string>{
                 "x", "y", "z", "segment_a", "segment_b", "index_a", "index_b"}));
  const std::uint8_t f32 = pcl::PCLPointField::FLOAT32,
                     u32 = pcl::PCLPointField::UINT32, i32 = pcl::PCLPointField::INT32;
  EXPECT_EQ (types, (std::vector<std::uint8_t>{f32, f32, f32, u32, u32, i32, i32}));
  const SurfaceIntersectionPoint p;
  EXPECT_EQ (p.segment_a, 0u);
  EXPECT_EQ (p.segment_b, 0u);
  EXPECT_EQ (p.index_a, -1); // no surface point yet
  EXPECT_EQ (p.index_b, -1);
}

TEST (SurfaceIntersectionPoint, PcdRoundTripAndCopyToXyz)
{
  pcl::PointCloud<SurfaceIntersectionPoint> cloud;
  for (int i = 0; i < 3; ++i) {
    SurfaceIntersectionPoint p;
    p.x = 0.5f * i;
    p.y = 1.f;
    p.z = -2.f;
    p.segment_a = 3;
    p.segment_b = 4000000000u;
    p.index_a = 10 * i;
    p.index_b = i == 2 ? -1 : 7;
    cloud.push_back (p);
  }
  const std::string path =
      testing::TempDir() + "/intersections_" + std::to_string (::getpid()) + ".pcd";
  ASSERT_EQ (pcl::io::savePCDFileBinary (path, cloud), 0);
  pcl::PointCloud<SurfaceIntersectionPoint> back;
  ASSERT_EQ (pcl::io::loadPCDFile (path, back), 0);
  std::remove (path.c_str());
  ASSERT_EQ (back.size(), 3u);
  EXPECT_EQ (back[2].x, 1.f);
  EXPECT_EQ (back[2].z, -2.f);
  EXPECT_EQ (back[2].segment_a, 3u);
  EXPECT_EQ (back[2].segment_b, 4000000000u);
  EXPECT_EQ (back[2].index_a, 20);
  EXPECT_EQ (back[2].index_b, -1);
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::copyPointCloud (cloud, xyz);
  ASSERT_EQ (xyz.size(), 3u);
  EXPECT_EQ (xyz[1].x, 0.5f);
  EXPECT_EQ (xyz[1].y, 1.f);
}
