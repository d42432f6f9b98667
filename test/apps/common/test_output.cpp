/*
 * Tests of the apps' result field and output: the field never overwrites an input field
 * the user did not name, refusals before any work, the ASPRS codes, and the output
 * written in the input's frame.
 */
#include <pcl_ext/apps/output.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstring>
#include <unistd.h>
#include <vector>

using pcl_ext::apps::ResultField;

namespace {
/** Parse \a args (after the tool name) with \a field's options declared. */
int
parse (ResultField& field,
       pcl_ext::apps::CommandLine& cl,
       std::vector<const char*> args)
{
  args.insert (args.begin(), "pcl_ext_test");
  field.addTo (cl);
  return cl.parse (static_cast<int> (args.size()), args.data());
}

/** An input of three points with a field `label` (a truth, say). */
pcl_ext::io::PointFile
labelledInput ()
{
  pcl::PointCloud<pcl::PointXYZL> cloud;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZL p;
    p.x = 0.5f * i;
    p.y = 1.0f;
    p.z = 2.0f;
    p.label = 7;
    cloud.push_back (p);
  }
  pcl_ext::io::PointFile input;
  pcl::toPCLPointCloud2 (cloud, input.cloud);
  input.origin = Eigen::Vector3d (500000.0, 6000000.0, 10.0);
  input.format = pcl_ext::io::PointFileFormat::PCD;
  return input;
}

std::string
tempPath (const std::string& name)
{
  return testing::TempDir() + "/pcl_ext_output_" + std::to_string (::getpid()) + "_" +
         name;
}
} // namespace

TEST (ResultField, AnInputFieldIsKeptUnlessNamed)
{
  const pcl_ext::io::PointFile input = labelledInput();
  {
    ResultField field ("label", "class", "");
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
    ASSERT_EQ (parse (field, cl, {}), -1);
    testing::internal::CaptureStdout();
    EXPECT_TRUE (field.checkInput (input, "in.pcd"));
    EXPECT_NE (testing::internal::GetCapturedStdout().find ("label_2"),
               std::string::npos);
    EXPECT_EQ (field.name(), "label_2");
    pcl::PCLPointCloud2 out = input.cloud;
    ASSERT_TRUE (field.attach (out, {1, 2, 3}));
    pcl::PointCloud<pcl::PointXYZL> truth;
    pcl::fromPCLPointCloud2 (out, truth);
    for (const auto& p : truth)
      EXPECT_EQ (p.label, 7u); // the input's field is untouched
    EXPECT_GE (pcl::getFieldIndex (out, "label_2"), 0);
  }
  {
    // Named by the user: replaced.
    ResultField field ("lv_class", "class", "");
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
    ASSERT_EQ (parse (field, cl, {"-output_field", "label"}), -1);
    EXPECT_TRUE (field.checkInput (input, "in.pcd"));
    EXPECT_EQ (field.name(), "label");
    // One value per point, or a refusal.
    pcl::PCLPointCloud2 out = input.cloud;
    testing::internal::CaptureStderr();
    EXPECT_FALSE (field.attach (out, {1, 2}));
    testing::internal::GetCapturedStderr();
  }
}

TEST (ResultField, OutputsThatCannotBeWrittenAreRefusedBeforeAnyWork)
{
  testing::internal::CaptureStderr();
  {
    ResultField field ("lv_class", "class", "the classes as ASPRS codes");
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
    ASSERT_EQ (parse (field, cl, {"-asprs"}), -1);
    EXPECT_TRUE (field.asprs());
    EXPECT_TRUE (field.checkOutput (tempPath ("out.las")));
    EXPECT_FALSE (field.checkOutput (tempPath ("out.pcd"))); // -asprs needs LAS
    EXPECT_FALSE (field.checkOutput (tempPath ("out.laz"))); // LAZ is not written
    EXPECT_FALSE (field.checkOutput ("/nonexistent-folder/out.las"));
  }
  {
    ResultField field = pcl_ext::apps::segmentIdField();
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
    ASSERT_EQ (parse (field, cl, {"-asprs"}), -1);
    EXPECT_FALSE (field.checkOutput (tempPath ("out.las"))); // ids are not classes
  }
  {
    ResultField field = pcl_ext::apps::segmentIdField();
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
    ASSERT_EQ (parse (field, cl, {"-output_field", "z"}), -1);
    EXPECT_FALSE (field.checkOutput (tempPath ("out.pcd"))); // not over a coordinate
  }
  testing::internal::GetCapturedStderr();
}

TEST (ResultField, AsprsCodesOfClassNames)
{
  using pcl_ext::apps::asprsClass;
  EXPECT_EQ (asprsClass ("ground"), 2);
  EXPECT_EQ (asprsClass ("Low Vegetation"), 3);
  EXPECT_EQ (asprsClass ("high vegetation"), 5);
  EXPECT_EQ (asprsClass ("tree"), 5);
  EXPECT_EQ (asprsClass ("facade"), 6);
  EXPECT_EQ (asprsClass ("wire"), 14);
  EXPECT_EQ (asprsClass ("edge"), -1); // Belton & Lichti's classes have no code
  EXPECT_EQ (asprsClass (""), -1);
}

TEST (ResultField, OutputIsWrittenInTheInputsFrame)
{
  const pcl_ext::io::PointFile input = labelledInput();
  const std::string path = tempPath ("frame.pcd");
  testing::internal::CaptureStdout();
  ASSERT_TRUE (pcl_ext::apps::saveOutput (path, input.cloud, input));
  testing::internal::GetCapturedStdout();
  pcl_ext::io::PointFile back;
  pcl_ext::io::loadPointFile (path, back);
  ASSERT_EQ (back.cloud.width * back.cloud.height, 3u);
  const int x = pcl::getFieldIndex (back.cloud, "x");
  ASSERT_GE (x, 0);
  for (std::size_t i = 0; i < 3; ++i) {
    float p[3];
    std::memcpy (p,
                 back.cloud.data.data() + i * back.cloud.point_step +
                     back.cloud.fields[x].offset,
                 sizeof (p));
    // The file coordinate is origin + local, whatever origin the reader chose.
    EXPECT_NEAR (back.origin.x() + p[0], 500000.0 + 0.5 * i, 1e-6);
    EXPECT_NEAR (back.origin.y() + p[1], 6000001.0, 1e-6);
    EXPECT_NEAR (back.origin.z() + p[2], 12.0, 1e-6);
  }
  std::remove (path.c_str());
}
