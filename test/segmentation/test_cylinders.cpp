/*
 * Tests of pcl_ext::cylinders (cylinders found in points without normals) on synthetic
 * strips, pipes, planes and box faces with known geometry. What the tests measured
 * within their bounds is in docs/sithole_mapurisa.md.
 */
#include <pcl_ext/segmentation/cylinders.h>

#include "cylinder_test_geometry.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using pcl_ext::cylinders::Cylinder;
using pcl_ext::cylinders::DetectionParameters;

namespace {
using pcl_ext::test::axisAngleDegrees;
using pcl_ext::test::lineDistance;

using Points = std::vector<Eigen::Vector3d>;

/** The part of a cylinder's surface a scanner on the side of \a facing sees: an arc of
 * \a arc radians centred on \a facing (a unit vector across the axis), from \a start
 * along \a axis for \a length, on a grid of about \a spacing both ways, with Gaussian
 * noise of \a sigma along the radial direction. With a \a taper, a cone: the radius is
 * \a radius at \a start and changes by \a taper per unit length along \a axis. */
void
addArc (Points& out,
        const Eigen::Vector3d& start,
        const Eigen::Vector3d& axis,
        const Eigen::Vector3d& facing,
        double radius,
        double arc,
        double length,
        double spacing,
        double sigma,
        std::mt19937& rng,
        double taper = 0.0)
{
  std::normal_distribution<double> noise (0.0, sigma);
  const Eigen::Vector3d u = facing.normalized(), v = axis.normalized().cross (u);
  const int along = static_cast<int> (std::ceil (length / spacing));
  const int across = static_cast<int> (std::ceil (arc * radius / spacing));
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const double t = (i + 0.5) * length / along;
      const double theta = -0.5 * arc + (j + 0.5) * arc / across;
      const Eigen::Vector3d n = std::cos (theta) * u + std::sin (theta) * v;
      out.push_back (start + t * axis.normalized() +
                     (radius + taper * t + noise (rng)) * n);
    }
}

/** A rectangle origin + a e1 + b e2 (a in [0, la], b in [0, lb]) on a grid of \a
 * spacing, with Gaussian noise of \a sigma along its normal. */
void
addRectangle (Points& out,
              const Eigen::Vector3d& origin,
              const Eigen::Vector3d& e1,
              const Eigen::Vector3d& e2,
              double la,
              double lb,
              double spacing,
              double sigma,
              std::mt19937& rng)
{
  std::normal_distribution<double> noise (0.0, sigma);
  const Eigen::Vector3d n = e1.cross (e2).normalized();
  for (double a = 0.5 * spacing; a < la; a += spacing)
    for (double b = 0.5 * spacing; b < lb; b += spacing)
      out.push_back (origin + a * e1 + b * e2 + noise (rng) * n);
}

/** An oblique strip, centred on the origin: half a cylinder of radius 0.15, 3 m long,
 * seen from below, sigma 3 mm. The axis is not along a coordinate axis so that no term
 * of the fit vanishes by symmetry. */
struct Strip {
  Eigen::Vector3d axis = Eigen::Vector3d (1.0, 0.2, 0.1).normalized();
  Eigen::Vector3d start = -1.5 * axis;
  double radius = 0.15, length = 3.0;
  Points points;
};

Strip
noisyStrip ()
{
  Strip s;
  std::mt19937 rng (7);
  // Facing: the downward direction made perpendicular to the axis.
  Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();
  down = (down - down.dot (s.axis) * s.axis).normalized();
  addArc (s.points, s.start, s.axis, down, s.radius, M_PI, s.length, 0.02, 0.003, rng);
  return s;
}

/** Two pipes along x, 0.35 m apart (y = -0.175 and 0.175), both seen only from below
 * (half circles on their lower side), 3 m long; radii 0.10 and 0.08. The first \a split
 * points are the first pipe's. */
Points
twoPipes (std::size_t& split)
{
  Points points;
  std::mt19937 rng (11);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), down = -Eigen::Vector3d::UnitZ();
  addArc (points,
          Eigen::Vector3d (-1.5, -0.175, 0.0),
          x,
          down,
          0.10,
          M_PI,
          3.0,
          0.02,
          0.003,
          rng);
  split = points.size();
  addArc (points,
          Eigen::Vector3d (-1.5, 0.175, 0.0),
          x,
          down,
          0.08,
          M_PI,
          3.0,
          0.02,
          0.003,
          rng);
  return points;
}

std::vector<std::uint32_t>
allOf (const Points& points)
{
  std::vector<std::uint32_t> all (points.size());
  for (std::uint32_t i = 0; i < all.size(); ++i)
    all[i] = i;
  return all;
}
} // namespace

TEST (Cylinders, RefineRecoversANoisyStrip)
{
  const Strip s = noisyStrip();
  // A start as a rough hypothesis gives it: the axis tilted 3 degrees, the axis point 2
  // cm off across the axis, the radius 20 % too large.
  const Eigen::Vector3d across = s.axis.unitOrthogonal();
  Eigen::Vector3d axis = Eigen::AngleAxisd (3.0 * M_PI / 180.0, across) * s.axis;
  Eigen::Vector3d point = 0.02 * s.axis.cross (across).normalized() + 0.3 * s.axis;
  double radius = 1.2 * s.radius;
  ASSERT_TRUE (pcl_ext::cylinders::refineCylinder (
      s.points, allOf (s.points), point, axis, radius));
  // 3600 points with 3 mm noise fix the cylinder far better than the start.
  EXPECT_NEAR (axis.norm(), 1.0, 1e-9);
  EXPECT_NEAR (radius, s.radius, 0.001);
  EXPECT_LT (axisAngleDegrees (axis, s.axis), 0.1);
  // Both ends of the true axis lie on the fitted one.
  EXPECT_LT (lineDistance (s.start, point, axis), 0.002);
  EXPECT_LT (lineDistance (s.start + s.length * s.axis, point, axis), 0.002);
}

TEST (Cylinders, RefineNeedsSixPoints)
{
  const Strip s = noisyStrip();
  // Five points cannot fix a cone's six parameters, and a cylinder is refined as a cone
  // of taper 0: false, and the inputs are left as they were.
  Eigen::Vector3d point (0.1, 0.2, 0.3), axis = Eigen::Vector3d::UnitY();
  double radius = 0.5;
  EXPECT_FALSE (pcl_ext::cylinders::refineCylinder (
      s.points, {0, 100, 200, 300, 400}, point, axis, radius));
  EXPECT_EQ (point, Eigen::Vector3d (0.1, 0.2, 0.3));
  EXPECT_EQ (axis, Eigen::Vector3d::UnitY());
  EXPECT_EQ (radius, 0.5);
  EXPECT_FALSE (pcl_ext::cylinders::refineCylinder (s.points, {}, point, axis, radius));
  EXPECT_EQ (radius, 0.5);
}

TEST (Cylinders, DetectsOneStrip)
{
  const Strip s = noisyStrip();
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (s.points, DetectionParameters(), found);
  ASSERT_EQ (found.size(), 1u);
  const Cylinder& c = found[0];
  EXPECT_NEAR (c.radius, s.radius, 0.001);
  EXPECT_LT (axisAngleDegrees (c.axis, s.axis), 0.1);
  EXPECT_NEAR (c.axis.norm(), 1.0, 1e-9);
  // A cylinder is a cone of no taper (where cones are fitted).
  EXPECT_LT (std::abs (c.taper), 0.001);
  // The point is mid-way along the inliers: the strip's centre (the origin) on its
  // axis; the outermost samples lie 0.01 inside the strip's ends.
  EXPECT_LT (c.point.norm(), 0.002);
  EXPECT_NEAR (c.half_length, 0.5 * s.length - 0.01, 0.002);
  // The noise (3 mm) is a fifth of the tolerance: every point is an inlier, and every
  // point near the surface is on it.
  EXPECT_EQ (c.inliers, allOf (s.points));
  EXPECT_GT (c.surface_fraction, 0.99);
  EXPECT_LE (c.surface_fraction, 1.0);
}

namespace {
/** A cone, as a trunk: half of it seen from the side, 2 m long, the radius 0.2 at the
 * start and 0.1 at the end (taper -0.05 along the axis), sigma 3 mm, centred on the
 * origin. */
struct Cone {
  Eigen::Vector3d axis = Eigen::Vector3d (0.1, -0.2, 1.0).normalized();
  Eigen::Vector3d start = -1.0 * axis;
  double radius = 0.2, taper = -0.05, length = 2.0;
  Points points;
};

Cone
noisyCone ()
{
  Cone c;
  std::mt19937 rng (8);
  addArc (c.points,
          c.start,
          c.axis,
          c.axis.unitOrthogonal(),
          c.radius,
          M_PI,
          c.length,
          0.02,
          0.003,
          rng,
          c.taper);
  return c;
}
} // namespace

TEST (Cylinders, RefineRecoversACone)
{
  const Cone cone = noisyCone();
  // From the cylinder through the middle (radius 0.15, no taper), with the taper free.
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), axis = cone.axis;
  double radius = 0.15, taper = 0.0;
  ASSERT_TRUE (pcl_ext::cylinders::refineCylinder (
      cone.points, allOf (cone.points), point, axis, radius, &taper));
  EXPECT_NEAR (taper, cone.taper, 0.002);
  // The radius at the point, which moves only across the axis: still the middle.
  EXPECT_NEAR (radius, 0.15, 0.001);
  EXPECT_LT (axisAngleDegrees (axis, cone.axis), 0.2);
  EXPECT_LT (lineDistance (cone.start, point, axis), 0.003);
}

TEST (Cylinders, DetectsAConeWhenTaperIsAllowed)
{
  const Cone cone = noisyCone();
  DetectionParameters p;
  p.max_taper = 0.1;
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (cone.points, p, found);
  ASSERT_EQ (found.size(), 1u);
  const Cylinder& c = found[0];
  // The taper is along the fitted axis, whichever way it points.
  const double sense = c.axis.dot (cone.axis) > 0.0 ? 1.0 : -1.0;
  EXPECT_NEAR (sense * c.taper, cone.taper, 0.002);
  EXPECT_NEAR (c.radius, 0.15, 0.002); // at the middle of the inliers
  EXPECT_LT (axisAngleDegrees (c.axis, cone.axis), 0.2);
  EXPECT_EQ (c.inliers, allOf (cone.points));
  EXPECT_GT (c.surface_fraction, 0.99);
  // A taper beyond the largest allowed, or cones not fitted at all: no cylinder takes
  // the cone whole.
  for (const double max_taper : {0.02, 0.0}) {
    p.max_taper = max_taper;
    pcl_ext::cylinders::detectCylinders (cone.points, p, found);
    for (const auto& f : found)
      EXPECT_LT (f.inliers.size(), cone.points.size() / 2) << max_taper;
  }
}

TEST (Cylinders, SeparatesTwoPipesSideBySide)
{
  std::size_t split = 0;
  const Points points = twoPipes (split);
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (points, DetectionParameters(), found);
  // A circle through the undersides of both pipes holds as many points as either pipe's
  // own; the fit must pick the pipes'.
  ASSERT_EQ (found.size(), 2u);
  for (const auto& c : found) {
    std::size_t first = 0;
    for (const auto i : c.inliers)
      first += i < split;
    const std::size_t second = c.inliers.size() - first;
    const bool is_first = first > second;
    const std::size_t size = is_first ? split : points.size() - split;
    // Each cylinder is one pipe: its radius, its axis, all of its points and none of
    // the other's (the surfaces are 0.17 m apart, the noise 3 mm).
    EXPECT_NEAR (c.radius, is_first ? 0.10 : 0.08, 0.002);
    EXPECT_LT (axisAngleDegrees (c.axis, Eigen::Vector3d::UnitX()), 0.1);
    EXPECT_NEAR (c.point.y(), is_first ? -0.175 : 0.175, 0.002);
    EXPECT_NEAR (c.point.z(), 0.0, 0.002);
    EXPECT_EQ (std::min (first, second), 0u);
    EXPECT_GE (std::max (first, second), size * 99 / 100);
    EXPECT_GT (c.surface_fraction, 0.99);
  }
  // One cylinder each.
  EXPECT_NE (found[0].radius > 0.09, found[1].radius > 0.09);
}

TEST (Cylinders, PlaneGivesNoCylinder)
{
  Points points;
  std::mt19937 rng (5);
  addRectangle (points,
                Eigen::Vector3d (-1, -1, 0),
                Eigen::Vector3d::UnitX(),
                Eigen::Vector3d::UnitY(),
                2.0,
                2.0,
                0.02,
                0.003,
                rng);
  std::vector<Cylinder> found (1);
  pcl_ext::cylinders::detectCylinders (points, DetectionParameters(), found);
  EXPECT_TRUE (found.empty());
  // Not even without the surface test: across any axis in the plane its points lie on a
  // line, so a circle through three of them is mostly metres wide, beyond the largest
  // radius, and the few hypotheses drawn all fall apart or leave the radius range when
  // grown over the plane.
  DetectionParameters p;
  p.min_surface_fraction = 0.0;
  pcl_ext::cylinders::detectCylinders (points, p, found);
  EXPECT_TRUE (found.empty());
  // Sampled at random, as sparse as 0.05 on average (more than three tolerances),
  // neither.
  Points sparse;
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::normal_distribution<double> noise (0.0, 0.003);
  for (int k = 0; k < 1600; ++k) {
    const double x = u (rng), y = u (rng);
    sparse.emplace_back (x, y, noise (rng));
  }
  found.resize (1);
  pcl_ext::cylinders::detectCylinders (sparse, DetectionParameters(), found);
  EXPECT_TRUE (found.empty());
}

// The same plane on a regular grid of spacing 0.05, more than the surface test's band
// (three tolerances, 0.045), as scan lines are far from the scanner: a cylinder with
// its axis in the plane, along the rows, has two rows on its surface and the
// neighbouring rows beyond the band, but the rows between lie inside it, which a solid
// seen from outside never has: the surface test counts the points inside against a
// cylinder.
TEST (Cylinders, SparseGridPlaneGivesNoCylinder)
{
  Points points;
  std::mt19937 rng (5);
  addRectangle (points,
                Eigen::Vector3d (-1, -1, 0),
                Eigen::Vector3d::UnitX(),
                Eigen::Vector3d::UnitY(),
                2.0,
                2.0,
                0.05,
                0.003,
                rng);
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (points, DetectionParameters(), found);
  EXPECT_TRUE (found.empty());
}

namespace {
/** A square column 0.3 x 0.3 m, 2.5 m high (along z), centred on the origin, seen from
 * a corner: its faces x = -0.15 and y = -0.15. */
Points
boxColumn ()
{
  Points points;
  std::mt19937 rng (6);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  addRectangle (
      points, Eigen::Vector3d (-0.15, -0.15, -1.25), y, z, 0.3, 2.5, 0.02, 0.003, rng);
  addRectangle (
      points, Eigen::Vector3d (-0.15, -0.15, -1.25), z, x, 2.5, 0.3, 0.02, 0.003, rng);
  return points;
}
} // namespace

TEST (Cylinders, SurfaceTestRejectsTheBestCylinderOfABoxColumn)
{
  const Points points = boxColumn();
  // Without the surface test, the first cylinder found rounds the corner: its inliers
  // are the bands of both faces its surface grazes, and only three quarters of the
  // points near its surface are on it, where a pipe's are all on it.
  DetectionParameters p;
  p.min_surface_fraction = 0.0;
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (points, p, found);
  ASSERT_FALSE (found.empty());
  EXPECT_GT (found[0].radius, 0.15); // centred on the diagonal inside
  EXPECT_LT (axisAngleDegrees (found[0].axis, Eigen::Vector3d::UnitZ()), 1.0);
  EXPECT_LT (found[0].surface_fraction, 0.85);
  EXPECT_GT (found[0].inliers.size(), 1000u);
  // With it, that cylinder is rejected, and a search that stops at the first failure
  // finds nothing.
  p = DetectionParameters();
  p.max_failures = 1;
  pcl_ext::cylinders::detectCylinders (points, p, found);
  EXPECT_TRUE (found.empty());
}

// With the defaults (two failures allowed) the next candidates on the box column must
// fail too: the band a rejected candidate took still counts against them (otherwise the
// next one, grazing the faces beside that band, would pass on the points left).
TEST (Cylinders, BoxColumnGivesNoCylinder)
{
  std::vector<Cylinder> found;
  pcl_ext::cylinders::detectCylinders (boxColumn(), DetectionParameters(), found);
  EXPECT_TRUE (found.empty());
}

TEST (Cylinders, RadiusLimitsAndCylinderCount)
{
  // The strip's radius (0.15) outside the limits: no cylinder of another radius
  // instead.
  const Strip s = noisyStrip();
  std::vector<Cylinder> found;
  DetectionParameters p;
  p.max_radius = 0.1;
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  EXPECT_TRUE (found.empty());
  p.max_radius = 0.6;
  p.min_radius = 0.2;
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  EXPECT_TRUE (found.empty());
  // Limits equal to the radius (within the noise) still find it.
  p.min_radius = 0.14;
  p.max_radius = 0.16;
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  ASSERT_EQ (found.size(), 1u);
  EXPECT_NEAR (found[0].radius, s.radius, 0.001);
  // At most max_cylinders: one of the two pipes.
  std::size_t split = 0;
  const Points pipes = twoPipes (split);
  p = DetectionParameters();
  p.max_cylinders = 1;
  pcl_ext::cylinders::detectCylinders (pipes, p, found);
  ASSERT_EQ (found.size(), 1u);
  EXPECT_TRUE (std::abs (found[0].radius - 0.10) < 0.002 ||
               std::abs (found[0].radius - 0.08) < 0.002);
  // Fewer inliers than min_points: the smaller pipe (1950 points) is not kept, the
  // larger (2400) is.
  p = DetectionParameters();
  p.min_points = 2000;
  pcl_ext::cylinders::detectCylinders (pipes, p, found);
  ASSERT_EQ (found.size(), 1u);
  EXPECT_NEAR (found[0].radius, 0.10, 0.002);
}

TEST (Cylinders, SameSeedSameResult)
{
  std::size_t split = 0;
  const Points points = twoPipes (split);
  std::vector<Cylinder> first, second;
  pcl_ext::cylinders::detectCylinders (points, DetectionParameters(), first);
  pcl_ext::cylinders::detectCylinders (points, DetectionParameters(), second);
  ASSERT_EQ (first.size(), 2u);
  ASSERT_EQ (second.size(), first.size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ (first[k].radius, second[k].radius);
    EXPECT_EQ (first[k].point, second[k].point);
    EXPECT_EQ (first[k].axis, second[k].axis);
    EXPECT_EQ (first[k].taper, second[k].taper);
    EXPECT_EQ (first[k].half_length, second[k].half_length);
    EXPECT_EQ (first[k].surface_fraction, second[k].surface_fraction);
    EXPECT_EQ (first[k].inliers, second[k].inliers);
  }
  // Another seed draws other hypotheses but finds the same two pipes.
  DetectionParameters p;
  p.seed = 12345;
  std::vector<Cylinder> other;
  pcl_ext::cylinders::detectCylinders (points, p, other);
  ASSERT_EQ (other.size(), 2u);
  for (const auto& c : other) {
    const auto same =
        std::find_if (first.begin(), first.end(), [&] (const Cylinder& f) {
          return std::abs (f.radius - c.radius) < 0.002;
        });
    ASSERT_TRUE (same != first.end());
    EXPECT_LT (lineDistance (same->point, c.point, c.axis), 0.002);
    EXPECT_EQ (same->inliers.size(), c.inliers.size());
  }
}

TEST (Cylinders, ValidParameters)
{
  using pcl_ext::cylinders::validParameters;
  EXPECT_TRUE (validParameters (DetectionParameters()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto with = [] (auto set) {
    DetectionParameters p;
    set (p);
    return validParameters (p);
  };
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.distance_tolerance = 0.0; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.distance_tolerance = -0.01; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.distance_tolerance = nan; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.distance_tolerance = inf; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.min_radius = 0.0; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.min_radius = nan; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.max_radius = nan; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.max_radius = inf; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) {
    p.min_radius = 0.5;
    p.max_radius = 0.4;
  }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.neighbourhood_radius = 0.0; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.neighbourhood_radius = nan; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.hypotheses = 0; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.refined_hypotheses = 0; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.min_points = 2; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.min_surface_fraction = 1.5; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.min_surface_fraction = -0.1; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.min_surface_fraction = nan; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.max_taper = 1.0; }));
  EXPECT_FALSE (with ([] (DetectionParameters& p) { p.max_taper = -0.1; }));
  EXPECT_FALSE (with ([&] (DetectionParameters& p) { p.max_taper = nan; }));
  // The bounds themselves are valid.
  EXPECT_TRUE (
      with ([] (DetectionParameters& p) { p.min_radius = p.max_radius = 0.3; }));
  EXPECT_TRUE (with ([] (DetectionParameters& p) { p.min_points = 3; }));
  EXPECT_TRUE (with ([] (DetectionParameters& p) { p.min_surface_fraction = 0.0; }));
  EXPECT_TRUE (with ([] (DetectionParameters& p) { p.min_surface_fraction = 1.0; }));
  EXPECT_TRUE (
      with ([] (DetectionParameters& p) { p.hypotheses = p.refined_hypotheses = 1; }));
  EXPECT_TRUE (with ([] (DetectionParameters& p) { p.max_taper = 0.5; }));
}

TEST (Cylinders, BadInputGivesNoCylinder)
{
  const Strip s = noisyStrip();
  std::vector<Cylinder> found;
  // The strip itself gives one, so each empty result below is the bad input's doing.
  pcl_ext::cylinders::detectCylinders (s.points, DetectionParameters(), found);
  ASSERT_EQ (found.size(), 1u);
  DetectionParameters p;
  p.distance_tolerance = 0.0;
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  EXPECT_TRUE (found.empty());
  p = DetectionParameters();
  p.min_radius = 0.3;
  p.max_radius = 0.2;
  found.resize (1);
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  EXPECT_TRUE (found.empty());
  // Fewer points than min_points, and none.
  p = DetectionParameters();
  p.min_points = s.points.size() + 1;
  found.resize (1);
  pcl_ext::cylinders::detectCylinders (s.points, p, found);
  EXPECT_TRUE (found.empty());
  found.resize (1);
  pcl_ext::cylinders::detectCylinders (Points(), DetectionParameters(), found);
  EXPECT_TRUE (found.empty());
  // One non-finite point: nothing (the input must be finite), no crash.
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    Points with_bad = s.points;
    with_bad[1234].y() = bad;
    found.resize (1);
    pcl_ext::cylinders::detectCylinders (with_bad, DetectionParameters(), found);
    EXPECT_TRUE (found.empty());
  }
}
