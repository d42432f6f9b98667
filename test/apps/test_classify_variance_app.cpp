/*
 * pcl_ext_classify_variance run as a command: labels of a cube written into the `label`
 * field next to the input's own fields, the options beyond the paper (-noise_sigma,
 * -boundary_band, -boundary_band_fraction, -crease_angle), usage errors, and no output
 * on failure.
 */
#include "../app_test.h"

#include "../features/analytic_clouds.h"

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <string>

namespace {
class ClassifyVarianceApp : public pcl_ext::test::AppTest {
protected:
  ClassifyVarianceApp() : AppTest (PCL_EXT_CLASSIFY_VARIANCE_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // A closed cube, 1 mm noise, coloured, so the output must keep the colours.
    cube_ = pcl_ext::test::makeCube (0.5, 0.01, 0.001);
    pcl::PointCloud<pcl::PointXYZRGB> cloud;
    for (const auto& p : *cube_.cloud)
      cloud.push_back (pcl::PointXYZRGB (p.x, p.y, p.z, 10, 20, 30));
    ASSERT_EQ (pcl::io::savePCDFileBinary (path ("cube.pcd"), cloud), 0);
  }

  /** Crease points (within a spacing) that are edges, and face points farther than 1.5
   * neighbourhood radii from the creases that are surface, as fractions. */
  std::pair<double, double>
  check (const std::string& output)
  {
    pcl::PointCloud<pcl::PointXYZRGBL> out;
    EXPECT_EQ (pcl::io::loadPCDFile (path (output), out), 0);
    EXPECT_EQ (out.size(), cube_.crease_distance.size());
    if (out.size() != cube_.crease_distance.size())
      return {0.0, 0.0};
    const double r = cube_.spacing * std::sqrt (50 / M_PI);
    std::size_t near = 0, near_edge = 0, far = 0, far_surface = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_EQ (out[i].g, 20); // the input's fields are kept
      if (cube_.crease_distance[i] <= cube_.spacing) {
        ++near;
        near_edge += out[i].label == 2;
      }
      else if (cube_.crease_distance[i] > 1.5 * r) {
        ++far;
        far_surface += out[i].label == 1;
      }
    }
    return {double (near_edge) / near, double (far_surface) / far};
  }

  pcl_ext::test::AnalyticCloud cube_;
};
} // namespace

TEST_F (ClassifyVarianceApp, CubeCreasesAreEdgesWithAndWithoutTheNoiseModel)
{
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("paper.pcd") + " -threads 2"), 0)
      << output_;
  EXPECT_NE (output_.find ("curvature threshold"), std::string::npos) << output_;
  const auto paper = check ("paper.pcd");
  EXPECT_EQ (paper.first, 1.0);
  EXPECT_GT (paper.second, 0.95);
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("noise.pcd") +
           " -threads 2 -noise_sigma 0.001 -boundary_band -boundary_band_fraction 0.6"),
      0)
      << output_;
  const auto noise = check ("noise.pcd");
  EXPECT_EQ (noise.first, 1.0);
  EXPECT_GT (noise.second, 0.95);
  // The crease angle keeps the cube's right-angled creases.
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("crease.pcd") +
                  " -threads 2 -noise_sigma 0.001 -crease_angle 45"),
             0)
      << output_;
  const auto crease = check ("crease.pcd");
  EXPECT_EQ (crease.first, 1.0);
  EXPECT_GT (crease.second, 0.95);
}

TEST_F (ClassifyVarianceApp, BadUsageFailsWithoutOutput)
{
  const std::string io = path ("cube.pcd") + " " + path ("out.pcd");
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("-noise_sigma"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-boundary_band"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-boundary_band_fraction"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-crease_angle"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-max_radius"), std::string::npos) << output_;
  EXPECT_EQ (run (io + " -noise_sigma -0.001"), 1);
  EXPECT_EQ (run (io + " -noise_sigma nan"), 1);
  EXPECT_EQ (run (io + " -crease_angle 91"), 1);
  EXPECT_EQ (run (io + " -crease_angle -1"), 1);
  EXPECT_EQ (run (io + " -boundary_band -boundary_band_fraction 0"), 1);
  EXPECT_EQ (run (io + " -boundary_band -boundary_band_fraction 1.5"), 1);
  EXPECT_EQ (run (io + " -variance_threshold -1"), 1);
  EXPECT_EQ (run (io + " -k 2"), 1);
  EXPECT_FALSE (exists ("out.pcd"));
}
