/*
 * Tests of the map planes inferred from footprints (Khoshelham & Gorte 2009,
 * section 3.1).
 */
#include "plane_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

using namespace pcl_ext;

namespace {
bool
inside (const io::Ring2d& ring, const Eigen::Vector2d& p)
{
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y() > p.y()) != (ring[j].y() > p.y()) &&
        p.x() < (ring[j].x() - ring[i].x()) * (p.y() - ring[i].y()) /
                        (ring[j].y() - ring[i].y()) +
                    ring[i].x())
      in = !in;
  return in;
}
} // namespace

TEST (MapPlanes, HShapeWallsFaceOutwardWithSignedOffsets)
{
  std::vector<MapPlane> planes;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), planes));
  ASSERT_EQ (planes.size(), 13u); // floor + 12 walls
  EXPECT_TRUE (planes[0].isFloor());
  EXPECT_EQ (planes[0].normal, Eigen::Vector3d::UnitZ());
  EXPECT_EQ (planes[0].d, 0.0);
  for (std::size_t i = 1; i < planes.size(); ++i) {
    const MapPlane& w = planes[i];
    EXPECT_NEAR (w.normal.norm(), 1.0, 1e-12);
    EXPECT_EQ (w.normal.z(), 0.0);
    // Eq. 2 with its sign: both edge ends lie on the plane.
    EXPECT_NEAR (
        w.signedDistance (Eigen::Vector3d (w.start.x(), w.start.y(), 3.0)), 0.0, 1e-12);
    EXPECT_NEAR (
        w.signedDistance (Eigen::Vector3d (w.end.x(), w.end.y(), 0.0)), 0.0, 1e-12);
    const Eigen::Vector2d mid = 0.5 * (w.start + w.end);
    EXPECT_FALSE (inside (test::hShape(), mid + 0.1 * w.normal.head<2>()))
        << "wall " << i;
    EXPECT_TRUE (inside (test::hShape(), mid - 0.1 * w.normal.head<2>()))
        << "wall " << i;
  }
  // n . x + d = 0. Edge (0,0)-(12,0): n = (0, -1, 0), d = 0; edge (40,0)-(40,30):
  // n = (1, 0, 0), d = -40.
  EXPECT_TRUE (planes[1].normal.isApprox (Eigen::Vector3d (0, -1, 0)));
  EXPECT_NEAR (planes[6].d, -40.0, 1e-12);
  EXPECT_TRUE (planes[6].normal.isApprox (Eigen::Vector3d (1, 0, 0)));
}

TEST (MapPlanes, ClockwiseRingAndLargeCoordinatesGiveTheSamePlanes)
{
  std::vector<MapPlane> reference, reversed, shifted;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), reference));
  io::Ring2d cw = test::hShape();
  std::reverse (cw.begin(), cw.end());
  ASSERT_TRUE (computeMapPlanes (cw, MapPlaneParameters(), reversed));
  ASSERT_EQ (reversed.size(), reference.size());
  for (const auto& p : reference)
    EXPECT_TRUE (
        std::any_of (reversed.begin(), reversed.end(), [&] (const MapPlane& q) {
          return p.normal.isApprox (q.normal) && std::abs (p.d - q.d) < 1e-12;
        }));

  // Georeferenced (RD New) coordinates: the local origin removes them exactly.
  io::Footprint footprint;
  footprint.polygons.resize (1);
  for (const auto& v : test::hShape())
    footprint.polygons[0].outer.push_back (v + Eigen::Vector2d (121350.0, 487230.0));
  Eigen::Vector3d origin;
  ASSERT_TRUE (chooseLocalOrigin ({footprint}, origin));
  EXPECT_EQ (origin, Eigen::Vector3d (121370.0, 487245.0, 0.0));
  MapPlaneParameters parameters;
  parameters.origin = origin;
  ASSERT_TRUE (computeMapPlanes ({footprint}, parameters, shifted));
  ASSERT_EQ (shifted.size(), reference.size());
  for (std::size_t i = 1; i < shifted.size(); ++i) {
    const Eigen::Vector3d p (
        shifted[i].start.x() + 20.0, shifted[i].start.y() + 15.0, 0.0);
    EXPECT_NEAR (reference[i].signedDistance (p), 0.0, 1e-9);
    EXPECT_NEAR (reference[i].d - shifted[i].d +
                     reference[i].normal.dot (Eigen::Vector3d (20, 15, 0)),
                 0.0,
                 1e-9);
  }
}

TEST (MapPlanes, ReadsFootprintFiles)
{
  std::vector<io::Footprint> footprints;
  io::loadFootprints (std::string (PCL_EXT_TEST_DATA_DIR) + "/footprints.wkt",
                      footprints);
  std::vector<MapPlane> planes;
  ASSERT_TRUE (computeMapPlanes (footprints, MapPlaneParameters(), planes));
  std::size_t edges = 0;
  for (const auto& f : footprints)
    for (const auto& p : f.polygons) {
      edges += p.outer.size();
      for (const auto& h : p.holes)
        edges += h.size();
    }
  EXPECT_EQ (planes.size(), edges + 1);
}

TEST (MapPlanes, BadInputIsRejected)
{
  std::vector<MapPlane> planes (3);
  EXPECT_FALSE (
      computeMapPlanes (std::vector<io::Footprint>(), MapPlaneParameters(), planes));
  EXPECT_TRUE (planes.empty());
  EXPECT_FALSE (
      computeMapPlanes (io::Ring2d{{0, 0}, {1, 0}}, MapPlaneParameters(), planes));
  EXPECT_FALSE (computeMapPlanes (
      io::Ring2d{{0, 0}, {4, 0}, {std::numeric_limits<double>::quiet_NaN(), 3}},
      MapPlaneParameters(),
      planes));
  const io::Ring2d bowtie = {{0, 0}, {4, 4}, {4, 0}, {0, 4}};
  EXPECT_TRUE (isSelfIntersecting (bowtie));
  EXPECT_FALSE (computeMapPlanes (bowtie, MapPlaneParameters(), planes));
  EXPECT_FALSE (isSelfIntersecting (test::hShape()));
  MapPlaneParameters bad;
  bad.wall_height = -1.0;
  EXPECT_FALSE (computeMapPlanes (test::hShape(), bad, planes));
  bad = MapPlaneParameters();
  bad.origin.x() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE (computeMapPlanes (test::hShape(), bad, planes));
  EXPECT_TRUE (planes.empty());
}

// Footprints far from the scan are left out of the map; when none is near, all stay.
TEST (MapPlanes, FootprintsNearTheScanOnly)
{
  auto square = [] (double x, double y, const std::string& id) {
    io::Footprint f;
    f.id = id;
    io::FootprintPolygon polygon;
    polygon.outer = {{x, y}, {x + 10, y}, {x + 10, y + 10}, {x, y + 10}};
    f.polygons.push_back (polygon);
    return f;
  };
  const std::vector<io::Footprint> all{
      square (0, 0, "a"), square (55, 0, "b"), square (500, 500, "c")};
  const Eigen::AlignedBox3d scan (Eigen::Vector3d (-5, -5, 0),
                                  Eigen::Vector3d (50, 20, 10));
  std::vector<io::Footprint> near;
  ASSERT_TRUE (selectFootprintsNearScan (all, scan, 0.0, near));
  ASSERT_EQ (near.size(), 1u);
  EXPECT_EQ (near[0].id, "a");
  ASSERT_TRUE (selectFootprintsNearScan (all, scan, 5.0, near));
  ASSERT_EQ (near.size(), 2u);
  EXPECT_EQ (near[1].id, "b");
  // A scan that is not in map coordinates: nothing near, everything kept.
  const Eigen::AlignedBox3d elsewhere (Eigen::Vector3d (-900, -900, 0),
                                       Eigen::Vector3d (-850, -850, 10));
  EXPECT_FALSE (selectFootprintsNearScan (all, elsewhere, 5.0, near));
  EXPECT_EQ (near.size(), 3u);
}
