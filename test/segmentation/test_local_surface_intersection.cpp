/*
 * Tests of pcl_ext::LocalSurfaceIntersection on half-planes with a known crease line or
 * step.
 */
#include <pcl_ext/segmentation/local_surface_intersection.h>

#include "lsi_test_clouds.h"

#include <pcl/common/io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <tuple>

using namespace lsi_test;
using Intersection = pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ>;
using IntersectionCloud = Intersection::IntersectionCloud;

namespace {
constexpr double kDeg = M_PI / 180.0;

struct Result {
  bool ok = false;
  IntersectionCloud intersections;
  LabelCloud labels;
  Intersection::Report report;
};

Result
run (const Scene& s,
     unsigned threads = 0,
     int k = 50,
     const std::function<void (Intersection&)>& configure = {})
{
  Intersection lsi;
  lsi.setInputCloud (s.cloud);
  lsi.setSegmentLabels (s.segments);
  lsi.setPointClasses (s.classes);
  lsi.setKSearch (k);
  lsi.setNumberOfThreads (threads);
  if (configure)
    configure (lsi);
  Result r;
  r.ok = lsi.compute (r.intersections, r.labels);
  r.report = lsi.getReport();
  return r;
}

/** Distances of the intersection points to the line, in double from the float output.
 */
std::vector<double>
distances (const IntersectionCloud& points,
           const Eigen::Vector3d& origin,
           const Eigen::Vector3d& along)
{
  std::vector<double> d;
  for (const auto& p : points)
    d.push_back (lineDistance (Eigen::Vector3d (p.x, p.y, p.z), origin, along));
  return d;
}

/** Fraction of the edge points (segment 0 in the input) labelled with their true
 * segment. */
double
rightlyReintegrated (const Scene& s, const LabelCloud& labels)
{
  std::size_t edges = 0, right = 0;
  for (std::size_t i = 0; i < s.truth.size(); ++i)
    if ((*s.segments)[i].label == 0) {
      ++edges;
      right += labels[i].label == s.truth[i];
    }
  return edges ? double (right) / double (edges) : 0.0;
}

double
quantile (std::vector<double> v, double q)
{
  std::sort (v.begin(), v.end());
  return v[static_cast<std::size_t> (q * (v.size() - 1))];
}

HalfPlanes
dihedral (double angle)
{
  HalfPlanes h;
  h.across[0] = Eigen::Vector3d::UnitY();
  h.across[1] = Eigen::Vector3d (0.0, std::cos (angle), std::sin (angle));
  return h;
}
} // namespace

TEST (LocalSurfaceIntersection, DihedralPointsLieOnTheCreaseToNoiseLevel)
{
  for (const double angle : {90.0, 60.0, 135.0}) {
    const HalfPlanes h = dihedral (angle * kDeg);
    const Scene s = makeHalfPlanes (h);
    const Result r = run (s);
    ASSERT_TRUE (r.ok);
    ASSERT_GT (r.intersections.size(), 40u) << angle;
    for (const auto& p : r.intersections) {
      const std::uint32_t a = std::min (p.segment_a, p.segment_b);
      const std::uint32_t b = std::max (p.segment_a, p.segment_b);
      EXPECT_EQ (a, 1u);
      EXPECT_EQ (b, 2u);
      EXPECT_EQ ((*s.segments)[p.index_a].label, p.segment_a);
      EXPECT_EQ ((*s.segments)[p.index_b].label, p.segment_b);
    }
    const auto d = distances (r.intersections, h.origin, h.along);
    const double med = median (d), q95 = quantile (d, 0.95);
    std::cout << "[ dihedral " << angle << " deg ] " << r.intersections.size()
              << " points, distance to the crease: median " << med << ", 95% " << q95
              << " (noise " << h.noise << "); edge points re-integrated right "
              << rightlyReintegrated (s, r.labels) << "\n";
    // The error of a plane fitted to one side of its point's neighbourhood,
    // extrapolated to the crease, is about the noise (normal error sigma / (spread
    // sqrt(n)) times a lever arm of about the spread).
    EXPECT_LT (med, 1.5 * h.noise);
    EXPECT_LT (q95, 4.0 * h.noise);
    EXPECT_EQ (r.report.intersections, r.intersections.size());
    EXPECT_EQ (r.report.pairs,
               r.report.intersections + r.report.parallel + r.report.beyond_tolerance +
                   r.report.no_plane);
    EXPECT_EQ (r.report.parallel, 0u);
    EXPECT_EQ (r.report.examined,
               r.report.reintegrated + r.report.ambiguous + r.report.left);
    EXPECT_GE (rightlyReintegrated (s, r.labels), 0.9) << angle;
  }
}

TEST (LocalSurfaceIntersection, GivenNormalsAreUsed)
{
  const HalfPlanes h = dihedral (90.0 * kDeg);
  const Scene s = makeHalfPlanes (h);
  const Result with_true =
      run (s, 0, 50, [&] (Intersection& l) { l.setInputNormals (s.normals); });
  ASSERT_TRUE (with_true.ok);
  ASSERT_GT (with_true.intersections.size(), 40u);
  EXPECT_LT (median (distances (with_true.intersections, h.origin, h.along)), h.noise);

  // Normals all equal: every pair is parallel (eq. 9), which the planes' own fit would
  // not say.
  pcl::PointCloud<pcl::Normal>::Ptr up (new pcl::PointCloud<pcl::Normal>);
  up->resize (s.cloud->size(), pcl::Normal (0.f, 0.f, 1.f));
  const Result with_up =
      run (s, 0, 50, [&] (Intersection& l) { l.setInputNormals (up); });
  ASSERT_TRUE (with_up.ok);
  EXPECT_TRUE (with_up.intersections.empty());
  EXPECT_EQ (with_up.report.parallel, with_up.report.pairs);
  EXPECT_GT (with_up.report.pairs, 0u);
}

TEST (LocalSurfaceIntersection, GeoreferencedCoordinates)
{
  // The crease runs along x at x = 6,000,000 m, where floats step by 0.5 m: samples
  // along it lie on that grid, the cross-section is at full precision.
  HalfPlanes h = dihedral (90.0 * kDeg);
  h.origin = Eigen::Vector3d (6000000.0, 0.0, 0.0);
  h.length = 20.0;
  h.spacing_along = 0.5;
  h.spacing_across = 0.05;
  h.width = 1.0;
  h.band = 0.08;
  h.noise = 0.002;
  const Scene s = makeHalfPlanes (h);
  const Result r = run (s);
  ASSERT_TRUE (r.ok);
  ASSERT_GT (r.intersections.size(), 20u);
  const double med = median (distances (r.intersections, h.origin, h.along));
  std::cout << "[ x = 6e6 m ] " << r.intersections.size() << " points, median distance "
            << med << "\n";
  EXPECT_LT (med, 1.5 * h.noise);
  EXPECT_GE (rightlyReintegrated (s, r.labels), 0.9);
}

TEST (LocalSurfaceIntersection, ParallelPlanesGiveNoIntersection)
{
  // A step: two horizontal half-planes, the second 3 cm higher (a jump discontinuity).
  HalfPlanes h;
  h.across[0] = Eigen::Vector3d::UnitY();
  h.across[1] = -Eigen::Vector3d::UnitY();
  h.offset[1] = Eigen::Vector3d (0.0, -0.01, 0.03);
  h.band = 0.03;
  const Scene s = makeHalfPlanes (h);
  const Result r = run (s);
  ASSERT_TRUE (r.ok);
  EXPECT_TRUE (r.intersections.empty());
  EXPECT_GT (r.report.pairs, 0u);
  EXPECT_EQ (r.report.parallel, r.report.pairs);
  // The border points of each level still fit their own plane only.
  EXPECT_GE (rightlyReintegrated (s, r.labels), 0.9);
  EXPECT_EQ (r.report.ambiguous, 0u);
}

TEST (LocalSurfaceIntersection, ParallelAngleThreshold)
{
  // A 5 degree crease: parallel for the default 10 degrees, intersected with a 2 degree
  // threshold.
  HalfPlanes h = dihedral (175.0 * kDeg);
  h.noise = 0.0002;
  const Scene s = makeHalfPlanes (h);
  const Result coarse = run (s);
  ASSERT_TRUE (coarse.ok);
  EXPECT_TRUE (coarse.intersections.empty());
  EXPECT_EQ (coarse.report.parallel, coarse.report.pairs);
  const Result fine = run (
      s, 0, 50, [] (Intersection& l) { l.setParallelAngleThreshold (2.0 * kDeg); });
  ASSERT_TRUE (fine.ok);
  ASSERT_GT (fine.intersections.size(), 40u);
  // Error grows as 1 / sin(theta): 5 degrees magnify the noise about 11 times.
  EXPECT_LT (median (distances (fine.intersections, h.origin, h.along)),
             h.noise / std::sin (5.0 * kDeg));
}

TEST (LocalSurfaceIntersection, FarIntersectionsAreRejected)
{
  // Not touching: the second half-plane is tilted by 15 degrees and lifted 3 cm, so its
  // plane meets the first 11 cm behind the first's border, farther than the points are
  // apart.
  HalfPlanes h;
  h.across[0] = -Eigen::Vector3d::UnitY();
  h.across[1] = Eigen::Vector3d (0.0, std::cos (15.0 * kDeg), std::sin (15.0 * kDeg));
  h.offset[1] = Eigen::Vector3d (0.0, 0.0, 0.03);
  h.spacing_across = h.spacing_along = 0.01;
  h.width = 0.2;
  h.length = 0.5;
  h.noise = 0.0005;
  h.band = 0.0;
  const Scene s = makeHalfPlanes (h);
  const Result r = run (s, 0, 50);
  ASSERT_TRUE (r.ok);
  EXPECT_GT (r.report.pairs, 0u);
  EXPECT_TRUE (r.intersections.empty());
  EXPECT_EQ (r.report.beyond_tolerance, r.report.pairs);
  // With a tolerance of 20 cm they are kept, on the planes' true intersection line.
  const Result loose =
      run (s, 0, 50, [] (Intersection& l) { l.setDistanceTolerance (0.2); });
  ASSERT_TRUE (loose.ok);
  ASSERT_FALSE (loose.intersections.empty());
  const Eigen::Vector3d line_origin (0.0, -0.03 / std::tan (15.0 * kDeg), 0.0);
  EXPECT_LT (median (distances (loose.intersections, line_origin, h.along)), 0.01);
}

TEST (LocalSurfaceIntersection, ReachLimitsThePartners)
{
  const Scene s = makeHalfPlanes (dihedral (90.0 * kDeg));
  // The nearest surface points of the two segments are at least 3 cm x sqrt(2) apart.
  const Result r = run (s, 0, 50, [] (Intersection& l) { l.setReach (0.01); });
  ASSERT_TRUE (r.ok);
  EXPECT_EQ (r.report.pairs, 0u);
  EXPECT_TRUE (r.intersections.empty());
  // Edge points farther than 1 cm from every surface point have nothing to fit.
  EXPECT_GT (r.report.left, 0u);
  const Result all = run (s);
  EXPECT_LT (all.report.left, r.report.left);
}

TEST (LocalSurfaceIntersection, AmbiguousPointsCanBeLeft)
{
  // A 150 degree crease: the 1 cm band next to it fits both planes within 3 x 1 mm
  // noise.
  HalfPlanes h = dihedral (150.0 * kDeg);
  const Scene s = makeHalfPlanes (h);
  const Result assign = run (s);
  const Result leave =
      run (s, 0, 50, [] (Intersection& l) { l.setAssignAmbiguous (false); });
  ASSERT_TRUE (assign.ok && leave.ok);
  EXPECT_GT (assign.report.ambiguous, 0u);
  EXPECT_EQ (assign.report.ambiguous, leave.report.ambiguous);
  std::size_t assigned = 0, left = 0;
  for (std::size_t i = 0; i < s.truth.size(); ++i) {
    assigned += assign.labels[i].label != 0 && (*s.segments)[i].label == 0;
    left += leave.labels[i].label != 0 && (*s.segments)[i].label == 0;
  }
  EXPECT_EQ (assigned, assign.report.reintegrated + assign.report.ambiguous);
  EXPECT_EQ (left, leave.report.reintegrated);
}

TEST (LocalSurfaceIntersection, DeterministicForAnyThreadCountAndRun)
{
  const Scene s = makeHalfPlanes (dihedral (70.0 * kDeg));
  const Result one = run (s, 1), two = run (s, 2), again = run (s, 2);
  for (const Result* other : {&two, &again}) {
    ASSERT_EQ (one.intersections.size(), other->intersections.size());
    for (std::size_t i = 0; i < one.intersections.size(); ++i) {
      EXPECT_EQ (one.intersections[i].x, other->intersections[i].x);
      EXPECT_EQ (one.intersections[i].y, other->intersections[i].y);
      EXPECT_EQ (one.intersections[i].z, other->intersections[i].z);
      EXPECT_EQ (one.intersections[i].index_a, other->intersections[i].index_a);
      EXPECT_EQ (one.intersections[i].index_b, other->intersections[i].index_b);
    }
    ASSERT_EQ (one.labels.size(), other->labels.size());
    for (std::size_t i = 0; i < one.labels.size(); ++i)
      EXPECT_EQ (one.labels[i].label, other->labels[i].label);
    EXPECT_EQ (one.report.reintegrated, other->report.reintegrated);
    EXPECT_EQ (one.report.ambiguous, other->report.ambiguous);
  }
}

TEST (LocalSurfaceIntersection, ResultsDoNotDependOnTheOrderOfTheIndices)
{
  // Nearby points share one search for their partners, grouped in the order the
  // indices give them; reversed and shuffled orders group them otherwise and must find
  // the same pairs and re-integrate the same points.
  const Scene s = makeHalfPlanes (dihedral (70.0 * kDeg));
  pcl::IndicesPtr reversed (new pcl::Indices), shuffled (new pcl::Indices);
  for (std::size_t i = s.cloud->size(); i-- > 0;)
    reversed->push_back (static_cast<pcl::index_t> (i));
  *shuffled = *reversed;
  std::mt19937 rng (11);
  std::shuffle (shuffled->begin(), shuffled->end(), rng);
  const auto pairs = [] (const IntersectionCloud& points) {
    std::vector<std::tuple<pcl::index_t, pcl::index_t, float, float, float>> p;
    for (const auto& q : points)
      p.emplace_back (std::min (q.index_a, q.index_b),
                      std::max (q.index_a, q.index_b),
                      q.x,
                      q.y,
                      q.z);
    std::sort (p.begin(), p.end());
    return p;
  };
  // The default reach, and one just above the 3 cm x sqrt(2) gap between the two
  // segments' nearest points, where partners lie near its limit.
  for (const double reach : {0.0, 0.05}) {
    const Result natural =
        run (s, 2, 50, [&] (Intersection& l) { l.setReach (reach); });
    ASSERT_TRUE (natural.ok);
    ASSERT_GT (natural.intersections.size(), 0u);
    ASSERT_GT (natural.report.reintegrated, 0u);
    for (const auto& order : {reversed, shuffled}) {
      const Result other = run (s, 2, 50, [&] (Intersection& l) {
        l.setReach (reach);
        l.setIndices (order);
      });
      ASSERT_TRUE (other.ok);
      EXPECT_EQ (pairs (natural.intersections), pairs (other.intersections));
      ASSERT_EQ (natural.labels.size(), other.labels.size());
      for (std::size_t i = 0; i < natural.labels.size(); ++i)
        EXPECT_EQ (natural.labels[i].label, other.labels[i].label);
      EXPECT_EQ (natural.report.reintegrated, other.report.reintegrated);
      EXPECT_EQ (natural.report.ambiguous, other.report.ambiguous);
    }
  }
}

TEST (LocalSurfaceIntersection, IndicesRestrictTheExaminedPoints)
{
  const Scene s = makeHalfPlanes (dihedral (90.0 * kDeg));
  pcl::IndicesPtr first (new pcl::Indices);
  for (std::size_t i = 0; i < s.cloud->size(); ++i)
    if (s.truth[i] == 1)
      first->push_back (static_cast<pcl::index_t> (i));
  const Result all = run (s);
  const Result part = run (s, 0, 50, [&] (Intersection& l) { l.setIndices (first); });
  ASSERT_TRUE (part.ok);
  // Every pair has one point in each half; from half 1 only, each is found once still.
  EXPECT_GT (part.intersections.size(), 0u);
  for (const auto& p : part.intersections)
    EXPECT_EQ (s.truth[p.index_a], 1u);
  EXPECT_GE (part.intersections.size(), all.intersections.size() / 2);
  // Only the edge points of half 1 are re-integrated; the labels still cover the cloud.
  ASSERT_EQ (part.labels.size(), s.cloud->size());
  for (std::size_t i = 0; i < s.truth.size(); ++i)
    if (s.truth[i] == 2)
      EXPECT_EQ (part.labels[i].label, (*s.segments)[i].label);
}

// ---- bad input: PCL_ERROR and empty output, or a clear result ----

TEST (LocalSurfaceIntersection, BadInputGivesErrorsAndEmptyOutput)
{
  const Scene s = makeHalfPlanes (dihedral (90.0 * kDeg));
  const auto fails = [] (const std::function<void (Intersection&)>& setup) {
    Intersection lsi;
    lsi.setKSearch (30);
    setup (lsi);
    IntersectionCloud points;
    points.resize (3);
    LabelCloud labels;
    labels.resize (3);
    const bool ok = lsi.compute (points, labels);
    return !ok && points.empty() && labels.empty();
  };
  const Cloud::Ptr empty (new Cloud);
  const LabelCloud::Ptr no_labels (new LabelCloud);
  LabelCloud::Ptr short_labels (new LabelCloud (*s.segments));
  short_labels->resize (short_labels->size() - 1);
  const auto full = [&] (Intersection& l) {
    l.setInputCloud (s.cloud);
    l.setSegmentLabels (s.segments);
    l.setPointClasses (s.classes);
  };
  EXPECT_TRUE (fails ([] (Intersection&) {})); // no cloud
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    l.setInputCloud (empty);
    l.setSegmentLabels (no_labels);
    l.setPointClasses (no_labels);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setSegmentLabels (nullptr);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setSegmentLabels (no_labels);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setSegmentLabels (short_labels);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setPointClasses (short_labels);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    pcl::PointCloud<pcl::Normal>::Ptr few (new pcl::PointCloud<pcl::Normal>);
    few->resize (5);
    l.setInputNormals (few);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setKSearch (2);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setParallelAngleThreshold (2.0);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setParallelAngleThreshold (-0.1);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setDistanceTolerance (-1.0);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setReach (std::numeric_limits<double>::quiet_NaN());
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setFitTolerance (-1e-3);
  }));
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    pcl::IndicesPtr bad (
        new pcl::Indices{0, static_cast<pcl::index_t> (s.cloud->size())});
    l.setIndices (bad);
  }));
  // k larger than the cloud: the neighbourhood search refuses it.
  EXPECT_TRUE (fails ([&] (Intersection& l) {
    full (l);
    l.setKSearch (static_cast<int> (s.cloud->size()) + 1);
  }));
}

TEST (LocalSurfaceIntersection, NoSegmentedSurfacePointIsAnError)
{
  const Scene s = makeHalfPlanes (dihedral (90.0 * kDeg));
  // Every point an edge point.
  LabelCloud::Ptr edges (new LabelCloud (*s.classes));
  for (auto& c : *edges)
    c.label = static_cast<std::uint32_t> (pcl_ext::PointClass::Edge);
  Result r = run (s, 0, 50, [&] (Intersection& l) { l.setPointClasses (edges); });
  EXPECT_FALSE (r.ok);
  EXPECT_TRUE (r.intersections.empty() && r.labels.empty());
  // Surface points, but none in a segment.
  LabelCloud::Ptr zeros (new LabelCloud (*s.segments));
  for (auto& l : *zeros)
    l.label = 0;
  r = run (s, 0, 50, [&] (Intersection& l) { l.setSegmentLabels (zeros); });
  EXPECT_FALSE (r.ok);
  EXPECT_TRUE (r.intersections.empty() && r.labels.empty());
}

TEST (LocalSurfaceIntersection, OneSegmentHasNothingToIntersect)
{
  // A flat sheet, all one segment, with an edge band in the middle: no intersection,
  // and the band goes back into the one segment.
  HalfPlanes h;
  h.across[1] = -Eigen::Vector3d::UnitY();
  Scene s = makeHalfPlanes (h);
  for (auto& l : *s.segments)
    l.label = l.label ? 7u : 0u;
  const Result r = run (s);
  ASSERT_TRUE (r.ok);
  EXPECT_TRUE (r.intersections.empty());
  EXPECT_EQ (r.report.pairs, 0u);
  EXPECT_GT (r.report.examined, 0u);
  EXPECT_EQ (r.report.ambiguous, 0u);
  // The 3 sigma fit test keeps nearly all of the band (a few noisy points are left).
  EXPECT_GE (r.report.reintegrated, 0.95 * r.report.examined);
  for (const auto& l : r.labels)
    EXPECT_TRUE (l.label == 7u || l.label == 0u);
}

TEST (LocalSurfaceIntersection, NonFinitePointsAreSkipped)
{
  const HalfPlanes h = dihedral (90.0 * kDeg);
  Scene s = makeHalfPlanes (h);
  const Result clean = run (s);
  const std::size_t n = s.cloud->size();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // NaN points of every kind: surface with a segment, edge without.
  for (std::size_t i = 0; i < n; i += 97)
    (*s.cloud)[i].x = nan;
  s.cloud->is_dense = false;
  const Result r = run (s);
  ASSERT_TRUE (r.ok);
  ASSERT_GT (r.intersections.size(), clean.intersections.size() / 2);
  EXPECT_LT (median (distances (r.intersections, h.origin, h.along)), h.noise);
  for (const auto& p : r.intersections) {
    EXPECT_TRUE (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z));
    EXPECT_TRUE (std::isfinite ((*s.cloud)[p.index_a].x));
    EXPECT_TRUE (std::isfinite ((*s.cloud)[p.index_b].x));
  }
  for (std::size_t i = 0; i < n; i += 97)
    EXPECT_EQ (r.labels[i].label, (*s.segments)[i].label); // untouched
}

TEST (LocalSurfaceIntersection, OnePointSegmentsHaveNoPlane)
{
  const HalfPlanes h = dihedral (90.0 * kDeg);
  Scene s = makeHalfPlanes (h);
  const Result clean = run (s);
  // Scatter single-point segments 100, 101, ... over both halves.
  std::uint32_t next = 100;
  for (std::size_t i = 0; i < s.cloud->size(); i += 53)
    if ((*s.segments)[i].label != 0)
      (*s.segments)[i].label = next++;
  const Result r = run (s);
  ASSERT_TRUE (r.ok);
  EXPECT_GT (r.report.no_plane, 0u);
  for (const auto& p : r.intersections) {
    EXPECT_LT (p.segment_a, 100u);
    EXPECT_LT (p.segment_b, 100u);
  }
  EXPECT_GT (r.intersections.size(), clean.intersections.size() / 2);
  EXPECT_LT (median (distances (r.intersections, h.origin, h.along)), h.noise);
}

TEST (LocalSurfaceIntersection, PrecompiledPointTypes)
{
  const Scene s = makeHalfPlanes (dihedral (90.0 * kDeg));
  pcl::PointCloud<pcl::PointXYZRGBNormal>::Ptr rich (
      new pcl::PointCloud<pcl::PointXYZRGBNormal>);
  pcl::copyPointCloud (*s.cloud, *rich);
  pcl_ext::LocalSurfaceIntersection<pcl::PointXYZRGBNormal> lsi;
  lsi.setInputCloud (rich);
  lsi.setSegmentLabels (s.segments);
  lsi.setPointClasses (s.classes);
  lsi.setKSearch (50);
  IntersectionCloud points;
  LabelCloud labels;
  ASSERT_TRUE (lsi.compute (points, labels));
  EXPECT_EQ (points.size(), run (s).intersections.size());
}
