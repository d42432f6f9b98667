/*
 * FootprintCoverage: which points a pose puts inside the footprints (holes are
 * outside, every part of a multipolygon counts), in the map's local frame.
 */
#include <pcl_ext/registration/footprint_coverage.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace pcl_ext;

namespace {
// A 10 x 10 m building at (100, 200) with a 4 x 4 m courtyard, and a 5 x 5 m second
// part 20 m east (one MULTIPOLYGON), and a separate 2 x 2 m shed.
std::vector<io::Footprint>
footprints ()
{
  io::Footprint building;
  building.polygons.resize (2);
  building.polygons[0].outer = {{100, 200}, {110, 200}, {110, 210}, {100, 210}};
  building.polygons[0].holes = {{{103, 203}, {103, 207}, {107, 207}, {107, 203}}};
  building.polygons[1].outer = {{130, 200}, {135, 200}, {135, 205}, {130, 205}};
  io::Footprint shed;
  shed.polygons.resize (1);
  shed.polygons[0].outer = {{90, 190}, {92, 190}, {92, 192}, {90, 192}};
  return {building, shed};
}
} // namespace

TEST (FootprintCoverage, InsideHonoursHolesAndParts)
{
  const FootprintCoverage map (footprints(), Eigen::Vector3d (100, 200, 50));
  ASSERT_FALSE (map.empty());
  EXPECT_TRUE (map.inside ({1, 1}));   // the building's wing
  EXPECT_FALSE (map.inside ({5, 5}));  // its courtyard
  EXPECT_TRUE (map.inside ({8, 5}));   // beside the courtyard
  EXPECT_TRUE (map.inside ({32, 2}));  // the second part
  EXPECT_FALSE (map.inside ({20, 2})); // between the parts
  EXPECT_TRUE (map.inside ({-9, -9})); // the shed
  EXPECT_FALSE (map.inside ({-5, -5}));
  EXPECT_FALSE (map.inside ({1, 11}));
  EXPECT_TRUE (FootprintCoverage ({}, Eigen::Vector3d::Zero()).empty());
}

// Points on a 1 m grid over the building's west wing strip x in [0, 3], y in [0, 10]
// (local): all inside as they are; shifted 2 m east, the columns at x 3.5 and 4.5 fall
// into the courtyard for y 3.5-6.5 (8 points); none turned half a turn about the
// strip's corner.
TEST (FootprintCoverage, ShareFollowsThePose)
{
  const FootprintCoverage map (footprints(), Eigen::Vector3d (100, 200, 0));
  std::vector<Eigen::Vector3d> points;
  for (double x = 0.5; x < 3.0; x += 1.0)
    for (double y = 0.5; y < 10.0; y += 1.0)
      points.emplace_back (x, y, 7.0);
  ASSERT_EQ (points.size(), 30u);
  EXPECT_DOUBLE_EQ (map.share (points, Eigen::Matrix4d::Identity()), 1.0);
  Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
  shift (0, 3) = 2.0;
  EXPECT_DOUBLE_EQ (map.share (points, shift), 22.0 / 30.0);
  Eigen::Matrix4d turn = Eigen::Matrix4d::Identity();
  turn.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_DOUBLE_EQ (map.share (points, turn), 0.0);
  EXPECT_DOUBLE_EQ (map.share ({}, turn), 0.0);
}

// A city's worth of footprints: 100 x 100 squares of 5 m every 10 m and one 2 km x 50 m
// strip across them all (a dyke), looked up through the grid: every square's centre is
// inside, every gap outside except on the strip.
TEST (FootprintCoverage, ManyFootprintsOfManySizes)
{
  std::vector<io::Footprint> footprints;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) {
      io::Footprint f;
      f.polygons.resize (1);
      const double x = 10.0 * i, y = 10.0 * j;
      f.polygons[0].outer = {{x, y}, {x + 5, y}, {x + 5, y + 5}, {x, y + 5}};
      footprints.push_back (f);
    }
  io::Footprint strip;
  strip.polygons.resize (1);
  strip.polygons[0].outer = {{-500, 402}, {1500, 402}, {1500, 452}, {-500, 452}};
  footprints.push_back (strip);
  const FootprintCoverage map (footprints, Eigen::Vector3d::Zero());
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) {
      const double x = 10.0 * i, y = 10.0 * j;
      ASSERT_TRUE (map.inside ({x + 2.5, y + 2.5})) << i << " " << j;
      const bool on_strip = y + 7.5 > 402.0 && y + 7.5 < 452.0;
      ASSERT_EQ (map.inside ({x + 7.5, y + 7.5}), on_strip) << i << " " << j;
    }
  EXPECT_TRUE (map.inside ({-400, 420}));
  EXPECT_TRUE (map.inside ({1400, 420}));
  EXPECT_FALSE (map.inside ({-400, 400}));
  EXPECT_FALSE (map.inside ({5000, 5000}));
}
