/*
 * Tests of SimulatedPoint, the point type of synthetic scans: its registered fields and
 * their way through PCL's conversions.
 */
#include <pcl_ext/simulation/simulated_point.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_cloud.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using pcl_ext::simulation::SimulatedPoint;

TEST (SimulatedPoint, RegisteredFieldsAndDefaults)
{
  std::vector<std::string> names;
  std::vector<std::uint8_t> types;
  for (const auto& f : pcl::getFields<SimulatedPoint>()) {
    names.push_back (f.name);
    types.push_back (f.datatype);
  }
  // point_class is the registered name; scene_io saves it as "class".
  EXPECT_EQ (names,
             (std::vector<std::string>{"x",
                                       "y",
                                       "z",
                                       "rgb",
                                       "intensity",
                                       "segment",
                                       "object",
                                       "point_class",
                                       "label"}));
  const std::uint8_t f32 = pcl::PCLPointField::FLOAT32,
                     u32 = pcl::PCLPointField::UINT32;
  EXPECT_EQ (types,
             (std::vector<std::uint8_t>{f32, f32, f32, f32, f32, u32, u32, u32, u32}));
  const SimulatedPoint p;
  EXPECT_EQ (p.intensity, 0.f);
  EXPECT_EQ (p.segment, 0u);
  EXPECT_EQ (p.object, 0u);
  EXPECT_EQ (p.point_class, 0u);
  EXPECT_EQ (p.label, 0u);
  EXPECT_EQ (alignof (SimulatedPoint), 16u);
}

TEST (SimulatedPoint, ThroughABlobAndIntoPclTypes)
{
  pcl::PointCloud<SimulatedPoint> cloud;
  for (int i = 0; i < 3; ++i) {
    SimulatedPoint p;
    p.x = static_cast<float> (i);
    p.y = 2.f * i;
    p.z = -1.f;
    p.r = static_cast<std::uint8_t> (10 * i);
    p.g = 200;
    p.b = 7;
    p.intensity = 0.25f * i;
    p.segment = 100u + i;
    p.object = 3;
    p.point_class = 2;
    p.label = 4000000000u;
    cloud.push_back (p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (cloud, blob);
  EXPECT_EQ (blob.width, 3u);
  ASSERT_GE (pcl::getFieldIndex (blob, "point_class"), 0);
  pcl::PointCloud<SimulatedPoint> back;
  pcl::fromPCLPointCloud2 (blob, back);
  ASSERT_EQ (back.size(), 3u);
  EXPECT_EQ (back[2].y, 4.f);
  EXPECT_EQ (back[2].r, 20);
  EXPECT_EQ (back[2].g, 200);
  EXPECT_EQ (back[2].b, 7);
  EXPECT_EQ (back[2].intensity, 0.5f);
  EXPECT_EQ (back[2].segment, 102u);
  EXPECT_EQ (back[2].point_class, 2u);
  EXPECT_EQ (back[2].label, 4000000000u);
  // Field by field into PCL's own types: colour, intensity and label come across.
  pcl::PointCloud<pcl::PointXYZRGBL> coloured;
  pcl::copyPointCloud (cloud, coloured);
  ASSERT_EQ (coloured.size(), 3u);
  EXPECT_EQ (coloured[1].r, 10);
  EXPECT_EQ (coloured[1].g, 200);
  EXPECT_EQ (coloured[1].label, 4000000000u);
  pcl::PointCloud<pcl::PointXYZI> with_intensity;
  pcl::copyPointCloud (cloud, with_intensity);
  EXPECT_EQ (with_intensity[1].intensity, 0.25f);
  EXPECT_EQ (with_intensity[1].x, 1.f);
}
