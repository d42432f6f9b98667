/*
 * RoofOutlinePlaneExtraction on a synthetic airborne cloud: two box buildings on
 * labelled ground, one of them cut by the cloud's edge. The walls found lie on the true
 * walls, the cut edge gets none, and bad input is refused without planes.
 */
#include "roof_outline_scene.h"

#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>

#include <pcl/common/point_tests.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

using namespace pcl_ext;

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Labels = pcl::PointCloud<pcl::Label>;
using pcl_ext::test::kBuilding;
using pcl_ext::test::kGround;
using pcl_ext::test::Scene;
using pcl_ext::test::twoBuildings;

std::vector<pcl::PointIndices>
extract (const Scene& s, RoofOutlinePlaneExtraction<pcl::PointXYZ>& walls)
{
  walls.setInputCloud (s.cloud);
  walls.setInputLabels (s.labels);
  std::vector<pcl::PointIndices> planes;
  walls.extract (planes);
  return planes;
}

// The true wall each found wall lies on (-1: none): in plan, its fitted normal within 3
// deg of the wall's, its centre within 0.3 m and every inlier within 0.5 m (two roof
// spacings: the outline band takes the second row of roof points too); tilted by 10 deg
// at most (the band is 0.3 m thick and the roof edge 0.4 m high, so the fit's tilt is
// loose, as in real data).
std::vector<int>
matchWalls (const Scene& s, const std::vector<pcl::PointIndices>& sets)
{
  std::vector<ScanPlane> planes;
  EXPECT_TRUE (fitScanPlanes (*s.cloud, sets, ScanViewpoints(), planes));
  EXPECT_EQ (planes.size(), sets.size());
  std::vector<int> match;
  for (const auto& plane : planes) {
    int found = -1;
    for (std::size_t w = 0; w < s.walls.size() && found < 0; ++w) {
      const Eigen::Vector2d n = plane.normal.head<2>().normalized();
      if (std::abs (plane.normal.z()) > std::sin (10.0 * M_PI / 180.0) ||
          std::abs (n.dot (s.walls[w].normal())) < std::cos (3.0 * M_PI / 180.0) ||
          s.walls[w].distance (plane.centroid.head<2>()) > 0.3)
        continue;
      bool on = true;
      for (const auto i : plane.inliers.indices)
        on = on && s.walls[w].distance (
                       (*s.cloud)[i].getVector3fMap().head<2>().cast<double>()) <= 0.5;
      if (on)
        found = static_cast<int> (w);
    }
    match.push_back (found);
  }
  return match;
}
} // namespace

TEST (RoofOutlinePlaneExtraction, WallsLieOnTheTrueWallsAndNoneOnTheCutEdge)
{
  const Scene s = twoBuildings();
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
  walls.setGroundLabel (kGround);
  walls.setBuildingLabel (kBuilding);
  const auto planes = extract (s, walls);
  ASSERT_GE (planes.size(), 1u + s.walls.size());

  // The ground first: ground points only, most of them.
  std::size_t ground_points = 0;
  for (const auto& l : *s.labels)
    ground_points += l.label == kGround;
  EXPECT_GE (planes[0].indices.size(), ground_points * 99 / 100);
  for (const auto i : planes[0].indices)
    ASSERT_EQ ((*s.labels)[i].label, kGround);

  // Every other set is a wall on a true wall, of building points; every true wall is
  // found.
  const std::vector<pcl::PointIndices> wall_sets (planes.begin() + 1, planes.end());
  const auto match = matchWalls (s, wall_sets);
  std::vector<int> found (s.walls.size(), 0);
  for (std::size_t w = 0; w < wall_sets.size(); ++w) {
    EXPECT_GE (match[w], 0) << "wall " << w << " (" << wall_sets[w].indices.size()
                            << " points) lies on no true wall";
    if (match[w] >= 0)
      ++found[match[w]];
    EXPECT_GE (wall_sets[w].indices.size(), 15u);
    for (const auto i : wall_sets[w].indices)
      ASSERT_EQ ((*s.labels)[i].label, kBuilding);
  }
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    EXPECT_EQ (found[w], 1) << "true wall " << w;

  // Nothing on the cut edge: no building point within 1 m of x = 30 is in a wall across
  // it.
  for (const auto& set : wall_sets) {
    std::size_t near_cut = 0;
    for (const auto i : set.indices)
      near_cut += (*s.cloud)[i].x > 29.f;
    EXPECT_LT (near_cut, set.indices.size() / 2) << "a wall along the cloud's edge";
  }
}

TEST (RoofOutlinePlaneExtraction, ParametersShapeTheOutput)
{
  const Scene s = twoBuildings();
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
  const auto all = extract (s, walls);

  // The same planes on every run, and from another seed the same walls.
  RoofOutlinePlaneExtraction<pcl::PointXYZ> again;
  const auto repeated = extract (s, again);
  ASSERT_EQ (repeated.size(), all.size());
  for (std::size_t p = 0; p < all.size(); ++p)
    EXPECT_EQ (repeated[p].indices, all[p].indices);
  RoofOutlinePlaneExtraction<pcl::PointXYZ> seeded;
  seeded.setSeed (99);
  EXPECT_EQ (seeded.getSeed(), 99u);
  const auto other = extract (s, seeded);
  EXPECT_EQ (other.size(), all.size());
  for (const int m :
       matchWalls (s, std::vector<pcl::PointIndices> (other.begin() + 1, other.end())))
    EXPECT_GE (m, 0);

  // No ground plane; one wall per building.
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls_only;
  walls_only.setExtractGround (false);
  EXPECT_EQ (extract (s, walls_only).size(), all.size() - 1);
  RoofOutlinePlaneExtraction<pcl::PointXYZ> one_each;
  one_each.setMaxWallsPerBuilding (1);
  EXPECT_EQ (extract (s, one_each).size(), 3u);

  // A minimum above every wall leaves the ground alone.
  RoofOutlinePlaneExtraction<pcl::PointXYZ> strict;
  strict.setMinWallPoints (100);
  EXPECT_EQ (extract (s, strict).size(), 1u);

  // Labels the other way round: the roofs are "ground", the ground "building"; the
  // ground is one big cluster whose outline is the holes the roofs leave, with roof
  // points beyond. Whatever it finds, it must not crash and must keep to the new
  // building label.
  RoofOutlinePlaneExtraction<pcl::PointXYZ> swapped;
  swapped.setGroundLabel (kBuilding);
  swapped.setBuildingLabel (kGround);
  const auto inverted = extract (s, swapped);
  for (std::size_t p = 1; p < inverted.size(); ++p)
    for (const auto i : inverted[p].indices)
      ASSERT_EQ ((*s.labels)[i].label, kGround);
}

TEST (RoofOutlinePlaneExtraction, NaNPointsAreLeftOut)
{
  Scene s = twoBuildings();
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
  const std::size_t clean = extract (s, walls).size();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < s.cloud->size(); i += 37)
    (*s.cloud)[i].x = nan;
  for (std::size_t i = 11; i < s.cloud->size(); i += 53)
    (*s.cloud)[i].z = std::numeric_limits<float>::infinity();
  s.cloud->is_dense = false;
  const auto planes = extract (s, walls);
  EXPECT_EQ (planes.size(), clean);
  for (const auto& set : planes)
    for (const auto i : set.indices)
      ASSERT_TRUE (pcl::isFinite ((*s.cloud)[i])) << i;
  for (const int m : matchWalls (
           s, std::vector<pcl::PointIndices> (planes.begin() + 1, planes.end())))
    EXPECT_GE (m, 0);
}

TEST (RoofOutlinePlaneExtraction, LongestStretchSplitsAtGaps)
{
  Cloud cloud;
  // Along y at x = 1: 10 points 0.5 m apart, a 3 m gap, then 20 points.
  for (int i = 0; i < 10; ++i)
    cloud.emplace_back (1.f, 0.5f * i, 0.f);
  for (int i = 0; i < 20; ++i)
    cloud.emplace_back (1.f, 7.5f + 0.5f * i, 0.f);
  pcl::Indices all (cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<int> (all.size() - 1 - i); // any order
  const pcl::Indices stretch =
      longestWallStretch (cloud, all, Eigen::Vector3f::UnitX(), 1.5f);
  ASSERT_EQ (stretch.size(), 20u);
  EXPECT_EQ (stretch.front(), 10);
  EXPECT_EQ (stretch.back(), 29);
  EXPECT_EQ (longestWallStretch (cloud, all, Eigen::Vector3f::UnitX(), 4.f).size(),
             30u);
  EXPECT_TRUE (
      longestWallStretch (cloud, pcl::Indices(), Eigen::Vector3f::UnitX(), 1.5f)
          .empty());
}

TEST (RoofOutlinePlaneExtraction, BadInputIsRefusedWithoutPlanes)
{
  const Scene s = twoBuildings();
  const auto refused = [] (RoofOutlinePlaneExtraction<pcl::PointXYZ>& walls,
                           const char* what) {
    std::vector<pcl::PointIndices> planes (1);
    ::testing::internal::CaptureStderr();
    walls.extract (planes);
    const std::string log = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE (planes.empty()) << what;
    EXPECT_NE (log.find ("[pcl_ext::RoofOutlinePlaneExtraction::extract]"),
               std::string::npos)
        << what << ": " << log;
  };
  const auto ready = [&s] () {
    RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
    walls.setInputCloud (s.cloud);
    walls.setInputLabels (s.labels);
    return walls;
  };

  RoofOutlinePlaneExtraction<pcl::PointXYZ> none;
  refused (none, "no input");
  auto unlabelled = ready();
  unlabelled.setInputLabels (nullptr);
  refused (unlabelled, "no labels");
  auto short_labels = ready();
  short_labels.setInputLabels (
      Labels::Ptr (new Labels (*s.labels, pcl::Indices{0, 1, 2})));
  refused (short_labels, "fewer labels than points");

  auto empty = ready();
  empty.setInputCloud (Cloud::Ptr (new Cloud));
  empty.setInputLabels (Labels::Ptr (new Labels));
  refused (empty, "empty cloud");
  Cloud::Ptr all_nan (new Cloud (*s.cloud));
  for (auto& p : *all_nan)
    p.y = std::numeric_limits<float>::quiet_NaN();
  auto nan = ready();
  nan.setInputCloud (all_nan);
  refused (nan, "all NaN");
  auto no_building = ready();
  no_building.setBuildingLabel (17);
  refused (no_building, "no building points");
  auto out_of_range = ready();
  out_of_range.setIndices (
      pcl::IndicesPtr (new pcl::Indices{0, 1, static_cast<int> (s.cloud->size())}));
  refused (out_of_range, "index out of range");

  const double nan_value = std::numeric_limits<double>::quiet_NaN();
  using Setter = std::function<void (RoofOutlinePlaneExtraction<pcl::PointXYZ>&)>;
  const std::vector<std::pair<const char*, Setter>> bad = {
      {"same labels", [] (auto& w) { w.setGroundLabel (6); }},
      {"ground distance 0", [] (auto& w) { w.setGroundDistanceThreshold (0.0); }},
      {"ground distance NaN",
       [&] (auto& w) { w.setGroundDistanceThreshold (nan_value); }},
      {"building tolerance -1", [] (auto& w) { w.setBuildingTolerance (-1.0); }},
      {"building points 0", [] (auto& w) { w.setMinBuildingPoints (0); }},
      {"outline neighbours 2", [] (auto& w) { w.setOutlineNeighbours (2); }},
      {"open side inf",
       [] (auto& w) {
         w.setOpenSideDistance (std::numeric_limits<double>::infinity());
       }},
      {"outline band -0.3", [] (auto& w) { w.setOutlineBand (-0.3); }},
      {"outline band NaN", [&] (auto& w) { w.setOutlineBand (nan_value); }},
      {"angle 0", [] (auto& w) { w.setAngleTolerance (0.0); }},
      {"angle 90", [] (auto& w) { w.setAngleTolerance (90.0); }},
      {"angle NaN", [&] (auto& w) { w.setAngleTolerance (nan_value); }},
      {"gap 0", [] (auto& w) { w.setMaxGap (0.0); }},
      {"wall points 2", [] (auto& w) { w.setMinWallPoints (2); }},
      {"walls -1", [] (auto& w) { w.setMaxWallsPerBuilding (-1); }},
      {"iterations 0", [] (auto& w) { w.setMaxIterations (0); }}};
  for (const auto& [what, set] : bad) {
    auto walls = ready();
    set (walls);
    refused (walls, what);
  }

  // Only roofs, nothing around them: no outline, so only the (absent) ground; not an
  // error.
  Cloud::Ptr roofs (new Cloud);
  Labels::Ptr roof_labels (new Labels);
  for (std::size_t i = 0; i < s.cloud->size(); ++i)
    if ((*s.labels)[i].label == kBuilding) {
      roofs->push_back ((*s.cloud)[i]);
      roof_labels->push_back ((*s.labels)[i]);
    }
  RoofOutlinePlaneExtraction<pcl::PointXYZ> roofs_only;
  roofs_only.setInputCloud (roofs);
  roofs_only.setInputLabels (roof_labels);
  std::vector<pcl::PointIndices> planes;
  ::testing::internal::CaptureStderr();
  roofs_only.extract (planes);
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE (planes.empty());
  EXPECT_EQ (log.find ("[pcl_ext::"), std::string::npos) << "not an error: " << log;

  // As a PlaneExtractor, on a cloud the labels do not fit: refused.
  auto walls = ready();
  std::vector<pcl::PointIndices> sets;
  ::testing::internal::CaptureStderr();
  walls.asExtractor() (roofs, nullptr, sets);
  const std::string refusal = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE (sets.empty());
  EXPECT_NE (refusal.find ("[pcl_ext::RoofOutlinePlaneExtraction::extract]"),
             std::string::npos)
      << refusal;
}

// As a PlaneExtractor with indices (how PlaneMatchingRegistration passes its
// setIndices): the walls come from the indexed points only and index the whole cloud,
// whose labels still fit. The scene is followed by a copy of itself 300 m away:
// indexing either copy gives the walls of the scene alone, shifted by the copy's
// offset.
TEST (RoofOutlinePlaneExtraction, AsExtractorTakesItsWallsAmongTheIndices)
{
  const Scene s = twoBuildings();
  RoofOutlinePlaneExtraction<pcl::PointXYZ> alone;
  const std::vector<pcl::PointIndices> expected = extract (s, alone);
  ASSERT_FALSE (expected.empty());

  const std::size_t n = s.cloud->size();
  Cloud::Ptr doubled (new Cloud (*s.cloud));
  Labels::Ptr labels (new Labels (*s.labels));
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = (*s.cloud)[i];
    doubled->emplace_back (p.x + 300.f, p.y, p.z);
    labels->push_back ((*s.labels)[i]);
  }
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
  walls.setInputLabels (labels);
  const auto extractor = walls.asExtractor();
  for (const std::size_t offset : {std::size_t (0), n}) {
    pcl::IndicesPtr copy (new pcl::Indices (n));
    for (std::size_t i = 0; i < n; ++i)
      (*copy)[i] = static_cast<pcl::index_t> (offset + i);
    std::vector<pcl::PointIndices> sets;
    extractor (doubled, copy, sets);
    ASSERT_EQ (sets.size(), expected.size()) << "copy at " << offset;
    for (std::size_t w = 0; w < sets.size(); ++w) {
      ASSERT_EQ (sets[w].indices.size(), expected[w].indices.size());
      for (std::size_t k = 0; k < sets[w].indices.size(); ++k)
        EXPECT_EQ (static_cast<std::size_t> (sets[w].indices[k]),
                   offset + expected[w].indices[k]);
    }
  }
  // Without indices: every point, so both copies' walls.
  std::vector<pcl::PointIndices> both;
  extractor (doubled, nullptr, both);
  EXPECT_GT (both.size(), expected.size());
}
