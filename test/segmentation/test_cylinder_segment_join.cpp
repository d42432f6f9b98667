/*
 * Tests of pcl_ext::CylinderSegmentJoin on synthetic pipes cut into segments: straight
 * runs cut at supports, elbows, pipes side by side, with the segments known. What the
 * tests measured within their bounds is in docs/sithole_mapurisa.md.
 */
#include <pcl_ext/segmentation/cylinder_segment_join.h>

#include <pcl/common/point_tests.h>

#include "cylinder_test_geometry.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Join = pcl_ext::CylinderSegmentJoin<pcl::PointXYZ>;

namespace {
using pcl_ext::test::axisAngleDegrees;
using pcl_ext::test::lineDistance;

/** A cloud and its input segmentation, built up piece by piece. */
struct Scene {
  Cloud::Ptr cloud{new Cloud};
  std::vector<pcl::PointIndices> segments;
  std::mt19937 rng{1};

  void
  add (const Eigen::Vector3d& p, pcl::Indices& indices)
  {
    indices.push_back (static_cast<pcl::index_t> (cloud->size()));
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x()),
                                     static_cast<float> (p.y()),
                                     static_cast<float> (p.z())));
  }

  /** The part of a cylinder's surface a scanner on the side of \a facing sees: an arc
   * of \a arc radians centred on \a facing (across the axis), from \a start along \a
   * axis for \a length, on a grid of about \a spacing both ways, with Gaussian noise of
   * \a sigma along the radial direction. */
  pcl::Indices
  arc (const Eigen::Vector3d& start,
       const Eigen::Vector3d& axis,
       const Eigen::Vector3d& facing,
       double radius,
       double length,
       double arc = M_PI,
       double spacing = 0.02,
       double sigma = 0.003)
  {
    std::normal_distribution<double> noise (0.0, sigma);
    const Eigen::Vector3d d = axis.normalized(), u = facing.normalized(),
                          v = d.cross (u);
    const int along = static_cast<int> (std::ceil (length / spacing));
    const int across = static_cast<int> (std::ceil (arc * radius / spacing));
    pcl::Indices indices;
    for (int i = 0; i < along; ++i)
      for (int j = 0; j < across; ++j) {
        const double t = (i + 0.5) * length / along;
        const double theta = -0.5 * arc + (j + 0.5) * arc / across;
        add (start + t * d +
                 (radius + noise (rng)) * (std::cos (theta) * u + std::sin (theta) * v),
             indices);
      }
    return indices;
  }

  /** A rectangle origin + a e1 + b e2 (a in [0, la], b in [0, lb]) on a grid of \a
   * spacing, with Gaussian noise of \a sigma along its normal. */
  pcl::Indices
  rectangle (const Eigen::Vector3d& origin,
             const Eigen::Vector3d& e1,
             const Eigen::Vector3d& e2,
             double la,
             double lb,
             double spacing,
             double sigma = 0.003)
  {
    std::normal_distribution<double> noise (0.0, sigma);
    const Eigen::Vector3d n = e1.cross (e2).normalized();
    pcl::Indices indices;
    for (double a = 0.5 * spacing; a < la; a += spacing)
      for (double b = 0.5 * spacing; b < lb; b += spacing)
        add (origin + a * e1 + b * e2 + noise (rng) * n, indices);
    return indices;
  }

  /** A new input segment of \a indices; returns its position. */
  std::size_t
  segment (const pcl::Indices& indices)
  {
    segments.emplace_back();
    segments.back().indices = indices;
    return segments.size() - 1;
  }
};

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

pcl::Indices
sorted (pcl::Indices indices)
{
  std::sort (indices.begin(), indices.end());
  return indices;
}

pcl::Indices
concat (std::initializer_list<pcl::Indices> parts)
{
  pcl::Indices all;
  for (const auto& p : parts)
    all.insert (all.end(), p.begin(), p.end());
  return sorted (all);
}

/** The output segment holding cloud index \a index, or -1. */
int
segmentOf (const std::vector<pcl::PointIndices>& segments, pcl::index_t index)
{
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (std::binary_search (
            segments[s].indices.begin(), segments[s].indices.end(), index))
      return static_cast<int> (s);
  return -1;
}

/** Every output segment sorted, and no index in two of them; returns how many there
 * are. */
std::size_t
checkPartition (const std::vector<pcl::PointIndices>& segments)
{
  pcl::Indices all;
  for (const auto& s : segments) {
    EXPECT_TRUE (std::is_sorted (s.indices.begin(), s.indices.end()));
    EXPECT_FALSE (s.indices.empty());
    all.insert (all.end(), s.indices.begin(), s.indices.end());
  }
  std::sort (all.begin(), all.end());
  EXPECT_TRUE (std::adjacent_find (all.begin(), all.end()) == all.end());
  return all.size();
}

std::vector<pcl::PointIndices>
join (Join& j, const Scene& scene, unsigned int threads = 1)
{
  j.setInputCloud (scene.cloud);
  j.setInputSegments (scene.segments);
  j.setNumberOfThreads (threads);
  std::vector<pcl::PointIndices> out (1); // join() must clear it
  j.join (out);
  return out;
}

/** A pipe rack in miniature: a pipe of radius 0.1 along x at height 1, 12 m long, cut
 * at supports at x = 4 and x = 8 with the 0.6 m around each missing, each span its own
 * segment (0, 1, 2); the ground below (segment 3); a parallel pipe 1 m away, whole
 * (segment 4). Pipes seen from below, as from a scanner on the ground. */
struct Rack {
  Scene scene;
  pcl::Indices spans[3], ground, other;
};

Rack
rack (const Eigen::Vector3d& offset = Eigen::Vector3d::Zero())
{
  Rack r;
  const Eigen::Vector3d down = -kZ;
  const double starts[3] = {0.0, 4.3, 8.3}, lengths[3] = {3.7, 3.4, 3.7};
  for (int k = 0; k < 3; ++k) {
    r.spans[k] = r.scene.arc (
        offset + Eigen::Vector3d (starts[k], 0, 1), kX, down, 0.1, lengths[k]);
    r.scene.segment (r.spans[k]);
  }
  r.ground = r.scene.rectangle (
      offset + Eigen::Vector3d (0, -0.5, 0), kX, kY, 12.0, 2.0, 0.03);
  r.scene.segment (r.ground);
  r.other = r.scene.arc (offset + Eigen::Vector3d (0, 1, 1), kX, down, 0.1, 12.0);
  r.scene.segment (r.other);
  return r;
}

} // namespace

TEST (CylinderSegmentJoin, StraightPipeCutAtSupportsIsJoined)
{
  const Rack r = rack();
  Join j;
  const auto out = join (j, r.scene);
  EXPECT_EQ (checkPartition (out), r.scene.cloud->size());
  ASSERT_EQ (out.size(), 3u);
  // The three spans are one segment; the ground and the other pipe stay as they were.
  const int pipe = segmentOf (out, r.spans[0][0]);
  ASSERT_GE (pipe, 0);
  EXPECT_EQ (out[pipe].indices, concat ({r.spans[0], r.spans[1], r.spans[2]}));
  const int ground = segmentOf (out, r.ground[0]);
  ASSERT_GE (ground, 0);
  EXPECT_EQ (out[ground].indices, sorted (r.ground));
  const int other = segmentOf (out, r.other[0]);
  ASSERT_GE (other, 0);
  EXPECT_EQ (out[other].indices, sorted (r.other));
  // Sorted by size, largest first.
  for (std::size_t s = 1; s < out.size(); ++s)
    EXPECT_GE (out[s - 1].indices.size(), out[s].indices.size());

  // The cylinders: the pipe's, in the cloud's coordinates, each span's in the joined
  // segment; the other pipe's joined nothing; none on the ground.
  std::size_t per_segment[5] = {0, 0, 0, 0, 0};
  for (const auto& c : j.getCylinders()) {
    ASSERT_LT (c.input_segment, 5u);
    ++per_segment[c.input_segment];
    const double y = c.input_segment == 4 ? 1.0 : 0.0;
    EXPECT_NEAR (c.cylinder.radius, 0.1, 0.002);
    EXPECT_LT (axisAngleDegrees (c.cylinder.axis, kX), 0.1);
    EXPECT_LT (lineDistance (c.cylinder.point, Eigen::Vector3d (0, y, 1), kX), 0.002);
    EXPECT_LT (std::abs (c.cylinder.taper),
               0.001); // a cylinder, where cones may be fitted
    EXPECT_EQ (c.output_segment, c.input_segment == 4 ? -1 : pipe);
    // Inliers are cloud indices of the segment the cylinder was found in: here all of
    // them.
    const pcl::Indices inliers (c.cylinder.inliers.begin(), c.cylinder.inliers.end());
    EXPECT_EQ (inliers, sorted (r.scene.segments[c.input_segment].indices));
  }
  EXPECT_EQ (per_segment[0], 1u);
  EXPECT_EQ (per_segment[1], 1u);
  EXPECT_EQ (per_segment[2], 1u);
  EXPECT_EQ (per_segment[3], 0u);
  EXPECT_EQ (per_segment[4], 1u);
}

namespace {
/** Two pieces of a pipe seen from below, each its own segment: one from x = 0 to 3.7
 * (radius 0.1, axis y = 0, z = 1), the other from x = 3.7 + gap, 3.7 long, of radius \a
 * radius_b, its axis shifted by \a offset and turned by \a tilt radians about z. */
Scene
twoSpans (double radius_b = 0.1,
          double gap = 0.6,
          const Eigen::Vector3d& offset = Eigen::Vector3d::Zero(),
          double tilt = 0.0)
{
  Scene scene;
  scene.segment (scene.arc (Eigen::Vector3d (0, 0, 1), kX, -kZ, 0.1, 3.7));
  const Eigen::Vector3d axis = Eigen::AngleAxisd (tilt, kZ) * kX;
  scene.segment (
      scene.arc (Eigen::Vector3d (3.7 + gap, 0, 1) + offset, axis, -kZ, radius_b, 3.7));
  return scene;
}

/** Whether \a scene's two segments come out as one. */
bool
joined (const Scene& scene, double max_gap = 2.0)
{
  Join j;
  j.setMaxGap (max_gap);
  const auto out = join (j, scene);
  EXPECT_EQ (checkPartition (out), scene.cloud->size());
  // Each span is one cylinder either way, so that a "no" is the join's, not the
  // detection's.
  EXPECT_EQ (j.getCylinders().size(), 2u);
  return out.size() == 1;
}
} // namespace

TEST (CylinderSegmentJoin, StraightRunNeedsMatchingRadiiAxesAndGap)
{
  // Equal radii on one axis, 0.6 m apart: joined.
  EXPECT_TRUE (joined (twoSpans()));
  // Radii within the allowed difference (20 % of 30 %) still join; 50 % does not.
  EXPECT_TRUE (joined (twoSpans (0.08)));
  EXPECT_FALSE (joined (twoSpans (0.05)));
  // The axis moved across by 0.1 (a radius; allowed: 0.3 radii + the tolerance, 0.045):
  // not joined; by 0.02, joined.
  EXPECT_FALSE (joined (twoSpans (0.1, 0.6, Eigen::Vector3d (0, 0.1, 0))));
  EXPECT_FALSE (joined (twoSpans (0.1, 0.6, Eigen::Vector3d (0, 0, 0.1))));
  EXPECT_TRUE (joined (twoSpans (0.1, 0.6, Eigen::Vector3d (0, 0.02, 0))));
  // The gap (0.6, a little more between the outermost points) against the longest
  // bridged.
  EXPECT_FALSE (joined (twoSpans(), 0.5));
  EXPECT_TRUE (joined (twoSpans(), 0.7));
  EXPECT_FALSE (joined (twoSpans (0.1, 2.5)));
  // Turned by 10 degrees about its end: neither one run (5 degrees at most) nor an
  // elbow (30 degrees at least).
  EXPECT_FALSE (
      joined (twoSpans (0.1, 0.0, Eigen::Vector3d::Zero(), 10.0 * M_PI / 180.0)));
  EXPECT_TRUE (
      joined (twoSpans (0.1, 0.0, Eigen::Vector3d::Zero(), 2.0 * M_PI / 180.0)));
}

namespace {
/** An elbow whose bend is missing: a horizontal leg along x ending 0.3 m before the
 * corner at the origin, and a vertical leg along z starting 0.3 m below it (radius 0.1
 * both, 1.7 m long, seen from the side -y). The vertical leg is moved by \a shift. */
Scene
elbow (const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  Scene scene;
  scene.segment (scene.arc (Eigen::Vector3d (-2.0, 0, 0), kX, -kY, 0.1, 1.7));
  scene.segment (scene.arc (Eigen::Vector3d (0, 0, -2.0) + shift, kZ, -kY, 0.1, 1.7));
  return scene;
}
} // namespace

TEST (CylinderSegmentJoin, ElbowLegsAreJoinedWhenTheirAxesMeet)
{
  EXPECT_TRUE (joined (elbow()));
  // The axes pass 0.5 m apart: two pipes crossing, not an elbow.
  EXPECT_FALSE (joined (elbow (Eigen::Vector3d (0, 0.5, 0))));
  // The axes meet, but 2.5 m below the vertical leg's end (longest bridged: 2).
  EXPECT_FALSE (joined (elbow (Eigen::Vector3d (0, 0, -2.2))));
  // A minimum elbow angle of 80 degrees still takes this right angle (fitted axes are
  // never exactly square, so pi/2 would join no elbow, as documented).
  Join j;
  j.setMinElbowAngle (80.0 * M_PI / 180.0);
  EXPECT_EQ (join (j, elbow()).size(), 1u);
}

TEST (CylinderSegmentJoin, SegmentWithTwoPipesIsSplit)
{
  // Two pipes side by side, 0.35 m apart (radii 0.1 and 0.08, seen from below), one
  // segment from x = 0 to 3.7; beyond a 0.6 m gap each continues in its own segment.
  Scene scene;
  const pcl::Indices a0 = scene.arc (Eigen::Vector3d (0, -0.175, 1), kX, -kZ, 0.1, 3.7);
  const pcl::Indices b0 = scene.arc (Eigen::Vector3d (0, 0.175, 1), kX, -kZ, 0.08, 3.7);
  scene.segment (concat ({a0, b0}));
  const pcl::Indices a1 =
      scene.arc (Eigen::Vector3d (4.3, -0.175, 1), kX, -kZ, 0.1, 3.7);
  scene.segment (a1);
  const pcl::Indices b1 =
      scene.arc (Eigen::Vector3d (4.3, 0.175, 1), kX, -kZ, 0.08, 3.7);
  scene.segment (b1);
  Join j;
  const auto out = join (j, scene);
  EXPECT_EQ (checkPartition (out), scene.cloud->size());
  // Every point of the shared segment is on one of the two pipes (3 mm noise, 15 mm
  // tolerance), so nothing of it is left: two segments, one per pipe.
  ASSERT_EQ (out.size(), 2u);
  const int a = segmentOf (out, a0[0]), b = segmentOf (out, b0[0]);
  ASSERT_GE (a, 0);
  ASSERT_GE (b, 0);
  EXPECT_EQ (out[a].indices, concat ({a0, a1}));
  EXPECT_EQ (out[b].indices, concat ({b0, b1}));
  // Four cylinders, two in the shared segment, each in its pipe's output segment.
  ASSERT_EQ (j.getCylinders().size(), 4u);
  for (const auto& c : j.getCylinders()) {
    const bool on_a = c.cylinder.radius > 0.09;
    EXPECT_NEAR (c.cylinder.radius, on_a ? 0.1 : 0.08, 0.002);
    EXPECT_EQ (c.output_segment, on_a ? a : b);
  }
}

TEST (CylinderSegmentJoin, GeoreferencedCoordinatesGiveTheSameSegments)
{
  // A float's significand holds 24 bits: at 6,000,000 (a UTM northing) its step is 0.5
  // m, so a PointXYZ cannot hold such a scene at all; at 5000, 6000, 100 the steps are
  // 0.5 mm at most, under the noise. The join centres the points in double before
  // fitting.
  const Eigen::Vector3d offset (5000.0, 6000.0, 100.0);
  const Rack local = rack(), far = rack (offset);
  Join j_local, j_far;
  const auto out_local = join (j_local, local.scene), out_far = join (j_far, far.scene);
  ASSERT_EQ (out_local.size(), 3u);
  ASSERT_EQ (out_far.size(), out_local.size());
  for (std::size_t s = 0; s < out_local.size(); ++s)
    EXPECT_EQ (out_far[s].indices, out_local[s].indices);
  // The cylinders are reported in the cloud's coordinates.
  const auto& c_local = j_local.getCylinders();
  const auto& c_far = j_far.getCylinders();
  ASSERT_EQ (c_far.size(), c_local.size());
  for (std::size_t k = 0; k < c_local.size(); ++k) {
    EXPECT_EQ (c_far[k].input_segment, c_local[k].input_segment);
    EXPECT_EQ (c_far[k].output_segment, c_local[k].output_segment);
    EXPECT_NEAR (c_far[k].cylinder.radius, c_local[k].cylinder.radius, 0.0005);
    EXPECT_LT (lineDistance (c_far[k].cylinder.point - offset,
                             c_local[k].cylinder.point,
                             c_local[k].cylinder.axis),
               0.0005);
  }
}

TEST (CylinderSegmentJoin, SameResultForAnyThreadCountAndRun)
{
  const Rack r = rack();
  Join one, two;
  const auto first = join (one, r.scene, 1);
  const auto second = join (two, r.scene, 2);
  const auto again = join (two, r.scene, 2);
  ASSERT_EQ (first.size(), 3u);
  ASSERT_EQ (second.size(), first.size());
  ASSERT_EQ (again.size(), first.size());
  for (std::size_t s = 0; s < first.size(); ++s) {
    EXPECT_EQ (second[s].indices, first[s].indices);
    EXPECT_EQ (again[s].indices, first[s].indices);
  }
  ASSERT_EQ (two.getCylinders().size(), one.getCylinders().size());
  for (std::size_t k = 0; k < one.getCylinders().size(); ++k) {
    const auto &a = one.getCylinders()[k], &b = two.getCylinders()[k];
    EXPECT_EQ (a.input_segment, b.input_segment);
    EXPECT_EQ (a.output_segment, b.output_segment);
    EXPECT_EQ (a.cylinder.radius, b.cylinder.radius);
    EXPECT_EQ (a.cylinder.point, b.cylinder.point);
    EXPECT_EQ (a.cylinder.inliers, b.cylinder.inliers);
  }
}

TEST (CylinderSegmentJoin, WholeSegmentFraction)
{
  // A span with a bracket under it (a plate of 0.3 x 0.3 m, 0.05 below the pipe; 225
  // points against 2960) in one segment, the next span beyond a gap in another.
  Scene scene;
  const pcl::Indices span = scene.arc (Eigen::Vector3d (0, 0, 1), kX, -kZ, 0.1, 3.7);
  const pcl::Indices bracket =
      scene.rectangle (Eigen::Vector3d (3.4, -0.15, 0.85), kX, kY, 0.3, 0.3, 0.02);
  scene.segment (concat ({span, bracket}));
  const pcl::Indices next = scene.arc (Eigen::Vector3d (4.3, 0, 1), kX, -kZ, 0.1, 3.7);
  scene.segment (next);
  // The pipe covers 93 % of its segment: by default (half) the bracket goes with it.
  Join j;
  auto out = join (j, scene);
  ASSERT_EQ (out.size(), 1u);
  EXPECT_EQ (out[0].indices, concat ({span, bracket, next}));
  // Asking for more than that: only the pipe's points move, the bracket stays.
  j.setWholeSegmentFraction (0.99);
  out = join (j, scene);
  ASSERT_EQ (out.size(), 2u);
  EXPECT_EQ (out[0].indices, concat ({span, next}));
  EXPECT_EQ (out[1].indices, sorted (bracket));
}

TEST (CylinderSegmentJoin, BadInput)
{
  // No input cloud.
  Join j;
  j.setInputSegments ({pcl::PointIndices()});
  std::vector<pcl::PointIndices> out (2);
  j.join (out);
  EXPECT_TRUE (out.empty());
  EXPECT_TRUE (j.getCylinders().empty());
  // An empty cloud with no segments: nothing to join, nothing out.
  Cloud::Ptr empty (new Cloud);
  j.setInputCloud (empty);
  j.setInputSegments ({});
  out.resize (2);
  j.join (out);
  EXPECT_TRUE (out.empty());

  // The two spans join (checked), so each empty output below is the bad input's doing.
  Scene scene = twoSpans();
  Join good;
  ASSERT_EQ (join (good, scene).size(), 1u);
  ASSERT_EQ (good.getCylinders().size(), 2u);
  // No segments.
  Join none;
  none.setInputCloud (scene.cloud);
  out.resize (2);
  none.join (out);
  EXPECT_TRUE (out.empty());
  EXPECT_TRUE (none.getCylinders().empty());
  // An index past the cloud, or negative: empty, and the cylinders of the last good run
  // are gone.
  for (const pcl::index_t bad : {static_cast<pcl::index_t> (scene.cloud->size()), -1}) {
    Scene broken = scene;
    broken.segments[1].indices.push_back (bad);
    EXPECT_TRUE (join (good, broken).empty());
    EXPECT_TRUE (good.getCylinders().empty());
  }
  // Invalid parameters.
  const auto fails = [&] (auto set) {
    Join k;
    set (k);
    return join (k, scene).empty() && k.getCylinders().empty();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE (fails ([] (Join& k) { k.setDistanceTolerance (0.0); }));
  EXPECT_TRUE (fails ([&] (Join& k) { k.setDistanceTolerance (nan); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setRadiusLimits (0.3, 0.2); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setRadiusLimits (0.0, 0.2); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMaxGap (-1.0); }));
  EXPECT_TRUE (fails ([&] (Join& k) { k.setMaxGap (nan); }));
  EXPECT_TRUE (fails ([] (Join& k) {
    k.setMaxAxisAngle (0.3);
    k.setMinElbowAngle (0.3);
  }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMinElbowAngle (2.0); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMaxAxisAngle (-0.1); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMaxRadiusDifference (1.0); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMaxAxisOffset (-0.1); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setWholeSegmentFraction (1.5); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setNeighbourhoodRadius (0.0); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setNumberOfHypotheses (0, 20); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setNumberOfHypotheses (300, 0); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMinCylinderSize (2); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMinSurfaceFraction (1.5); }));
  EXPECT_TRUE (fails ([] (Join& k) { k.setMaxTaper (1.0); }));
  // Bounds that are valid.
  EXPECT_FALSE (fails ([] (Join& k) { k.setWholeSegmentFraction (1.0); }));
  EXPECT_FALSE (fails ([] (Join& k) { k.setMaxGap (0.0); }));
}

TEST (CylinderSegmentJoin, NonFinitePointsGoWithTheirSegment)
{
  Rack r = rack();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // Every 50th point of the middle span made non-finite.
  pcl::Indices bad;
  for (std::size_t k = 0; k < r.spans[1].size(); k += 50) {
    (*r.scene.cloud)[r.spans[1][k]].x = (k % 100) ? inf : nan;
    bad.push_back (r.spans[1][k]);
  }
  // A segment of only non-finite points: it has nowhere else to go.
  pcl::Indices lost;
  for (int k = 0; k < 5; ++k)
    r.scene.add (Eigen::Vector3d (nan, 0, 0), lost);
  r.scene.segment (lost);
  r.scene.cloud->is_dense = false;
  Join j;
  const auto out = join (j, r.scene);
  EXPECT_EQ (checkPartition (out), r.scene.cloud->size());
  // The spans still join, the non-finite points of the middle one with them (where most
  // of their segment went); the ground and the other pipe as before, and the lost
  // points alone.
  ASSERT_EQ (out.size(), 4u);
  const int pipe = segmentOf (out, r.spans[0][0]);
  ASSERT_GE (pipe, 0);
  EXPECT_EQ (out[pipe].indices, concat ({r.spans[0], r.spans[1], r.spans[2]}));
  for (const auto i : bad)
    EXPECT_EQ (segmentOf (out, i), pipe);
  const int alone = segmentOf (out, lost[0]);
  ASSERT_GE (alone, 0);
  EXPECT_EQ (out[alone].indices, lost);
  // No cylinder holds a non-finite point.
  for (const auto& c : j.getCylinders())
    for (const auto i : c.cylinder.inliers)
      EXPECT_TRUE (pcl::isXYZFinite ((*r.scene.cloud)[i]));
}

TEST (CylinderSegmentJoin, PointInTwoSegmentsStaysWithTheFirst)
{
  // A span and a plate next to it that does not join it; one plate point also listed in
  // the span's segment.
  Scene scene;
  const pcl::Indices span = scene.arc (Eigen::Vector3d (0, 0, 1), kX, -kZ, 0.1, 3.7);
  const pcl::Indices plate =
      scene.rectangle (Eigen::Vector3d (0, 1, 0), kX, kY, 1.0, 1.0, 0.02);
  const pcl::index_t shared = plate[17];
  for (const bool plate_first : {true, false}) {
    scene.segments.clear();
    pcl::Indices span_and_shared = span;
    span_and_shared.push_back (shared);
    if (plate_first) {
      scene.segment (plate);
      scene.segment (span_and_shared);
    }
    else {
      scene.segment (span_and_shared);
      scene.segment (plate);
    }
    Join j;
    const auto out = join (j, scene);
    EXPECT_EQ (checkPartition (out), scene.cloud->size());
    ASSERT_EQ (out.size(), 2u);
    const int with_shared = segmentOf (out, shared);
    EXPECT_EQ (with_shared, segmentOf (out, plate_first ? plate[0] : span[0]));
    EXPECT_NE (with_shared, segmentOf (out, plate_first ? span[0] : plate[0]));
  }
}
