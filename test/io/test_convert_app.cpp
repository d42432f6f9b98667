/*
 * pcl_ext_convert run as a command: formats, class mapping, origin, and no output on
 * failure.
 */
#include "../app_test.h"
#include "test_helpers.h"

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <string>
#include <sys/stat.h>

namespace {
class ConvertApp : public pcl_ext::test::AppTest {
protected:
  ConvertApp() : AppTest (PCL_EXT_CONVERT_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
  }
};
} // namespace

TEST_F (ConvertApp, OaklandWithClassMapping)
{
  ASSERT_EQ (run (fixture ("oakland_sample.xyz_label_conf") + " " + path ("o.pcd") +
                  " -classes " + fixture ("classes_sample.txt")),
             0)
      << output_;
  pcl::PointCloud<pcl::PointXYZL> cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("o.pcd"), cloud), 0);
  ASSERT_EQ (cloud.size(), 6u);
  const std::uint32_t expected[] = {1, 1, 1, 2, 0, 0};
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ (cloud[i].label, expected[i]) << i;
  EXPECT_FLOAT_EQ (cloud[0].z, -1.5f); // local data: no origin subtracted
  EXPECT_EQ (output_.find ("origin"), std::string::npos) << output_;

  // PCD in, mapping the field given: the mapped classes of a mapped file are all 0.
  ASSERT_EQ (run (path ("o.pcd") + " " + path ("o.ply") + " -classes " +
                  fixture ("classes_sample.txt")),
             0)
      << output_;
  EXPECT_TRUE (exists ("o.ply"));
}

TEST_F (ConvertApp, AsciiColumnsAndOrigin)
{
  ASSERT_EQ (run (fixture ("points_georef.txt") + " " + path ("g.pcd") +
                  " -columns x,y,z,label"),
             0)
      << output_;
  EXPECT_NE (output_.find ("119300.000, 485100.000, 0.000"), std::string::npos)
      << output_;
  pcl::PointCloud<pcl::PointXYZL> cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("g.pcd"), cloud), 0);
  EXPECT_FLOAT_EQ (cloud[0].x, 5.125f);
  EXPECT_EQ (cloud[1].label, 6u);
  ASSERT_EQ (run (fixture ("points_georef.txt") + " " + path ("g2.pcd") +
                  " -columns x,y,z,label -origin 119000,485000,1"),
             0)
      << output_;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("g2.pcd"), cloud), 0);
  EXPECT_FLOAT_EQ (cloud[0].x, 305.125f);
  EXPECT_FLOAT_EQ (cloud[0].z, 0.25f);
  ASSERT_EQ (run (fixture ("points_xyzirgbl.txt") + " " + path ("c.ply") + " -ascii"),
             0)
      << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> rgbl;
  ASSERT_EQ (pcl::io::loadPLYFile (path ("c.ply"), rgbl), 0);
  ASSERT_EQ (rgbl.size(), 3u);
  EXPECT_EQ (rgbl[1].g, 255);
}

TEST_F (ConvertApp, FailuresLeaveNoOutput)
{
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("(default: auto)"), std::string::npos) << output_;
  EXPECT_EQ (run (fixture ("points_bad_number.txt") + " " + path ("x.pcd")), 1);
  EXPECT_NE (
      output_.find ("points_bad_number.txt:3: column 3 (z): 'nine' is not a number"),
      std::string::npos)
      << output_;
  EXPECT_EQ (run (fixture ("points_truncated.txt") + " " + path ("x.pcd")), 1);
  EXPECT_NE (output_.find ("points_truncated.txt:3:"), std::string::npos) << output_;
  EXPECT_EQ (run (fixture ("empty.txt") + " " + path ("x.pcd")), 1);
  EXPECT_EQ (run (fixture ("missing.xyz") + " " + path ("x.pcd")), 1);
  // LAZ is read but not written (LAS, PCD and PLY are: test/apps).
  EXPECT_EQ (run (fixture ("points_comma.csv") + " " + path ("x.laz")), 1);
  EXPECT_FALSE (exists ("x.laz"));
  EXPECT_EQ (
      run (fixture ("points_comma.csv") + " " + path ("x.pcd") + " -columns x,y,q"), 1);
  EXPECT_EQ (run (fixture ("points_comma.csv") + " " + path ("x.pcd") + " -origin 1,2"),
             1);
  EXPECT_EQ (run (fixture ("points_comma.csv") + " " + path ("x.pcd") + " -classes " +
                  fixture ("classes_duplicate.txt")),
             1);
  EXPECT_NE (output_.find ("classes_duplicate.txt:2:"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("x.pcd"));
  // A failed conversion leaves an existing output as it was.
  ASSERT_EQ (run (fixture ("points_comma.csv") + " " + path ("keep.pcd")), 0)
      << output_;
  struct stat before, after;
  ASSERT_EQ (::stat (path ("keep.pcd").c_str(), &before), 0);
  EXPECT_EQ (run (fixture ("points_wrong_columns.txt") + " " + path ("keep.pcd")), 1);
  ASSERT_EQ (::stat (path ("keep.pcd").c_str(), &after), 0);
  EXPECT_EQ (before.st_size, after.st_size);
  EXPECT_EQ (before.st_mtime, after.st_mtime);
  // The input is never the output.
  EXPECT_EQ (run (path ("keep.pcd") + " " + path ("keep.pcd")), 1);
}
