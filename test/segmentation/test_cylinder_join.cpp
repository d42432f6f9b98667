/*
 * Tests of the cylinder join on plain coordinates (cylinder_join.h): when two cylinders
 * continue one another, the joined labels of a pipe cut into two segments, and the join
 * over segments loaded one at a time.
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/cylinder_join.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace pcl_ext::cylinder_join;
using pcl_ext::cylinders::Cylinder;

namespace {
Cylinder
cylinder (const Eigen::Vector3d& point,
          const Eigen::Vector3d& axis,
          double radius,
          double half_length)
{
  Cylinder c;
  c.point = point;
  c.axis = axis.normalized();
  c.radius = radius;
  c.half_length = half_length;
  return c;
}

/** Points of a pipe of radius 0.1 along x at z = 1 seen from below (half its
 * circumference), from x = \a start for \a length, on a 2 cm grid with 3 mm of noise;
 * appended to \a xyz, their positions to \a segment. */
void
addPipe (double start,
         double length,
         std::mt19937& rng,
         std::vector<Eigen::Vector3d>& xyz,
         std::vector<std::uint32_t>& segment)
{
  std::normal_distribution<double> noise (0.0, 0.003);
  const int along = static_cast<int> (std::ceil (length / 0.02));
  const int across = static_cast<int> (std::ceil (M_PI * 0.1 / 0.02));
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const double x = start + (i + 0.5) * length / along;
      const double theta = -0.5 * M_PI + (j + 0.5) * M_PI / across;
      const double r = 0.1 + noise (rng);
      segment.push_back (static_cast<std::uint32_t> (xyz.size()));
      xyz.emplace_back (x, r * std::sin (theta), 1.0 - r * std::cos (theta));
    }
}
/** Points of a pipe of radius 0.25 along x at z = 1, from x = \a start for \a length,
 * over the arc of \a arc radians centred on its underside, on a grid of \a spacing with
 * 5 mm of noise along the radius; appended to \a xyz, their positions to \a segment. */
void
addWidePipe (double start,
             double length,
             double arc,
             double spacing,
             pcl_ext::RandomStream& rng,
             std::vector<Eigen::Vector3d>& xyz,
             std::vector<std::uint32_t>& segment)
{
  const int along = static_cast<int> (std::ceil (length / spacing));
  const int across = static_cast<int> (std::ceil (arc * 0.25 / spacing));
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const double x = start + (i + 0.5) * length / along;
      const double theta = -0.5 * arc + (j + 0.5) * arc / across;
      const double r = 0.25 + 0.005 * rng.gaussian();
      segment.push_back (static_cast<std::uint32_t> (xyz.size()));
      xyz.emplace_back (x, r * std::sin (theta), 1.0 - r * std::cos (theta));
    }
}
} // namespace

TEST (CylinderJoin, ContinuesAlongOneAxisAndAroundAnElbow)
{
  const JoinParameters
      p; // gap 2, 5 degrees for a run, 30 for an elbow, radii within 30 %
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  // One run: a covers z in [-1, 1], b z in [2, 4], a gap of 1.
  const Cylinder a = cylinder (Eigen::Vector3d::Zero(), z, 0.2, 1.0);
  EXPECT_TRUE (continues (a, cylinder (Eigen::Vector3d (0, 0, 3), z, 0.2, 1.0), p));
  EXPECT_TRUE (continues (cylinder (Eigen::Vector3d (0, 0, 3), z, 0.2, 1.0), a, p));
  JoinParameters short_gap;
  short_gap.max_gap = 0.5;
  EXPECT_FALSE (
      continues (a, cylinder (Eigen::Vector3d (0, 0, 3), z, 0.2, 1.0), short_gap));
  // Radii: 0.05 apart is within 30 % of 0.25, 0.1 apart is more than 30 % of 0.3.
  EXPECT_TRUE (continues (a, cylinder (Eigen::Vector3d (0, 0, 3), z, 0.25, 1.0), p));
  EXPECT_FALSE (continues (a, cylinder (Eigen::Vector3d (0, 0, 3), z, 0.3, 1.0), p));
  // The axis moved across by 0.2, farther than 0.3 radii plus the tolerance.
  EXPECT_FALSE (continues (a, cylinder (Eigen::Vector3d (0.2, 0, 3), z, 0.2, 1.0), p));
  // Turned by 15 degrees: neither one run nor an elbow.
  const Eigen::Vector3d turned (std::sin (M_PI / 12), 0, std::cos (M_PI / 12));
  EXPECT_FALSE (
      continues (a, cylinder (Eigen::Vector3d (0, 0, 3), turned, 0.2, 1.0), p));
  // An elbow: the axes meet at (0, 0, 1.5), half a metre beyond the end of each leg.
  EXPECT_TRUE (continues (a, cylinder (Eigen::Vector3d (1.5, 0, 1.5), x, 0.2, 1.0), p));
  // The second leg passes 0.5 m beside the first axis: two pipes crossing.
  EXPECT_FALSE (
      continues (a, cylinder (Eigen::Vector3d (1.5, 0.5, 1.5), x, 0.2, 1.0), p));
  // The axes meet 2.5 m beyond the second leg's end, farther than the longest gap.
  EXPECT_FALSE (
      continues (a, cylinder (Eigen::Vector3d (3.5, 0, 1.5), x, 0.2, 1.0), p));
}

TEST (CylinderJoin, ParametersAreChecked)
{
  EXPECT_TRUE (validParameters (JoinParameters()));
  for (int k = 0; k < 7; ++k) {
    JoinParameters p;
    if (k == 0)
      p.threads = 0;
    if (k == 1)
      p.max_gap = -1.0;
    if (k == 2)
      p.min_elbow_angle = p.max_axis_angle;
    if (k == 3)
      p.max_radius_difference = 1.0;
    if (k == 4)
      p.whole_segment_fraction = 1.5;
    if (k == 5)
      p.absorb_fraction = -0.1;
    if (k == 6)
      p.detection.distance_tolerance = 0.0;
    EXPECT_FALSE (validParameters (p)) << "case " << k;
  }
}

TEST (CylinderJoin, PipeCutInTwoBecomesOneSegment)
{
  // Segment 0 and 1: a pipe from x = 0 to 1.5 and from 2.1 to 3.6; segment 2: a patch
  // of ground under it; the last three points are in no segment.
  std::mt19937 rng (1);
  std::vector<Eigen::Vector3d> xyz;
  std::vector<std::vector<std::uint32_t>> segments (3);
  addPipe (0.0, 1.5, rng, xyz, segments[0]);
  addPipe (2.1, 1.5, rng, xyz, segments[1]);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) {
      segments[2].push_back (static_cast<std::uint32_t> (xyz.size()));
      xyz.emplace_back (0.05 * i, -0.5 + 0.05 * j, 0.0);
    }
  const std::size_t free_points = 3;
  for (std::size_t k = 0; k < free_points; ++k)
    xyz.emplace_back (5.0 + k, 5.0, 5.0);
  JoinResult result;
  ASSERT_TRUE (joinCylinderSegments (xyz, segments, JoinParameters(), result));
  ASSERT_EQ (result.labels.size(), xyz.size());
  // One cylinder per span, none on the ground; both joined into the first label.
  ASSERT_EQ (result.pieces.size(), 2u);
  EXPECT_EQ (result.pieces[0].segment, 0u);
  EXPECT_EQ (result.pieces[1].segment, 1u);
  EXPECT_EQ (result.pieces[0].joined, 0u);
  EXPECT_EQ (result.pieces[1].joined, 0u);
  for (const auto& piece : result.pieces)
    EXPECT_NEAR (piece.cylinder.radius, 0.1, 0.005);
  EXPECT_EQ (result.num_segments, 2u);
  for (std::size_t s = 0; s < 2; ++s)
    for (const auto i : segments[s])
      EXPECT_EQ (result.labels[i], 0u) << "point " << i;
  for (const auto i : segments[2])
    EXPECT_EQ (result.labels[i], 1u) << "point " << i;
  for (std::size_t k = 1; k <= free_points; ++k)
    EXPECT_EQ (result.labels[xyz.size() - k], kNoSegment);
  // A position out of range, or invalid parameters: false, nothing labelled.
  segments[2].push_back (static_cast<std::uint32_t> (xyz.size()));
  EXPECT_FALSE (joinCylinderSegments (xyz, segments, JoinParameters(), result));
  EXPECT_TRUE (result.labels.empty());
  segments[2].pop_back();
  JoinParameters bad;
  bad.threads = 0;
  EXPECT_FALSE (joinCylinderSegments (xyz, segments, bad, result));
  EXPECT_TRUE (result.pieces.empty());
}

TEST (CylinderJoin, StraightRunIsFittedAsOneCylinder)
{
  // A pipe of radius 0.25 seen nearly all round over 2 m, then eight strips of its
  // underside (70 degrees, 0.55 m, about 140 points each, as where a pipe rests on its
  // supports), 0.3 m apart. Alone, a strip's points fix its radius and axis poorly
  // (docs/sithole_mapurisa.md); the run of all of them fixes them, and every piece of
  // the run reports the run's cylinder.
  pcl_ext::RandomStream rng (28);
  std::vector<Eigen::Vector3d> xyz;
  constexpr int strips = 8;
  std::vector<std::vector<std::uint32_t>> segments (1 + strips);
  addWidePipe (0.0, 2.0, 1.5 * M_PI, 0.035, rng, xyz, segments[0]);
  for (int k = 0; k < strips; ++k)
    addWidePipe (
        2.3 + 0.85 * k, 0.55, 70.0 * M_PI / 180.0, 0.035, rng, xyz, segments[1 + k]);
  JoinResult result; // cones fitted (a taper up to 0.1), as by default
  ASSERT_TRUE (joinCylinderSegments (xyz, segments, JoinParameters(), result));
  std::vector<int> found (segments.size(), 0);
  for (const auto& piece : result.pieces) {
    ++found[piece.segment];
    EXPECT_EQ (piece.joined, 0u) << "segment " << piece.segment;
    EXPECT_NEAR (piece.cylinder.radius, 0.25, 0.002) << "segment " << piece.segment;
    EXPECT_NEAR (std::abs (piece.cylinder.axis.x()), 1.0, 1e-4)
        << "segment " << piece.segment;
  }
  for (std::size_t s = 0; s < segments.size(); ++s)
    EXPECT_EQ (found[s], 1) << "segment " << s;
  EXPECT_EQ (result.num_segments, 1u);
}

namespace {
/** Segments held apart, loaded one at a time, as a caller that reads them from disk
 * would; \a failing (if set) cannot be loaded. */
class SeparateSegments : public SegmentSource {
public:
  std::vector<std::vector<Eigen::Vector3d>> points;
  std::size_t failing = std::numeric_limits<std::size_t>::max();

  std::size_t
  size () const override
  {
    return points.size();
  }
  std::size_t
  pointCount (std::size_t s) const override
  {
    return points[s].size();
  }
  bool
  load (std::size_t s, std::vector<Eigen::Vector3d>& out) const override
  {
    if (s == failing)
      return false;
    out = points[s];
    return true;
  }
};
} // namespace

TEST (CylinderJoin, SegmentsLoadedOneAtATimeGiveTheSameJoin)
{
  // Segments 0 and 1: the spans of a pipe (x = 0 to 1.5 and 2.1 to 3.6); 2: a ring of
  // it 6 cm long between them, too short for a cylinder of its own; 3: ground under it.
  std::mt19937 rng (5);
  std::vector<Eigen::Vector3d> xyz;
  std::vector<std::vector<std::uint32_t>> segments (4);
  addPipe (0.0, 1.5, rng, xyz, segments[0]);
  addPipe (2.1, 1.5, rng, xyz, segments[1]);
  addPipe (1.7, 0.06, rng, xyz, segments[2]);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) {
      segments[3].push_back (static_cast<std::uint32_t> (xyz.size()));
      xyz.emplace_back (0.05 * i, -0.5 + 0.05 * j, 0.0);
    }
  JoinResult held;
  ASSERT_TRUE (joinCylinderSegments (xyz, segments, JoinParameters(), held));

  SeparateSegments separate;
  for (const auto& segment : segments) {
    separate.points.emplace_back();
    for (const auto i : segment)
      separate.points.back().push_back (xyz[i]);
  }
  SegmentJoin join;
  ASSERT_TRUE (joinSegments (separate, JoinParameters(), join));
  // The spans joined in one group (label 4, the first after the segments), the ring on
  // it moved there whole, the ground kept.
  ASSERT_EQ (join.pieces.size(), 2u);
  EXPECT_EQ (join.labels, 5u);
  ASSERT_EQ (join.whole.size(), 4u);
  EXPECT_EQ (join.whole[0], 4u);
  EXPECT_EQ (join.whole[1], 4u);
  EXPECT_EQ (join.whole[2], 4u);
  EXPECT_EQ (join.whole[3], kNoSegment);
  // The same pieces and labels as the join over the held points.
  ASSERT_EQ (held.pieces.size(), join.pieces.size());
  for (std::size_t k = 0; k < join.pieces.size(); ++k) {
    const Cylinder &a = held.pieces[k].cylinder, &b = join.pieces[k].cylinder;
    EXPECT_EQ (held.pieces[k].segment, join.pieces[k].segment);
    EXPECT_EQ (a.radius, b.radius);
    EXPECT_EQ (a.point, b.point);
    EXPECT_EQ (a.axis, b.axis);
    ASSERT_EQ (a.inliers.size(), b.inliers.size());
    for (std::size_t i = 0; i < a.inliers.size(); ++i)
      EXPECT_EQ (a.inliers[i], segments[join.pieces[k].segment][b.inliers[i]]);
  }
  EXPECT_EQ (held.num_segments, 2u);
  for (std::size_t s = 0; s < 3; ++s)
    for (const auto i : segments[s])
      EXPECT_EQ (held.labels[i], held.labels[segments[0][0]]) << "point " << i;
  EXPECT_NE (held.labels[segments[3][0]], held.labels[segments[0][0]]);

  // A segment that cannot be loaded: false.
  separate.failing = 1;
  EXPECT_FALSE (joinSegments (separate, JoinParameters(), join));
}
