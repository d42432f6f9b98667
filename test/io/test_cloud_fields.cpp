/*
 * Reading a named field of any type from a PCLPointCloud2, and writing a label field.
 */
#include <pcl_ext/io/cloud_fields.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

TEST (CloudFields, ReadsAnyType)
{
  pcl::PointCloud<pcl::PointXYZL> typed;
  for (std::uint32_t l : {0u, 3u, 4000000000u}) {
    pcl::PointXYZL p;
    p.x = p.y = p.z = 1.f;
    p.label = l;
    typed.push_back (p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (typed, blob);
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{0, 3, 4000000000u}));

  // Float field (x) with whole values, then with a fraction.
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "x", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{1, 1, 1}));
  typed[1].x = 1.5f;
  pcl::toPCLPointCloud2 (typed, blob);
  std::string error;
  EXPECT_FALSE (pcl_ext::io::getLabelField (blob, "x", labels, &error));
  EXPECT_NE (error.find ("point 1"), std::string::npos) << error;
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{1, 1, 1})); // unchanged
  EXPECT_FALSE (pcl_ext::io::getLabelField (blob, "segment", labels, &error));
  EXPECT_NE (error.find ("no field 'segment'"), std::string::npos) << error;

  // NaN and negative values mean "no label".
  typed[0].y = std::nanf ("");
  typed[1].y = -1.f;
  pcl::toPCLPointCloud2 (typed, blob);
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "y", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{0, 0, 1}));
}

TEST (CloudFields, WritesLabel)
{
  pcl::PointCloud<pcl::PointXYZI> typed;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZI p;
    p.x = static_cast<float> (i);
    p.y = 2.f;
    p.z = 3.f;
    p.intensity = 10.f * i;
    typed.push_back (p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (typed, blob);
  // Appended.
  ASSERT_TRUE (pcl_ext::io::setLabelField (blob, "label", {5, 6, 7}));
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{5, 6, 7}));
  pcl::PointCloud<pcl::PointXYZI> back;
  pcl::fromPCLPointCloud2 (blob, back);
  EXPECT_FLOAT_EQ (back[2].intensity, 20.f);
  EXPECT_FLOAT_EQ (back[1].x, 1.f);
  // Overwritten in place.
  ASSERT_TRUE (pcl_ext::io::setLabelField (blob, "label", {1, 2, 3}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{1, 2, 3}));
  // Replacing a float field by a uint32 one keeps the others.
  ASSERT_TRUE (pcl_ext::io::setLabelField (blob, "intensity", {9, 9, 9}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "intensity", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{9, 9, 9}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{1, 2, 3}));
  pcl::fromPCLPointCloud2 (blob, back);
  EXPECT_FLOAT_EQ (back[2].x, 2.f);
  EXPECT_FLOAT_EQ (back[2].z, 3.f);
  EXPECT_FALSE (pcl_ext::io::setLabelField (blob, "label", {1}));
}

TEST (CloudFields, WritesFloat)
{
  pcl::PointCloud<pcl::PointXYZL> typed;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZL p;
    p.x = static_cast<float> (i);
    p.y = p.z = 1.f;
    p.label = static_cast<std::uint32_t> (4 + i);
    typed.push_back (p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (typed, blob);
  // Appended as float32, the other fields kept.
  ASSERT_TRUE (pcl_ext::io::setFloatField (blob, "probability", {0.25f, 0.5f, 1.f}));
  pcl::PointCloud<pcl::PointXYZI> as_intensity;
  const int f = pcl::getFieldIndex (blob, "probability");
  ASSERT_GE (f, 0);
  EXPECT_EQ (blob.fields[f].datatype, pcl::PCLPointField::FLOAT32);
  blob.fields[f].name = "intensity";
  pcl::fromPCLPointCloud2 (blob, as_intensity);
  EXPECT_FLOAT_EQ (as_intensity[0].intensity, 0.25f);
  EXPECT_FLOAT_EQ (as_intensity[2].intensity, 1.f);
  blob.fields[f].name = "probability";
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{4, 5, 6}));
  // Overwritten in place; a uint32 field of that name is replaced by a float one.
  ASSERT_TRUE (pcl_ext::io::setFloatField (blob, "probability", {0.75f, 0.f, 0.5f}));
  ASSERT_TRUE (pcl_ext::io::setFloatField (blob, "label", {2.f, 3.f, 4.f}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (blob, "label", labels));
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_EQ (blob.fields[pcl::getFieldIndex (blob, "label")].datatype,
             pcl::PCLPointField::FLOAT32);
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::fromPCLPointCloud2 (blob, xyz);
  EXPECT_FLOAT_EQ (xyz[2].x, 2.f);
  EXPECT_FALSE (pcl_ext::io::setFloatField (blob, "probability", {1.f}));
}

namespace {
/** A cloud of \a n points with UINT16 fields red green blue (like a LAS file's). */
pcl::PCLPointCloud2
lasLikeColours (const std::vector<std::array<std::uint16_t, 3>>& colours)
{
  pcl::PCLPointCloud2 cloud;
  std::uint32_t offset = 0;
  for (const char* name : {"x", "y", "z"}) {
    cloud.fields.push_back ({name, offset, pcl::PCLPointField::FLOAT32, 1});
    offset += 4;
  }
  for (const char* name : {"red", "green", "blue"}) {
    cloud.fields.push_back ({name, offset, pcl::PCLPointField::UINT16, 1});
    offset += 2;
  }
  cloud.point_step = offset;
  cloud.width = static_cast<std::uint32_t> (colours.size());
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.assign (cloud.row_step, 0);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const float xyz[3] = {float (i), 0.f, 1.f};
    std::memcpy (&cloud.data[i * cloud.point_step], xyz, sizeof (xyz));
    std::memcpy (&cloud.data[i * cloud.point_step + 12], colours[i].data(), 6);
  }
  return cloud;
}
} // namespace

TEST (CloudFields, CloudsOfDifferentFieldsInOneLayout)
{
  // A PCD-like cloud (x y z rgb intensity) and a LAS-like one (x y z red green blue).
  pcl::PointCloud<pcl::PointXYZRGB> coloured;
  pcl::PointXYZRGB p;
  p.x = 1.f;
  p.y = 2.f;
  p.z = 3.f;
  p.r = 10;
  p.g = 20;
  p.b = 255;
  coloured.push_back (p);
  pcl::PCLPointCloud2 a, intensity;
  pcl::toPCLPointCloud2 (coloured, a);
  pcl::PointCloud<pcl::PointXYZI> with_intensity;
  with_intensity.push_back (pcl::PointXYZI (7.f));
  pcl::toPCLPointCloud2 (with_intensity, intensity);
  const pcl::PCLPointCloud2 b = lasLikeColours ({{2570, 5140, 65535}, {0, 257, 512}});

  pcl::PCLPointCloud2 layout;
  std::string error;
  ASSERT_TRUE (pcl_ext::io::unionOfFields ({a, b, intensity}, layout, error)) << error;
  std::vector<std::string> names;
  for (const auto& f : layout.fields)
    names.push_back (f.name);
  EXPECT_EQ (names,
             (std::vector<std::string>{
                 "x", "y", "z", "rgb", "red", "green", "blue", "intensity"}));
  EXPECT_EQ (layout.point_step, 4u * 4 + 3u * 2 + 4u);

  // The packed colour gives the channels (8 bits x 257) and the channels the packed
  // colour; a field a cloud lacks is 0.
  pcl::PCLPointCloud2 from_a, from_b;
  pcl_ext::io::conformToFields (a, layout, from_a);
  pcl_ext::io::conformToFields (b, layout, from_b);
  ASSERT_EQ (from_a.width, 1u);
  ASSERT_EQ (from_b.width, 2u);
  std::vector<std::uint32_t> values;
  ASSERT_TRUE (pcl_ext::io::getLabelField (from_a, "red", values));
  EXPECT_EQ (values, (std::vector<std::uint32_t>{2570}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (from_a, "blue", values));
  EXPECT_EQ (values, (std::vector<std::uint32_t>{65535}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (from_a, "intensity", values));
  EXPECT_EQ (values, (std::vector<std::uint32_t>{0}));
  ASSERT_TRUE (pcl_ext::io::getLabelField (from_b, "green", values));
  EXPECT_EQ (values, (std::vector<std::uint32_t>{5140, 257}));
  pcl::PointCloud<pcl::PointXYZRGB> back;
  pcl::fromPCLPointCloud2 (from_b, back);
  ASSERT_EQ (back.size(), 2u);
  EXPECT_EQ (back[0].r, 10);
  EXPECT_EQ (back[0].g, 20);
  EXPECT_EQ (back[0].b, 255);
  EXPECT_EQ (back[1].g, 1);
  EXPECT_EQ (back[1].b, 2);
  EXPECT_EQ (back[1].x, 1.f);
  pcl::fromPCLPointCloud2 (from_a, back);
  EXPECT_EQ (back[0].y, 2.f);
  EXPECT_EQ (back[0].b, 255);

  // One name, two types: refused, naming the field.
  pcl::PointCloud<pcl::PointXYZL> labelled;
  labelled.push_back (pcl::PointXYZL());
  pcl::PCLPointCloud2 l;
  pcl::toPCLPointCloud2 (labelled, l);
  l.fields[3].name = "intensity"; // UINT32 where the other has FLOAT32
  EXPECT_FALSE (pcl_ext::io::unionOfFields ({intensity, l}, layout, error));
  EXPECT_NE (error.find ("'intensity'"), std::string::npos) << error;
}
