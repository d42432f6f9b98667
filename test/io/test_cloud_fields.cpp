/*
 * Reading a named field of any type from a PCLPointCloud2, and writing a label field.
 */
#include <pcl_ext/io/cloud_fields.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>

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
