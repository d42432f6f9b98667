/*
 * pcl_ext_classify_variance run as a command: labels of a cube written into the `label`
 * field next to the input's own fields, the options beyond the paper (-noise_sigma,
 * -boundary_band, -boundary_band_fraction, -crease_angle), usage errors, and no output
 * on failure.
 */
#include "../app_result.h"
#include "../app_test.h"

#include "../features/analytic_clouds.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/las_writer.h>

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
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
    EXPECT_EQ (pcl_ext::test::loadResult (path (output), "lv_class", out), 0);
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
  // Eq. 5's edges as they are, a band about a neighbourhood wide along each crease.
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("paper.pcd") + " -threads 2 -wide_edges"), 0)
      << output_;
  EXPECT_NE (output_.find ("curvature threshold"), std::string::npos) << output_;
  const auto paper = check ("paper.pcd");
  EXPECT_EQ (paper.first, 1.0);
  EXPECT_GT (paper.second, 0.95);
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("noise.pcd") +
           " -threads 2 -noise_sigma 0.001 -boundary_band -boundary_band_fraction 0.6 "
           "-wide_edges"),
      0)
      << output_;
  const auto noise = check ("noise.pcd");
  EXPECT_EQ (noise.first, 1.0);
  EXPECT_GT (noise.second, 0.95);
  // The crease angle keeps the cube's right-angled creases.
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("crease.pcd") +
                  " -threads 2 -noise_sigma 0.001 -crease_angle 45 -wide_edges"),
             0)
      << output_;
  const auto crease = check ("crease.pcd");
  EXPECT_EQ (crease.first, 1.0);
  EXPECT_GT (crease.second, 0.95);
}

TEST_F (ClassifyVarianceApp, DefaultEdgesAreNarrowedToTheCreases)
{
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("wide.pcd") + " -threads 2 -wide_edges"), 0)
      << output_;
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("narrow.pcd") + " -threads 2"), 0)
      << output_;
  EXPECT_NE (output_.find ("edges narrowed to their creases"), std::string::npos)
      << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> wide, narrow;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("wide.pcd"), "lv_class", wide), 0);
  ASSERT_EQ (pcl_ext::test::loadResult (path ("narrow.pcd"), "lv_class", narrow), 0);
  ASSERT_EQ (wide.size(), cube_.crease_distance.size());
  ASSERT_EQ (narrow.size(), wide.size());
  // The points on a crease stay edges (the corners, where three faces meet, aside);
  // the edges of the wide band 1.5 spacings or more from a crease become surface
  // points; nothing else changes.
  std::size_t on = 0, on_edge = 0, off = 0, off_surface = 0;
  for (std::size_t i = 0; i < wide.size(); ++i) {
    if (wide[i].label != 2) {
      EXPECT_EQ (narrow[i].label, wide[i].label);
      continue;
    }
    const auto& p = (*cube_.cloud)[i];
    int ends = 0;
    for (const float c : {p.x, p.y, p.z})
      ends += c < 0.05f || c > 0.45f;
    if (cube_.crease_distance[i] <= 0.25 * cube_.spacing && ends < 3) {
      ++on;
      on_edge += narrow[i].label == 2;
    }
    else if (cube_.crease_distance[i] >= 1.5 * cube_.spacing) {
      ++off;
      off_surface += narrow[i].label == 1;
    }
  }
  ASSERT_GT (on, 400u);
  ASSERT_GT (off, 2000u);
  EXPECT_GE (on_edge, 0.98 * on) << on_edge << " of " << on;
  EXPECT_GE (off_surface, 0.98 * off) << off_surface << " of " << off;
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
  EXPECT_NE (output_.find ("-wide_edges"), std::string::npos) << output_;
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

// The georeferencing test of issue 29: the cube at UTM coordinates (x ~ 500,000, y ~
// 6,000,000, mm scale), classified and written back as LAS, has the input's integers
// and the labels of the same cube at the origin.
TEST_F (ClassifyVarianceApp, UtmLasKeepsItsCoordinatesAndGetsTheLocalLabels)
{
  pcl::PCLPointCloud2 local;
  {
    pcl::PointCloud<pcl::PointXYZRGB> cloud;
    pcl::io::loadPCDFile (path ("cube.pcd"), cloud);
    pcl::toPCLPointCloud2 (cloud, local);
  }
  const Eigen::Vector3d utm (500000.0, 6000000.0, 0.0);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (path ("local.las"), local, Eigen::Vector3d::Zero()));
  ASSERT_TRUE (pcl_ext::io::saveLas (path ("utm.las"), local, utm));
  ASSERT_EQ (run (path ("local.las") + " " + path ("local_out.las") + " -threads 2"), 0)
      << output_;
  ASSERT_EQ (run (path ("utm.las") + " " + path ("utm_out.las") + " -threads 2"), 0)
      << output_;
  pcl::PCLPointCloud2 in, out, local_out;
  pcl_ext::io::LasFileInfo in_info, out_info, local_info;
  pcl_ext::io::loadLas (path ("utm.las"), in, in_info);
  pcl_ext::io::loadLas (path ("utm_out.las"), out, out_info);
  pcl_ext::io::loadLas (path ("local_out.las"), local_out, local_info);
  EXPECT_EQ (out_info.header.scale, in_info.header.scale);
  EXPECT_EQ (out_info.header.offset, in_info.header.offset);
  std::vector<std::uint32_t> in_x, out_x, in_y, out_y, labels, local_labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out, "lv_class", labels));
  ASSERT_TRUE (pcl_ext::io::getLabelField (local_out, "lv_class", local_labels));
  EXPECT_EQ (labels, local_labels);
  // The file coordinates, to the integer, and within 1 mm of the cube at UTM.
  pcl::PointCloud<pcl::PointXYZ> a, b;
  pcl::fromPCLPointCloud2 (in, a);
  pcl::fromPCLPointCloud2 (out, b);
  ASSERT_EQ (a.size(), b.size());
  ASSERT_EQ (a.size(), cube_.cloud->size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector3d file_in =
        in_info.origin + a[i].getVector3fMap().cast<double>();
    const Eigen::Vector3d file_out =
        out_info.origin + b[i].getVector3fMap().cast<double>();
    EXPECT_EQ (file_in, file_out);
    const Eigen::Vector3d truth =
        utm + (*cube_.cloud)[i].getVector3fMap().cast<double>();
    worst = std::max (worst, (file_out - truth).cwiseAbs().maxCoeff());
  }
  EXPECT_LE (worst, 0.0005 + 1e-6); // the mm scale's rounding
  const auto las_integers = [] (const pcl::PCLPointCloud2& c) {
    const int f = pcl::getFieldIndex (c, "las_x");
    std::vector<std::int32_t> v;
    for (std::size_t i = 0; f >= 0 && i < c.width; ++i) {
      std::int32_t x;
      std::memcpy (&x, &c.data[i * c.point_step + c.fields[f].offset], 4);
      v.push_back (x);
    }
    return v;
  };
  EXPECT_EQ (las_integers (in), las_integers (out));
  // Every input dimension is in the output, with its values.
  for (const auto& f : in.fields) {
    EXPECT_GE (pcl::getFieldIndex (out, f.name), 0) << f.name;
    if (f.name == "red" || f.name == "classification") {
      std::vector<std::uint32_t> before, after;
      pcl_ext::io::getLabelField (in, f.name, before);
      pcl_ext::io::getLabelField (out, f.name, after);
      EXPECT_EQ (before, after) << f.name;
    }
  }
}

TEST_F (ClassifyVarianceApp, NamedFieldsAndRefusals)
{
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("first.pcd") + " -threads 2"), 0)
      << output_;
  // lv_class exists now: kept, the result goes to the next free name.
  EXPECT_EQ (run (path ("first.pcd") + " " + path ("second.pcd") + " -threads 2"), 0)
      << output_;
  EXPECT_NE (output_.find ("already has a field 'lv_class' (kept)"), std::string::npos)
      << output_;
  EXPECT_NE (output_.find ("goes to 'lv_class_2'"), std::string::npos) << output_;
  {
    pcl::PCLPointCloud2 first, second;
    ASSERT_EQ (pcl::io::loadPCDFile (path ("first.pcd"), first), 0);
    ASSERT_EQ (pcl::io::loadPCDFile (path ("second.pcd"), second), 0);
    std::vector<std::uint32_t> kept, before, again;
    ASSERT_TRUE (pcl_ext::io::getLabelField (first, "lv_class", before));
    ASSERT_TRUE (pcl_ext::io::getLabelField (second, "lv_class", kept));
    ASSERT_TRUE (pcl_ext::io::getLabelField (second, "lv_class_2", again));
    EXPECT_EQ (kept, before);  // the input's field untouched
    EXPECT_EQ (again, before); // the same cloud classified again
  }
  EXPECT_EQ (run (path ("first.pcd") + " " + path ("second.pcd") +
                  " -threads 2 -output_field lv_class"),
             0)
      << output_;
  // Output formats refused before any work.
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.laz")), 1);
  EXPECT_NE (output_.find ("writing LAZ is not supported"), std::string::npos)
      << output_;
  EXPECT_EQ (output_.find ("Loading"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("out.laz"));
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.las") + " -asprs"), 1);
  EXPECT_NE (output_.find ("no ASPRS class code"), std::string::npos) << output_;
  // A lying input: a PCD named .las is read as PCD; garbage named .las is refused.
  std::filesystem::copy_file (path ("cube.pcd"), path ("cube_pcd.las"));
  EXPECT_EQ (run (path ("cube_pcd.las") + " " + path ("lied.pcd") + " -threads 2"), 0)
      << output_;
  std::ofstream (path ("garbage.las")) << "LASF but far too short";
  EXPECT_EQ (run (path ("garbage.las") + " " + path ("garbage_out.las")), 1);
  EXPECT_NE (output_.find (path ("garbage.las")), std::string::npos) << output_;
  EXPECT_FALSE (exists ("garbage_out.las"));
}
