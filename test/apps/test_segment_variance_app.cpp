/*
 * pcl_ext_segment_variance run as a command: segments of a cube written into the
 * `label` field next to the input's own fields, the classifier's options beyond the
 * paper (-noise_sigma, -boundary_band, -boundary_band_fraction, -crease_angle,
 * -max_radius), usage errors, and no output on failure.
 */
#include "../app_result.h"
#include "../app_test.h"

#include "../features/analytic_clouds.h"

#include <pcl_ext/segmentation/surface_intersection_point.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace {
class SegmentVarianceApp : public pcl_ext::test::AppTest {
protected:
  SegmentVarianceApp() : AppTest (PCL_EXT_SEGMENT_VARIANCE_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // A closed unit cube with 1 mm noise, coloured, so the output must keep the
    // colours.
    const auto cube = pcl_ext::test::makeCube (1.0, 0.025, 0.001);
    pcl::PointCloud<pcl::PointXYZRGB> cloud;
    for (const auto& p : *cube.cloud) {
      pcl::PointXYZRGB q (p.x, p.y, p.z, 10, 20, 30);
      cloud.push_back (q);
    }
    crease_distance_ = cube.crease_distance;
    ASSERT_EQ (pcl::io::savePCDFileBinary (path ("cube.pcd"), cloud), 0);
  }

  std::vector<double> crease_distance_;
};
} // namespace

TEST_F (SegmentVarianceApp, CubeFacesAreLabelledSegments)
{
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -threads 2"), 0)
      << output_;
  EXPECT_NE (output_.find ("6 segments"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("[done, "), std::string::npos) << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> out;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("out.pcd"), "segment", out), 0);
  ASSERT_EQ (out.size(), crease_distance_.size());
  std::set<std::uint32_t> ids;
  for (std::size_t i = 0; i < out.size(); ++i) {
    ids.insert (out[i].label);
    EXPECT_EQ (out[i].r, 10); // the input's fields are kept
    EXPECT_EQ (out[i].b, 30);
    // Unsegmented points are the edge band (about a neighbourhood radius, 0.1 m here).
    if (out[i].label == 0)
      EXPECT_LT (crease_distance_[i], 0.12) << i;
  }
  EXPECT_EQ (ids, (std::set<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));

  // A minimum size above a face leaves nothing: an error, and no output written.
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("none.pcd") + " -min_size 5000"), 1);
  EXPECT_FALSE (exists ("none.pcd"));
}

TEST_F (SegmentVarianceApp, ClassifierOptionsReachTheSegmentation)
{
  // The options beyond the paper pass through to the classification: with the cube's 1
  // mm noise removed, the boundary band on and a 45 degree crease angle, the faces are
  // still the 6 segments; a radius cap below the k = 50 neighbourhood radius (about 0.1
  // m at this spacing) narrows the edge band the segments stop at (sections 2 and 3:
  // section 4 would re-integrate the band).
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("noise.pcd") +
                  " -threads 2 -noise_sigma 0.001 -boundary_band -crease_angle 45 "
                  "-no_reintegrate"),
             0)
      << output_;
  EXPECT_NE (output_.find ("6 segments"), std::string::npos) << output_;
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("capped.pcd") +
                  " -threads 2 -max_radius 0.06 -no_reintegrate"),
             0)
      << output_;
  EXPECT_NE (output_.find ("6 segments"), std::string::npos) << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> noise, capped;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("noise.pcd"), "segment", noise), 0);
  ASSERT_EQ (pcl_ext::test::loadResult (path ("capped.pcd"), "segment", capped), 0);
  ASSERT_EQ (capped.size(), crease_distance_.size());
  ASSERT_EQ (noise.size(), crease_distance_.size());
  std::size_t unsegmented = 0, far_capped = 0, far_uncapped = 0;
  for (std::size_t i = 0; i < capped.size(); ++i) {
    unsegmented += capped[i].label == 0;
    far_capped += capped[i].label == 0 && crease_distance_[i] > 0.07;
    far_uncapped += noise[i].label == 0 && crease_distance_[i] > 0.07;
  }
  EXPECT_GT (unsegmented, 0u);
  EXPECT_EQ (far_capped, 0u);
  EXPECT_GT (far_uncapped, 1000u);
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -noise_sigma -0.001"),
             1);
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -noise_sigma nan"), 1);
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -max_radius -1"), 1);
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -crease_angle 91"), 1);
  EXPECT_EQ (
      run (path ("cube.pcd") + " " + path ("out.pcd") + " -boundary_band_fraction -1"),
      1);
  EXPECT_FALSE (exists ("out.pcd"));
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("-noise_sigma"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-boundary_band"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-boundary_band_fraction"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-max_radius"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-crease_angle"), std::string::npos) << output_;
}

TEST_F (SegmentVarianceApp, RendersThePng)
{
  if (!std::getenv ("DISPLAY"))
    GTEST_SKIP() << "no X display for rendering";
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("out.pcd") + " -png " + path ("out.png")), 0)
      << output_;
  // PNG signature, then the IHDR chunk: width and height, big-endian, at bytes 16
  // and 20.
  std::ifstream png (path ("out.png"), std::ios::binary);
  unsigned char header[24] = {};
  ASSERT_TRUE (png.read (reinterpret_cast<char*> (header), sizeof (header)));
  EXPECT_EQ (header[1], 'P');
  EXPECT_EQ ((header[16] << 24) | (header[17] << 16) | (header[18] << 8) | header[19],
             1280);
  EXPECT_EQ ((header[20] << 24) | (header[21] << 16) | (header[22] << 8) | header[23],
             720);
  png.seekg (0, std::ios::end);
  EXPECT_GT (png.tellg(), 20000); // more than a blank image compresses to
  // Every view and the height clip are accepted.
  for (const char* view : {"top", "side", "oblique", "sensor"})
    EXPECT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -png " +
                    path ("out.png") + " -png_max_z none -view " + view),
               0)
        << view << ": " << output_;
}

TEST_F (SegmentVarianceApp, BadUsageAndInputFailWithoutOutput)
{
  const std::string io = path ("cube.pcd") + " " + path ("out.pcd");
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("-max_distance X"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("(default: 50)"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("(default: 0.0001)"), std::string::npos) << output_;
  EXPECT_EQ (run (""), 1);
  EXPECT_EQ (run (path ("cube.pcd")), 1);
  EXPECT_EQ (run (io + " -k 2"), 1);
  EXPECT_EQ (run (io + " -min_size 0"), 1);
  EXPECT_EQ (run (io + " -max_distance -1"), 1);
  EXPECT_EQ (run (io + " -max_distance_factor -1"), 1);
  EXPECT_EQ (run (io + " -variance_threshold -1"), 1);
  EXPECT_EQ (run (io + " -k"), 1);
  EXPECT_EQ (run (io + " -bogus 3"), 1);
  EXPECT_EQ (run (io + " -view below"), 1);
  EXPECT_NE (output_.find ("-view must be"), std::string::npos) << output_;
  EXPECT_EQ (run (io + " -png_max_z high"), 1);
  EXPECT_NE (output_.find ("-png_max_z must be"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("out.pcd"));
  EXPECT_EQ (run (path ("missing.pcd") + " " + path ("out.pcd")), 1);
  EXPECT_FALSE (exists ("out.pcd"));
  EXPECT_EQ (run (path ("cube.pcd") + " " + path ("no/such/folder/out.pcd")), 1);
  // A cloud without a surface point (collinear points): an error, no output.
  pcl::PointCloud<pcl::PointXYZ> line;
  for (int i = 0; i < 100; ++i)
    line.push_back (pcl::PointXYZ (0.01f * i, 0.f, 0.f));
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("line.pcd"), line), 0);
  EXPECT_EQ (run (path ("line.pcd") + " " + path ("out.pcd") + " -k 10"), 1);
  EXPECT_NE (output_.find ("No surface point"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("out.pcd"));
}

TEST_F (SegmentVarianceApp, IntersectionsLieOnTheCubeEdges)
{
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("plain.pcd") + " -no_reintegrate"), 0)
      << output_;
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -intersections " +
                  path ("edges.pcd")),
             0)
      << output_;
  EXPECT_NE (output_.find ("intersection points from"), std::string::npos) << output_;
  pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> edges;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("edges.pcd"), edges), 0);
  ASSERT_GT (edges.size(), 100u);
  // Distance to the nearest of the unit cube's 12 edges: two coordinates at 0 or 1.
  std::vector<double> distances;
  for (const auto& e : edges) {
    EXPECT_NE (e.segment_a, e.segment_b);
    EXPECT_TRUE (e.segment_a >= 1 && e.segment_a <= 6 && e.segment_b >= 1 &&
                 e.segment_b <= 6);
    const double p[3] = {e.x, e.y, e.z};
    double d[3], best = 1e9;
    for (int a = 0; a < 3; ++a)
      d[a] = std::min (std::abs (p[a]), std::abs (p[a] - 1.0));
    for (int a = 0; a < 3; ++a)
      best = std::min (best, std::hypot (d[a], d[(a + 1) % 3]));
    distances.push_back (best);
  }
  std::nth_element (
      distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  EXPECT_LT (distances[distances.size() / 2], 0.003); // 3 noise sigmas

  // Re-integration leaves fewer points without a segment, and never a wrong face: every
  // re-integrated point keeps to a face it lies on (within the 1 mm noise and the
  // band).
  pcl::PointCloud<pcl::PointXYZRGBL> plain, out;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("plain.pcd"), "segment", plain), 0);
  ASSERT_EQ (pcl_ext::test::loadResult (path ("out.pcd"), "segment", out), 0);
  ASSERT_EQ (plain.size(), out.size());
  std::size_t unsegmented_before = 0, unsegmented_after = 0, changed_segmented = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    unsegmented_before += plain[i].label == 0;
    unsegmented_after += out[i].label == 0;
    changed_segmented += plain[i].label != 0 && out[i].label != plain[i].label;
  }
  EXPECT_EQ (changed_segmented, 0u);
  EXPECT_LT (unsegmented_after, unsegmented_before / 2);

  // The re-integration is the default (out.pcd above); the paper's settings leave it
  // out, as -no_reintegrate does.
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("paper.pcd") + " -preset paper"), 0)
      << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> paper;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("paper.pcd"), "segment", paper), 0);
  ASSERT_EQ (paper.size(), plain.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < paper.size(); ++i)
    differ += paper[i].label != plain[i].label;
  EXPECT_EQ (differ, 0u);
}

TEST_F (SegmentVarianceApp, RendersTheIntersectionsOnThePng)
{
  if (!std::getenv ("DISPLAY"))
    GTEST_SKIP() << "no X display for rendering";
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("out.pcd") + " -intersections " +
                  path ("edges.pcd") + " -png " + path ("out.png")),
             0)
      << output_;
  std::ifstream png (path ("out.png"), std::ios::binary);
  unsigned char header[24] = {};
  ASSERT_TRUE (png.read (reinterpret_cast<char*> (header), sizeof (header)));
  EXPECT_EQ (header[1], 'P');
  EXPECT_EQ ((header[16] << 24) | (header[17] << 16) | (header[18] << 8) | header[19],
             1280);
  png.seekg (0, std::ios::end);
  EXPECT_GT (png.tellg(), 20000);
}

TEST_F (SegmentVarianceApp, BadIntersectionOptionsFailWithoutOutput)
{
  const std::string io = path ("cube.pcd") + " " + path ("out.pcd");
  EXPECT_EQ (run (io + " -intersections " + path ("edges.pcd") + " -parallel_angle 95"),
             1);
  EXPECT_EQ (run (io + " -intersections " + path ("edges.pcd") + " -parallel_angle -1"),
             1);
  EXPECT_EQ (run (io + " -intersections " + path ("no/such/folder/edges.pcd")), 1);
  EXPECT_FALSE (exists ("out.pcd"));
  EXPECT_FALSE (exists ("edges.pcd"));
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("-intersections"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("-reintegrate"), std::string::npos) << output_;
}

TEST_F (SegmentVarianceApp, LeftoverSegmentsOnlyAddToTheOthers)
{
  // The new segments among the points left out (the default) never change a point that
  // sections 3 and 4 segmented, and are numbered after their segments.
  // (The merging and the assignment after them are left out of both.)
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("kept.pcd") +
                  " -no_leftovers -no_merge -no_assign"),
             0)
      << output_;
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("grown.pcd") + " -no_merge -no_assign"), 0)
      << output_;
  EXPECT_NE (output_.find ("points without one"), std::string::npos) << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> kept, grown;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("kept.pcd"), "segment", kept), 0);
  ASSERT_EQ (pcl_ext::test::loadResult (path ("grown.pcd"), "segment", grown), 0);
  ASSERT_EQ (kept.size(), grown.size());
  std::uint32_t largest = 0;
  for (const auto& p : kept)
    largest = std::max (largest, p.label);
  EXPECT_EQ (largest, 6u); // the cube's faces
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i].label != 0)
      ASSERT_EQ (grown[i].label, kept[i].label) << i;
    else
      ASSERT_TRUE (grown[i].label == 0 || grown[i].label > largest) << i;
  }
  const std::string io = path ("cube.pcd") + " " + path ("out.pcd");
  EXPECT_EQ (run (io + " -leftovers -no_leftovers"), 1);
  EXPECT_EQ (run (io + " -leftover_angle 0"), 1);
  EXPECT_EQ (run (io + " -leftover_angle 95"), 1);
  EXPECT_EQ (run (io + " -leftover_angle nan"), 1);
  EXPECT_FALSE (exists ("out.pcd"));
}

TEST_F (SegmentVarianceApp, MergingAndAssignmentOnlyJoinSegmentsAndFillTheRest)
{
  // The last two default stages: segments are merged whole (two points together before
  // are together after) and a point left over only joins a segment; none loses one.
  ASSERT_EQ (
      run (path ("cube.pcd") + " " + path ("before.pcd") + " -no_merge -no_assign"), 0)
      << output_;
  ASSERT_EQ (run (path ("cube.pcd") + " " + path ("after.pcd")), 0) << output_;
  EXPECT_NE (output_.find ("merged into others"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("lie on a neighbouring segment's plane"), std::string::npos)
      << output_;
  pcl::PointCloud<pcl::PointXYZRGBL> before, after;
  ASSERT_EQ (pcl_ext::test::loadResult (path ("before.pcd"), "segment", before), 0);
  ASSERT_EQ (pcl_ext::test::loadResult (path ("after.pcd"), "segment", after), 0);
  ASSERT_EQ (before.size(), after.size());
  std::map<std::uint32_t, std::uint32_t> now;
  std::size_t segmented_before = 0, segmented_after = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    segmented_before += before[i].label != 0;
    segmented_after += after[i].label != 0;
    if (before[i].label == 0)
      continue;
    ASSERT_NE (after[i].label, 0u) << i;
    const auto it = now.emplace (before[i].label, after[i].label).first;
    ASSERT_EQ (it->second, after[i].label) << i;
  }
  EXPECT_GE (segmented_after, segmented_before);
  // The cube's six faces are six planes at right angles: nothing to merge.
  std::set<std::uint32_t> targets;
  for (const auto& p : now)
    targets.insert (p.second);
  EXPECT_EQ (targets.size(), now.size());
  const std::string io = path ("cube.pcd") + " " + path ("out.pcd");
  EXPECT_EQ (run (io + " -merge -no_merge"), 1);
  EXPECT_EQ (run (io + " -assign -no_assign"), 1);
  EXPECT_FALSE (exists ("out.pcd"));
  // -preset paper leaves both out; -merge and -assign add them to it.
  ASSERT_EQ (run (io + " -preset paper"), 0) << output_;
  EXPECT_EQ (output_.find ("merged into others"), std::string::npos) << output_;
  ASSERT_EQ (run (io + " -preset paper -merge -assign"), 0) << output_;
  EXPECT_NE (output_.find ("merged into others"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("lie on a neighbouring segment's plane"), std::string::npos)
      << output_;
}
