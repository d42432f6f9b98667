/*
 * Tests of the curve-reconstruction profile segmenter (profiles::crustEdges) on curves
 * whose edges are known.
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

using namespace pcl_ext::profiles;

namespace {
/** \a n points on a circle of radius \a r about the origin, starting at angle \a a0. */
void
addCircle (ProfilePoints& profile, double r, int n, double a0 = 0.0)
{
  for (int i = 0; i < n; ++i) {
    const double a = a0 + 2.0 * M_PI * i / n;
    profile.uv.emplace_back (static_cast<float> (r * std::cos (a)),
                             static_cast<float> (r * std::sin (a)));
    profile.t.push_back (0.f);
  }
}

/** The component of every point of the graph. */
std::vector<std::uint32_t>
components (std::size_t n, const std::vector<LocalEdge>& edges)
{
  std::vector<std::uint32_t> parent (n);
  std::iota (parent.begin(), parent.end(), 0u);
  const auto find = [&] (std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& e : edges)
    parent[find (e.a)] = find (e.b);
  std::vector<std::uint32_t> out (n);
  for (std::uint32_t i = 0; i < n; ++i)
    out[i] = find (i);
  return out;
}

std::size_t
countComponents (std::size_t n, const std::vector<LocalEdge>& edges)
{
  const auto c = components (n, edges);
  return std::set<std::uint32_t> (c.begin(), c.end()).size();
}
} // namespace

TEST (ProfileCrust, ACircleIsItsPolygon)
{
  // A closed curve sampled evenly: the crust is the polygon through the samples, each
  // sample linked to its two neighbours along the curve and to nothing else.
  ProfilePoints profile;
  const int n = 300;
  addCircle (profile, 1.0, n);
  std::vector<LocalEdge> edges;
  crustEdges (profile, 0.1, edges);
  ASSERT_EQ (edges.size(), static_cast<std::size_t> (n));
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    expected.insert ({std::min (i, j), std::max (i, j)});
  }
  for (const auto& e : edges)
    EXPECT_EQ (expected.count ({e.a, e.b}), 1u) << e.a << "-" << e.b;
}

TEST (ProfileCrust, NestedCurvesCloserThanTheThresholdStayApart)
{
  // The profile of two nested spheres (section 5.2): circles 0.035 apart, sampled every
  // 0.021, threshold 0.08. Proximity chaining links across; the crust does not.
  ProfilePoints profile;
  addCircle (profile, 1.0, 300);
  addCircle (profile, 1.035, 310, 0.01);
  const std::size_t n = profile.uv.size();
  std::vector<LocalEdge> proximity, crust;
  proximityEdges (profile, 0.08, 4, proximity);
  EXPECT_EQ (countComponents (n, proximity), 1u);
  crustEdges (profile, 0.08, crust);
  const auto c = components (n, crust);
  EXPECT_EQ (std::set<std::uint32_t> (c.begin(), c.end()).size(), 2u);
  for (std::size_t i = 1; i < n; ++i)
    EXPECT_EQ (c[i] == c[0], i < 300) << "point " << i;
}

TEST (ProfileCrust, LinksLongerThanTheThresholdAreCut)
{
  // Two arcs of one circle with a gap of 0.3 between their ends: two curves at a
  // threshold of 0.1, one at 0.5.
  ProfilePoints profile;
  for (int i = 0; i < 200; ++i) {
    if (i >= 90 && i < 100)
      continue; // the gap: 10 samples of 0.0314
    const double a = 2.0 * M_PI * i / 200;
    profile.uv.emplace_back (static_cast<float> (std::cos (a)),
                             static_cast<float> (std::sin (a)));
    profile.t.push_back (0.f);
  }
  profile.uv.resize (profile.uv.size() - 10); // open the other end as well
  profile.t.resize (profile.uv.size());
  std::vector<LocalEdge> edges;
  crustEdges (profile, 0.1, edges);
  EXPECT_EQ (countComponents (profile.uv.size(), edges), 2u);
  crustEdges (profile, 0.5, edges);
  EXPECT_EQ (countComponents (profile.uv.size(), edges), 1u);
  // Per-point thresholds: the smaller of the two ends decides.
  std::vector<float> thresholds (profile.uv.size(), 0.5f);
  thresholds[0] = 0.1f;
  crustEdges (profile, 0.5, edges, &thresholds);
  EXPECT_EQ (countComponents (profile.uv.size(), edges), 1u);
}

TEST (ProfileCrust, CoincidentPointsAndDegenerateProfiles)
{
  ProfilePoints profile;
  addCircle (profile, 1.0, 100);
  profile.uv.push_back (profile.uv[10]); // duplicates of point 10
  profile.uv.push_back (profile.uv[10]);
  profile.t.resize (profile.uv.size(), 0.f);
  std::vector<LocalEdge> edges;
  crustEdges (profile, 0.1, edges);
  EXPECT_EQ (countComponents (profile.uv.size(), edges), 1u);
  EXPECT_EQ (edges.size(), 102u); // the polygon and the two duplicates on point 10
  // One point, a negative or NaN threshold: no edge.
  ProfilePoints one;
  one.uv.emplace_back (0.f, 0.f);
  one.t.push_back (0.f);
  crustEdges (one, 0.1, edges);
  EXPECT_TRUE (edges.empty());
  crustEdges (profile, -1.0, edges);
  EXPECT_TRUE (edges.empty());
  crustEdges (profile, std::nan (""), edges);
  EXPECT_TRUE (edges.empty());
}
