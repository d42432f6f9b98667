/*
 * Tests of the camera's framing: view directions, robust bounds, the ceiling and the
 * point spacing estimated from the points. No rendering.
 */
#include <pcl_ext/visualization/framing.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace pcl_ext::visualization;

namespace {
/** A grid of \a nx x \a ny points with spacing \a step in the plane z = \a z. */
void
addGrid (std::vector<Eigen::Vector3d>& points, int nx, int ny, double step, double z)
{
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      points.emplace_back (i * step, j * step, z);
}

/** A room 8 x 4 x 3 (floor and four walls, spacing 0.1), with a ceiling or not. */
std::vector<Eigen::Vector3d>
room (bool with_ceiling)
{
  std::vector<Eigen::Vector3d> points;
  addGrid (points, 81, 41, 0.1, 0.0);
  if (with_ceiling)
    addGrid (points, 81, 41, 0.1, 3.0);
  for (int i = 0; i <= 80; ++i)
    for (int k = 1; k < 30; ++k) {
      points.emplace_back (i * 0.1, 0.0, k * 0.1);
      points.emplace_back (i * 0.1, 4.0, k * 0.1);
    }
  for (int j = 1; j < 40; ++j)
    for (int k = 1; k < 30; ++k) {
      points.emplace_back (0.0, j * 0.1, k * 0.1);
      points.emplace_back (8.0, j * 0.1, k * 0.1);
    }
  return points;
}
} // namespace

TEST (Framing, ViewKindsParseAndPrint)
{
  for (const ViewKind kind : {ViewKind::Auto,
                              ViewKind::Top,
                              ViewKind::Side,
                              ViewKind::Oblique,
                              ViewKind::Sensor}) {
    ViewKind parsed = ViewKind::Auto;
    ASSERT_TRUE (parseViewKind (viewKindName (kind), parsed));
    EXPECT_EQ (parsed, kind);
  }
  ViewKind kind = ViewKind::Top;
  EXPECT_FALSE (parseViewKind ("below", kind));
  EXPECT_FALSE (parseViewKind ("", kind));
  EXPECT_EQ (kind, ViewKind::Top);
}

TEST (Framing, DirectionsFollowTheUpDirectionAndTheLongerAxis)
{
  const auto points = room (false); // 8 long along x, 4 along y
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant (std::nan (""));
  EXPECT_TRUE (viewDirection (points, ViewKind::Top, up, nan).isApprox (-up));
  const Eigen::Vector3d side = viewDirection (points, ViewKind::Side, up, nan);
  EXPECT_NEAR (side.z(), 0.0, 1e-9);
  EXPECT_NEAR (std::abs (side.y()), 1.0, 1e-6); // across the long x axis
  const Eigen::Vector3d oblique = viewDirection (points, ViewKind::Oblique, up, nan);
  EXPECT_NEAR (oblique.z(), -std::sin (35.0 * M_PI / 180.0), 1e-6); // from above
  // Without a sensor, the sensor view is the oblique one; with one, it looks from it.
  EXPECT_TRUE (viewDirection (points, ViewKind::Sensor, up, nan).isApprox (oblique));
  const Eigen::Vector3d sensor (4.0, -20.0, 1.5);
  const Eigen::Vector3d from = viewDirection (points, ViewKind::Sensor, up, sensor);
  EXPECT_GT (from.y(), 0.99);
  // Another up direction (a depth camera's -y) turns every view with it.
  EXPECT_TRUE (viewDirection (points, ViewKind::Top, -Eigen::Vector3d::UnitY(), nan)
                   .isApprox (Eigen::Vector3d::UnitY()));
}

TEST (Framing, WithoutASensorTheCameraStandsOnTheGroundsSide)
{
  // A facade 20 m long and 8 m high along x at y = 0, and the ground a scan of it saw
  // in front of it, on one side: the side and oblique views look from that side,
  // whichever it is. With the ground on both sides the fixed side is kept.
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant (std::nan (""));
  const auto scene = [] (double ground_side, bool both) {
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; j <= 40; ++j) {
        points.emplace_back (0.2 * i, 0.0, 0.2 * j);
        points.emplace_back (0.2 * i, ground_side * 0.25 * (j + 1), 0.0);
        if (both)
          points.emplace_back (0.2 * i, -ground_side * 0.25 * (j + 1), 0.0);
      }
    return points;
  };
  for (const double side : {-1.0, 1.0}) {
    const auto points = scene (side, false);
    // Looking from the ground's side towards the facade: along -side * y.
    EXPECT_GT (-side * viewDirection (points, ViewKind::Side, up, nan).y(), 0.99)
        << side;
    EXPECT_GT (-side * viewDirection (points, ViewKind::Oblique, up, nan).y(), 0.5)
        << side;
  }
  const auto symmetric = scene (1.0, true);
  // The fixed side: looking along (-1, -1.4, 0) made across the long axis, -y.
  EXPECT_LT (viewDirection (symmetric, ViewKind::Side, up, nan).y(), -0.99);
}

TEST (Framing, FarSparsePointsDoNotShrinkTheSubject)
{
  std::vector<Eigen::Vector3d> points;
  addGrid (points, 101, 51, 0.1, 0.0); // 10 x 5
  const std::size_t subject = points.size();
  for (int i = 0; i < 20; ++i) { // 0.8 % of the points, far away
    points.emplace_back (100.0 + i, -80.0, 5.0);
    points.emplace_back (60.0 + i, 2.0, 5.0); // level with the subject, far to its side
  }
  const Framing framing = frameRobustly (
      points, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(), 4.0 / 3.0, 0.05);
  // The 10 wide subject fills the width but the margins: 10 / 0.9.
  EXPECT_NEAR (2.0 * framing.half_width, 10.0 / 0.9, 1e-6);
  EXPECT_NEAR (framing.half_width / framing.half_height, 4.0 / 3.0, 1e-9);
  // Every subject point is inside the frame, off its edges by the margin.
  const Eigen::Vector3d right = framing.direction.cross (framing.up);
  for (std::size_t i = 0; i < subject; ++i) {
    const Eigen::Vector3d d = points[i] - framing.centre;
    EXPECT_LE (std::abs (d.dot (right)), 0.91 * framing.half_width);
    EXPECT_LE (std::abs (d.dot (framing.up)), 0.91 * framing.half_height);
  }
}

TEST (Framing, TailsOfTheSubjectStayInTheFrame)
{
  // A thin mast (1 % of the points) 3 high on a 10 x 10 plate, seen from the side in a
  // wide frame: within half the robust extent, so it is the subject's, not an outlier.
  std::vector<Eigen::Vector3d> points;
  addGrid (points, 100, 100, 0.1, 0.0);
  for (int k = 1; k <= 100; ++k)
    points.emplace_back (5.0, 5.0, 0.03 * k);
  const Framing framing = frameRobustly (
      points, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), 4.0, 0.05);
  EXPECT_GE (framing.centre.z() + 0.9 * framing.half_height, 3.0);
  EXPECT_LE (framing.centre.z() - 0.9 * framing.half_height, 0.0);
}

TEST (Framing, CeilingFoundAboveRoomsOnly)
{
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const double clip = estimateCeilingHeight (room (true), up);
  EXPECT_GT (clip, 2.85);
  EXPECT_LT (clip, 3.0);
  EXPECT_TRUE (std::isinf (estimateCeilingHeight (room (false), up)));
  // A flat terrain has no ceiling, nor has a terrain with a small roof.
  std::vector<Eigen::Vector3d> terrain;
  addGrid (terrain, 100, 100, 0.1, 0.0);
  EXPECT_TRUE (std::isinf (estimateCeilingHeight (terrain, up)));
  addGrid (terrain, 20, 20, 0.1, 3.0);
  EXPECT_TRUE (std::isinf (estimateCeilingHeight (terrain, up)));
}

TEST (Framing, SpacingOfAGrid)
{
  std::vector<Eigen::Vector3d> points;
  addGrid (points, 50, 40, 0.25, 0.0);
  for (auto& p : points)
    p += Eigen::Vector3d (485000.0, 5750000.0, 12.0); // georeferenced
  EXPECT_NEAR (estimateSpacing (points), 0.25, 1e-3);
  EXPECT_TRUE (std::isnan (estimateSpacing ({Eigen::Vector3d::Zero()})));
}

TEST (Framing, SideViewsLookFromTheSensorsSide)
{
  // A street 20 long (x) and 8 wide.
  std::vector<Eigen::Vector3d> points;
  addGrid (points, 201, 81, 0.1, 0.0);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // A sensor at y = -30 puts the camera on its side, looking towards +y; at y = +30,
  // towards -y.
  for (const double y : {-30.0, 30.0}) {
    const Eigen::Vector3d sensor (10.0, y, 1.0);
    EXPECT_GT (viewDirection (points, ViewKind::Side, up, sensor).y() * -y,
               0.99 * 30.0);
    EXPECT_GT (viewDirection (points, ViewKind::Oblique, up, sensor).y() * -y,
               0.5 * 30.0);
  }
}
