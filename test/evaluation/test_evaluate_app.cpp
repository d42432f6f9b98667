/*
 * pcl_ext_evaluate run as a command: exit codes, tables, CSV, and no output on failure.
 */
#include "../app_test.h"

#include <pcl_ext/io/las_writer.h>

#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {
class EvaluateApp : public pcl_ext::test::AppTest {
protected:
  EvaluateApp() : AppTest (PCL_EXT_EVALUATE_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // Ground truth as the scene generator writes it (fields segment, object, class;
    // 'class' is not a valid C++ member name, so the file is written as text): segments
    // 1 (4 points, class 1), 2 (4 points, class 2), 0 (2 points, ignored).
    const std::uint32_t segments[] = {1, 1, 1, 1, 2, 2, 2, 2, 0, 0};
    const std::uint32_t predicted[] = {7, 7, 7, 7, 9, 9, 9, 0, 5, 5};
    std::ofstream truth (path ("truth.pcd"));
    truth
        << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
        << "FIELDS x y z segment object class\nSIZE 4 4 4 4 4 4\nTYPE F F F U U U\n"
        << "COUNT 1 1 1 1 1 1\nWIDTH 10\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 10\n"
        << "DATA ascii\n";
    pcl::PointCloud<pcl::PointXYZL> prediction;
    for (int i = 0; i < 10; ++i) {
      truth << i << " 0 0 " << segments[i] << " 1 " << segments[i] << "\n";
      pcl::PointXYZL p;
      p.x = static_cast<float> (i);
      p.y = p.z = 0.f;
      p.label = predicted[i];
      prediction.push_back (p);
    }
    truth.close();
    ASSERT_EQ (pcl::io::savePCDFileBinary (path ("prediction.pcd"), prediction), 0);
  }

  std::string
  read (const std::string& name) const
  {
    std::ifstream in (path (name));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
};
} // namespace

TEST_F (EvaluateApp, Segments)
{
  ASSERT_EQ (run ("-segments " + path ("prediction.pcd") + " " + path ("truth.pcd") +
                  " -csv " + path ("out.csv")),
             0)
      << output_;
  // Segment 1 is found exactly, segment 2 by 3 of its 4 points (0.75 < 0.8): missed.
  EXPECT_NE (output_.find ("correct                  1"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("missed                   1"), std::string::npos) << output_;
  const std::string csv = read ("out.csv");
  EXPECT_EQ (csv.rfind ("scope,label,name,metric,value\n", 0), 0u);
  EXPECT_NE (csv.find ("summary,,,correct,1\n"), std::string::npos) << csv;
  EXPECT_NE (csv.find ("summary,,,ignored_points,2\n"), std::string::npos) << csv;
  EXPECT_NE (csv.find ("segment,2,,iou,0.75\n"), std::string::npos) << csv;
  // A looser tolerance makes segment 2 correct.
  ASSERT_EQ (run ("-segments " + path ("prediction.pcd") + " " + path ("truth.pcd") +
                  " -tolerance 0.7"),
             0)
      << output_;
  EXPECT_NE (output_.find ("correct                  2"), std::string::npos) << output_;
}

TEST_F (EvaluateApp, ReadsTheToolsOutputFormats)
{
  // The same prediction as a georeferenced LAS file (its label an extra-bytes
  // dimension, as the tools write their results): the same figures as from the PCD.
  pcl::PointCloud<pcl::PointXYZL> prediction;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("prediction.pcd"), prediction), 0);
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (prediction, blob);
  ASSERT_TRUE (pcl_ext::io::saveLas (
      path ("prediction.las"), blob, Eigen::Vector3d (500000.0, 6000000.0, 0.0)));
  ASSERT_EQ (run ("-segments " + path ("prediction.las") + " " + path ("truth.pcd")), 0)
      << output_;
  EXPECT_NE (output_.find ("correct                  1"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("missed                   1"), std::string::npos) << output_;
  // A file that is no point file at all is refused, naming it.
  std::ofstream (path ("garbage.las")) << "not a point cloud\n";
  EXPECT_EQ (run ("-segments " + path ("garbage.las") + " " + path ("truth.pcd")), 1);
  EXPECT_NE (output_.find ("garbage.las"), std::string::npos) << output_;
}

TEST_F (EvaluateApp, Classes)
{
  // The prediction's own segment labels scored as classes against the 'class' field.
  ASSERT_EQ (run ("-classes " + path ("truth.pcd") + " " + path ("truth.pcd") +
                  " -field segment"),
             0)
      << output_;
  EXPECT_NE (output_.find ("overall accuracy   1.0000"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("surface"), std::string::npos)
      << output_; // PointClass names
}

TEST_F (EvaluateApp, Transform)
{
  const std::string data = PCL_EXT_TEST_DATA_DIR;
  // A 90 degree rotation about z with t = (1, 2, 3) against a pure translation (10, 20,
  // 0.5).
  ASSERT_EQ (run ("-transform " + data + "/transform_3x4.txt " + data +
                  "/transform_translation.txt -csv " + path ("t.csv")),
             0)
      << output_;
  EXPECT_NE (output_.find ("rotation error     90.0000 deg"), std::string::npos)
      << output_;
  const std::string csv = read ("t.csv");
  EXPECT_NE (csv.find ("summary,,,rotation_error_deg,90\n"), std::string::npos) << csv;
  // |(1, 2, 3) - (10, 20, 0.5)| = sqrt(81 + 324 + 6.25)
  EXPECT_NE (output_.find ("translation error  20.2793 m"), std::string::npos)
      << output_;
  EXPECT_EQ (
      run ("-transform " + data + "/transform_bad.txt " + data + "/transform_3x4.txt"),
      1);
  EXPECT_NE (output_.find ("transform_bad.txt:2:"), std::string::npos) << output_;
  EXPECT_EQ (run ("-transform " + data + "/transform_3x4.txt " + data +
                  "/transform_3x4.txt -reference 1,2"),
             1);
}

TEST_F (EvaluateApp, BadUsageAndInputFailWithoutOutput)
{
  const std::string both = path ("prediction.pcd") + " " + path ("truth.pcd");
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("-tolerance X"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("(default: 0.8)"), std::string::npos) << output_;
  EXPECT_EQ (run (both), 1);
  EXPECT_EQ (run ("-segments -classes " + both), 1);
  EXPECT_EQ (run ("-segments " + path ("prediction.pcd")), 1);
  EXPECT_EQ (run ("-segments " + both + " -tolerance 0.4 -csv " + path ("a.csv")), 1);
  EXPECT_EQ (run ("-segments " + path ("missing.pcd") + " " + path ("truth.pcd") +
                  " -csv " + path ("a.csv")),
             1);
  EXPECT_NE (output_.find ("missing.pcd"), std::string::npos) << output_;
  EXPECT_EQ (run ("-segments " + both + " -truth_field nothing -csv " + path ("a.csv")),
             1);
  EXPECT_NE (output_.find ("no field 'nothing'"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("a.csv"));
}
