/*
 * Tests of joinCurvesAcrossJunctions (Sithole & Mapurisa, section 4.1.2): curves that
 * cross or touch in a profile are followed across the junction their curve ends leave.
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace pcl_ext::profiles;

namespace {
constexpr double kSpacing = 0.02;
constexpr double kThreshold = 3.0 * kSpacing;
constexpr double kWindow = 2.0 * kThreshold;

/** A profile and, for every point, the curve it was drawn on. */
struct Drawing {
  ProfilePoints profile;
  std::vector<int> curve;
  std::mt19937 rng{7};

  /** Points every kSpacing along the parametric curve f(s), s in [0, length), with
   * noise of 1 mm across it and t spread over the profile's width. */
  template <typename Curve>
  void
  draw (int id, double length, Curve f)
  {
    std::normal_distribution<double> noise (0.0, 0.001);
    std::uniform_real_distribution<double> across (0.0, 1.5 * kSpacing);
    for (double s = 0.0; s < length; s += kSpacing) {
      const Eigen::Vector2d p = f (s);
      const Eigen::Vector2d tangent = (f (s + 1e-4) - p).normalized();
      const Eigen::Vector2d q =
          p + noise (rng) * Eigen::Vector2d (-tangent[1], tangent[0]);
      profile.uv.push_back (q.cast<float>());
      profile.t.push_back (static_cast<float> (across (rng)));
      curve.push_back (id);
    }
  }

  /** A straight line from \a from at \a degrees, \a length long. */
  void
  line (int id, Eigen::Vector2d from, double degrees, double length)
  {
    const double a = degrees * M_PI / 180.0;
    const Eigen::Vector2d d (std::cos (a), std::sin (a));
    draw (id, length, [&] (double s) -> Eigen::Vector2d { return from + s * d; });
  }
};

/** The pipeline's curve ends for one profile: a sharp turn or a residual well above the
 * profile's median (ProfileSegmentation's defaults). */
void
findCurveEnds (const Drawing& d,
               std::vector<LocalEdge>& chains,
               std::vector<std::uint8_t>& ends,
               double& tolerance)
{
  spanningTreeEdges (d.profile, kThreshold, chains);
  CurveFitParameters fit;
  fit.threshold = kThreshold;
  fit.window = kWindow;
  fit.tangent_radius = 0.5 * kWindow;
  CurveScores scores;
  scoreCurveTurns (d.profile, chains, fit, scores);
  std::vector<float> rms;
  for (std::size_t i = 0; i < scores.rms.size(); ++i)
    if (scores.evaluated[i])
      rms.push_back (scores.rms[i]);
  ASSERT_FALSE (rms.empty());
  std::nth_element (rms.begin(), rms.begin() + rms.size() / 2, rms.end());
  tolerance = std::max (3.0 * rms[rms.size() / 2], 0.1 * kThreshold);
  ends.assign (d.profile.uv.size(), 0);
  for (std::size_t i = 0; i < ends.size(); ++i)
    ends[i] = scores.evaluated[i] &&
              (scores.turn[i] > M_PI / 6.0 || scores.rms[i] > tolerance);
}

std::vector<LocalEdge>
joinsOf (const Drawing& d)
{
  std::vector<LocalEdge> chains, joins;
  std::vector<std::uint8_t> ends;
  double tolerance = 0.0;
  findCurveEnds (d, chains, ends, tolerance);
  EXPECT_GT (std::count (ends.begin(), ends.end(), 1), 0);
  JunctionParameters parameters;
  parameters.threshold = kThreshold;
  parameters.window = kWindow;
  parameters.max_turn = M_PI / 6.0;
  parameters.tolerance = tolerance;
  joinCurvesAcrossJunctions (d.profile, chains, ends, parameters, joins);
  for (const LocalEdge& e : joins) {
    EXPECT_LT (e.a, e.b);
    EXPECT_FALSE (ends[e.a]);
    EXPECT_FALSE (ends[e.b]);
  }
  return joins;
}
} // namespace

TEST (ProfileJunctions, CrossingCurvesContinueThroughTheCrossing)
{
  // Two lines crossing at the origin, at 60 and 90 degrees to each other: each is cut
  // by curve ends around the crossing, and each is joined to itself across it.
  for (const double angle : {60.0, 90.0}) {
    Drawing d;
    d.line (0, Eigen::Vector2d (-0.6, 0.0), 0.0, 1.2);
    const double a = angle * M_PI / 180.0;
    d.line (1, -0.6 * Eigen::Vector2d (std::cos (a), std::sin (a)), angle, 1.2);
    const auto joins = joinsOf (d);
    ASSERT_EQ (joins.size(), 2u) << angle << " degrees";
    int joined[2] = {0, 0};
    for (const LocalEdge& e : joins) {
      EXPECT_EQ (d.curve[e.a], d.curve[e.b]) << angle << " degrees";
      // The two sides of the crossing.
      const Eigen::Vector2f dir = d.curve[e.a] == 0
                                      ? Eigen::Vector2f (1.f, 0.f)
                                      : Eigen::Vector2f (std::cos (a), std::sin (a));
      EXPECT_LT (d.profile.uv[e.a].dot (dir) * d.profile.uv[e.b].dot (dir), 0.f);
      ++joined[d.curve[e.a]];
    }
    EXPECT_EQ (joined[0], 1);
    EXPECT_EQ (joined[1], 1);
  }
}

TEST (ProfileJunctions, ACurveContinuesPastABranch)
{
  // A pipe's section resting on a support (a T), and a branch leaving a trunk at 40
  // degrees (a Y): the straight curve is joined across, the branch is left.
  for (const double branch : {-90.0, 40.0}) {
    Drawing d;
    d.line (0, Eigen::Vector2d (-0.6, 0.0), 0.0, 1.2);
    const double a = branch * M_PI / 180.0;
    d.line (1, 0.03 * Eigen::Vector2d (std::cos (a), std::sin (a)), branch, 0.6);
    const auto joins = joinsOf (d);
    ASSERT_EQ (joins.size(), 1u) << "branch at " << branch;
    EXPECT_EQ (d.curve[joins[0].a], 0);
    EXPECT_EQ (d.curve[joins[0].b], 0);
    EXPECT_LT (d.profile.uv[joins[0].a][0] * d.profile.uv[joins[0].b][0], 0.f);
  }
}

TEST (ProfileJunctions, CreasesAndCornersAreNotJoined)
{
  // An L (two arms: a crease), and a V of two lines meeting at 90 degrees with a third
  // line leaving the vertex: no two arms continue each other.
  {
    Drawing d;
    d.line (0, Eigen::Vector2d (-0.6, 0.0), 0.0, 0.6);
    d.line (1, Eigen::Vector2d (0.0, 0.02), 90.0, 0.6);
    EXPECT_TRUE (joinsOf (d).empty());
  }
  {
    Drawing d;
    d.line (0, Eigen::Vector2d (0.0, 0.0), 45.0, 0.6);
    d.line (1, Eigen::Vector2d (-0.02, 0.02), 135.0, 0.6);
    d.line (2, Eigen::Vector2d (0.0, -0.03), -90.0, 0.6);
    EXPECT_TRUE (joinsOf (d).empty());
  }
}

TEST (ProfileJunctions, APipeOnTheFloorKeepsBothCurves)
{
  // The section of a pipe of radius 0.15 touching the floor: the floor is joined under
  // the pipe; the circle's ends leave the floor steeply and are not joined to it.
  Drawing d;
  d.line (0, Eigen::Vector2d (-0.8, 0.0), 0.0, 1.6);
  constexpr double r = 0.15;
  d.draw (1, 2.0 * M_PI * r, [&] (double s) -> Eigen::Vector2d {
    const double a = s / r;
    return Eigen::Vector2d (r * std::sin (a), r - r * std::cos (a) + 0.002);
  });
  const auto joins = joinsOf (d);
  ASSERT_FALSE (joins.empty());
  for (const LocalEdge& e : joins)
    EXPECT_EQ (d.curve[e.a], d.curve[e.b]);
  bool floor = false;
  for (const LocalEdge& e : joins)
    floor = floor ||
            (d.curve[e.a] == 0 && d.profile.uv[e.a][0] * d.profile.uv[e.b][0] < 0.f);
  EXPECT_TRUE (floor);
}

TEST (ProfileJunctions, NothingToJoinWithoutCurveEnds)
{
  Drawing d;
  d.line (0, Eigen::Vector2d (-0.6, 0.0), 0.0, 1.2);
  std::vector<LocalEdge> chains, joins{{0, 1}};
  spanningTreeEdges (d.profile, kThreshold, chains);
  const std::vector<std::uint8_t> ends (d.profile.uv.size(), 0);
  JunctionParameters parameters;
  parameters.threshold = kThreshold;
  parameters.window = kWindow;
  parameters.max_turn = M_PI / 6.0;
  parameters.tolerance = 0.003;
  joinCurvesAcrossJunctions (d.profile, chains, ends, parameters, joins);
  EXPECT_TRUE (joins.empty());
  // Flags that do not match the points, or a zero window: nothing, no crash.
  joinCurvesAcrossJunctions (d.profile, chains, {1, 0}, parameters, joins);
  EXPECT_TRUE (joins.empty());
  parameters.window = 0.0;
  joinCurvesAcrossJunctions (d.profile, chains, {}, parameters, joins);
  EXPECT_TRUE (joins.empty());
}
