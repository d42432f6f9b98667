/*
 * LeftoverRegionGrowing: new segments among the points a segmentation left out, on
 * clouds of known geometry (a pipe, two faces meeting at a right-angled crease, a
 * segmented plane that must stay as it is), and its bad input.
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Labels = pcl::PointCloud<pcl::Label>;

enum LeftoverPart : std::uint32_t { kSegmentedPlane, kPipe, kFaceA, kFaceB };

/** A cloud of four parts, uniformly sampled at about 1 cm with 0.5 mm noise: a 2 x 2 m
 * floor at z = 0 (already segment 7), a pipe of radius 0.1 m along x at height 0.5 m
 * (1.5 m long, its whole circumference), and two 0.15 m-wide, 1 m-long faces meeting at
 * a right angle (a narrow box edge at x = 1.5, y = 1), each a few neighbourhoods wide.
 */
struct LeftoverScene {
  Cloud::Ptr cloud = pcl::make_shared<Cloud>();
  std::vector<LeftoverPart> part;
  Labels::Ptr labels = pcl::make_shared<Labels>();
};

LeftoverScene
makeLeftoverScene ()
{
  LeftoverScene s;
  pcl_ext::RandomStream random (2024);
  const auto noise = [&random] {
    return static_cast<float> (0.0005 * random.gaussian());
  };
  const auto add = [&s] (float x, float y, float z, LeftoverPart part) {
    s.cloud->push_back (Point (x, y, z));
    s.part.push_back (part);
    pcl::Label l;
    l.label = part == kSegmentedPlane ? 7u : 0u;
    s.labels->push_back (l);
  };
  for (int i = 0; i < 40000; ++i)
    add (static_cast<float> (-0.5 + 2.0 * random.uniform()),
         static_cast<float> (-1.5 + 2.0 * random.uniform()),
         noise(),
         kSegmentedPlane);
  for (int i = 0; i < 9000; ++i) {
    const double a = 2.0 * M_PI * random.uniform();
    const double r = 0.1 + 0.0005 * random.gaussian();
    add (static_cast<float> (1.5 * random.uniform()),
         static_cast<float> (r * std::cos (a)),
         static_cast<float> (0.5 + r * std::sin (a)),
         kPipe);
  }
  for (int i = 0; i < 1500; ++i) // face A: the plane y = 1, x in [1.35, 1.5]
    add (static_cast<float> (1.35 + 0.15 * random.uniform()),
         1.0f + noise(),
         static_cast<float> (1.0 + random.uniform()),
         kFaceA);
  for (int i = 0; i < 1500; ++i) // face B: the plane x = 1.5, y in [1, 1.15]
    add (1.5f + noise(),
         static_cast<float> (1.0 + 0.15 * random.uniform()),
         static_cast<float> (1.0 + random.uniform()),
         kFaceB);
  return s;
}

Labels
growLeftovers (const LeftoverScene& s, double angle_degrees, unsigned int threads = 2)
{
  pcl_ext::LeftoverRegionGrowing<Point> growing;
  growing.setInputCloud (s.cloud);
  growing.setSegmentLabels (s.labels);
  growing.setAngleThreshold (angle_degrees * M_PI / 180.0);
  growing.setNumberOfThreads (threads);
  Labels out;
  EXPECT_TRUE (growing.compute (out));
  return out;
}

/** The label most points of \a part got, and how many did. */
std::pair<std::uint32_t, std::size_t>
leftoverMajority (const LeftoverScene& s, const Labels& out, LeftoverPart part)
{
  std::map<std::uint32_t, std::size_t> count;
  for (std::size_t i = 0; i < s.part.size(); ++i)
    if (s.part[i] == part)
      ++count[out[i].label];
  std::pair<std::uint32_t, std::size_t> best (0, 0);
  for (const auto& c : count)
    if (c.second > best.second)
      best = c;
  return best;
}
} // namespace

TEST (LeftoverRegionGrowing, PipeAndEachFaceBecomeOneNewSegment)
{
  const LeftoverScene s = makeLeftoverScene();
  const Labels out = growLeftovers (s, 25.0);
  ASSERT_EQ (out.size(), s.cloud->size());
  // The segmented floor keeps its label, and nothing else takes it.
  for (std::size_t i = 0; i < s.part.size(); ++i)
    ASSERT_EQ (out[i].label == 7u, s.part[i] == kSegmentedPlane) << i;
  // Neighbouring normals on the pipe differ by the spacing over the radius (about 6
  // degrees): it grows whole.
  const auto pipe = leftoverMajority (s, out, kPipe);
  EXPECT_NE (pipe.first, 0u);
  EXPECT_GT (pipe.second, 0.97 * 9000);
  // The crease between the two faces stops the growth: two segments, neither the pipe.
  const auto a = leftoverMajority (s, out, kFaceA);
  const auto b = leftoverMajority (s, out, kFaceB);
  EXPECT_NE (a.first, 0u);
  EXPECT_NE (b.first, 0u);
  EXPECT_NE (a.first, b.first);
  EXPECT_NE (a.first, pipe.first);
  EXPECT_GT (a.second, 0.85 * 1500);
  EXPECT_GT (b.second, 0.85 * 1500);
  // New segments are numbered after the largest input label, largest first.
  EXPECT_EQ (pipe.first, 8u);
  std::map<std::uint32_t, std::size_t> size;
  for (const auto& l : out)
    ++size[l.label];
  for (auto it = size.find (8u); it != size.end() && std::next (it) != size.end(); ++it)
    EXPECT_GE (it->second, std::next (it)->second) << it->first;
}

TEST (LeftoverRegionGrowing, WithoutTheCurvatureLimitTheCreaseIsCrossed)
{
  // With no limit on the patches' curvature the crease's points link too, and the
  // normals turning a few degrees from one to the next join the two faces.
  const LeftoverScene s = makeLeftoverScene();
  pcl_ext::LeftoverRegionGrowing<Point> growing;
  growing.setInputCloud (s.cloud);
  growing.setSegmentLabels (s.labels);
  growing.setMaxCurvature (1.0);
  Labels out;
  ASSERT_TRUE (growing.compute (out));
  EXPECT_EQ (leftoverMajority (s, out, kFaceA).first,
             leftoverMajority (s, out, kFaceB).first);
}

TEST (LeftoverRegionGrowing, GroupsOutsideTheSizeLimitsStayOut)
{
  const LeftoverScene s = makeLeftoverScene();
  pcl_ext::LeftoverRegionGrowing<Point> growing;
  growing.setInputCloud (s.cloud);
  growing.setSegmentLabels (s.labels);
  growing.setMinClusterSize (2000); // the faces have 1,500 points each
  Labels out;
  ASSERT_TRUE (growing.compute (out));
  EXPECT_EQ (growing.getReport().segments, 1u);
  EXPECT_EQ (leftoverMajority (s, out, kFaceA).first, 0u);
  EXPECT_EQ (leftoverMajority (s, out, kFaceB).first, 0u);
  EXPECT_EQ (growing.getReport().examined, 12000u);
  // And above the maximum: the pipe (9,000 points) too.
  growing.setMinClusterSize (50);
  growing.setMaxClusterSize (5000);
  ASSERT_TRUE (growing.compute (out));
  EXPECT_EQ (leftoverMajority (s, out, kPipe).first, 0u);
  EXPECT_NE (leftoverMajority (s, out, kFaceA).first, 0u);
}

TEST (LeftoverRegionGrowing, DeterministicAcrossThreadCounts)
{
  const LeftoverScene s = makeLeftoverScene();
  const Labels one = growLeftovers (s, 25.0, 1);
  const Labels two = growLeftovers (s, 25.0, 2);
  ASSERT_EQ (one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    ASSERT_EQ (one[i].label, two[i].label) << i;
}

TEST (LeftoverRegionGrowing, NaNPointsStayWithoutSegment)
{
  LeftoverScene s = makeLeftoverScene();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < s.cloud->size(); i += 97)
    (*s.cloud)[i].x = nan;
  s.cloud->is_dense = false;
  const Labels out = growLeftovers (s, 25.0);
  ASSERT_EQ (out.size(), s.cloud->size());
  for (std::size_t i = 0; i < s.cloud->size(); i += 97)
    EXPECT_EQ (out[i].label, s.part[i] == kSegmentedPlane ? 7u : 0u) << i;
  EXPECT_NE (leftoverMajority (s, out, kPipe).first, 0u);
}

TEST (LeftoverRegionGrowing, OnlyTheLinkingPointsMakeLinks)
{
  // Links made from the points with x < 0.75 only: the rest of the pipe, and the two
  // faces (x >= 1.35), link nothing of their own and stay without a segment, but for
  // the pipe's points within a neighbourhood of x = 0.75, linked to from the left.
  const LeftoverScene s = makeLeftoverScene();
  const auto growFrom = [&s] (bool left, pcl::uindex_t min_size) {
    auto linking = pcl::make_shared<pcl::Indices>();
    for (std::size_t i = 0; i < s.cloud->size(); ++i)
      if (((*s.cloud)[i].x < 0.75f) == left)
        linking->push_back (static_cast<pcl::index_t> (i));
    pcl_ext::LeftoverRegionGrowing<Point> growing;
    growing.setInputCloud (s.cloud);
    growing.setSegmentLabels (s.labels);
    growing.setLinkingIndices (linking);
    growing.setMinClusterSize (min_size);
    Labels out;
    EXPECT_TRUE (growing.compute (out));
    return out;
  };
  const Labels left = growFrom (true, 50);
  ASSERT_EQ (left.size(), s.cloud->size());
  const auto pipe = leftoverMajority (s, left, kPipe);
  ASSERT_NE (pipe.first, 0u);
  for (std::size_t i = 0; i < s.part.size(); ++i) {
    const float x = (*s.cloud)[i].x;
    if (s.part[i] == kPipe && x < 0.7f)
      EXPECT_EQ (left[i].label, pipe.first) << i;
    if ((s.part[i] == kPipe && x > 0.8f) || s.part[i] == kFaceA || s.part[i] == kFaceB)
      EXPECT_EQ (left[i].label, 0u) << i;
  }

  // The groups of two runs whose linking points part the cloud, joined through the
  // points both group (every one, with groups of one point kept), are the groups of
  // one run over the whole cloud: every link is made in one of the two.
  pcl_ext::LeftoverRegionGrowing<Point> whole;
  whole.setInputCloud (s.cloud);
  whole.setSegmentLabels (s.labels);
  whole.setMinClusterSize (1);
  Labels all;
  ASSERT_TRUE (whole.compute (all));
  const Labels a = growFrom (true, 1), b = growFrom (false, 1);
  std::map<std::uint32_t, std::uint32_t> parent; // over a's labels and b's + 2^31
  const std::function<std::uint32_t (std::uint32_t)> find = [&] (std::uint32_t x) {
    auto it = parent.emplace (x, x).first;
    return it->second == x ? x : (it->second = find (it->second));
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    if (s.part[i] != kSegmentedPlane) {
      ASSERT_NE (a[i].label, 0u) << i;
      ASSERT_NE (b[i].label, 0u) << i;
      parent[find (a[i].label)] = find (b[i].label + (1u << 31));
    }
  std::map<std::uint32_t, std::uint32_t> joined_to_whole, whole_to_joined;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (s.part[i] == kSegmentedPlane)
      continue;
    const std::uint32_t j = find (a[i].label);
    EXPECT_EQ (joined_to_whole.emplace (j, all[i].label).first->second, all[i].label)
        << i;
    EXPECT_EQ (whole_to_joined.emplace (all[i].label, j).first->second, j) << i;
  }
  EXPECT_GT (joined_to_whole.size(), 3u); // the pipe, the faces and small groups
}

TEST (LeftoverRegionGrowing, BadInputIsRefusedWithEmptyOutput)
{
  const LeftoverScene s = makeLeftoverScene();
  const auto refuses = [&s] (const auto& setUp) {
    pcl_ext::LeftoverRegionGrowing<Point> growing;
    growing.setInputCloud (s.cloud);
    growing.setSegmentLabels (s.labels);
    setUp (growing);
    Labels out;
    out.resize (3);
    const bool ok = growing.compute (out);
    return !ok && out.empty();
  };
  using G = pcl_ext::LeftoverRegionGrowing<Point>;
  EXPECT_TRUE (refuses ([] (G& g) { g.setSegmentLabels (nullptr); }));
  EXPECT_TRUE (
      refuses ([] (G& g) { g.setSegmentLabels (pcl::make_shared<Labels>()); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setInputCloud (pcl::make_shared<Cloud>()); }));
  EXPECT_TRUE (refuses (
      [] (G& g) { g.setAngleThreshold (std::numeric_limits<double>::quiet_NaN()); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setAngleThreshold (2.0); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setNormalK (2); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setMaxCurvature (-1.0); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setMinClusterSize (0); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setMaxClusterSize (10); }));
  EXPECT_TRUE (refuses ([] (G& g) { g.setKSearch (2); }));
  EXPECT_TRUE (refuses ([&s] (G& g) {
    auto indices = pcl::make_shared<pcl::Indices> (
        pcl::Indices{0, static_cast<pcl::index_t> (s.cloud->size())});
    g.setIndices (indices);
  }));
  EXPECT_TRUE (refuses ([] (G& g) {
    g.setLinkingIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{-1}));
  }));
}

TEST (LeftoverRegionGrowing, FewerPointsThanNeighboursAreRefused)
{
  // 30 points and k = 50: the shared neighbourhood search refuses, and so does the
  // growing, with an empty output.
  LeftoverScene s;
  for (int i = 0; i < 30; ++i) {
    s.cloud->push_back (Point (
        0.01f * static_cast<float> (i % 6), 0.01f * static_cast<float> (i / 6), 0.0f));
    s.labels->push_back (pcl::Label());
    s.labels->back().label = 0;
  }
  pcl_ext::LeftoverRegionGrowing<Point> growing;
  growing.setInputCloud (s.cloud);
  growing.setSegmentLabels (s.labels);
  Labels out;
  EXPECT_FALSE (growing.compute (out));
  EXPECT_TRUE (out.empty());
  // With k = 12 it grows them into one segment when they reach the minimum size.
  growing.setKSearch (12);
  growing.setMinClusterSize (10);
  ASSERT_TRUE (growing.compute (out));
  EXPECT_EQ (growing.getReport().segments, 1u);
  EXPECT_EQ (growing.getReport().segmented, 30u);
}
