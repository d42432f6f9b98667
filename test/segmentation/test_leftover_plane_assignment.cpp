/*
 * LeftoverPlaneAssignment: points without a segment put into the neighbouring segment
 * whose local plane they lie on (a plane's rim, a crease's points to their own face),
 * those off every plane left out, the result independent of the thread count, and bad
 * input.
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Labels = pcl::PointCloud<pcl::Label>;

enum Part : int { kFloorSegmented, kFloorLeft, kWallSegmented, kWallLeft, kAbove };

/** A floor z = 0 (x, y in 0 .. 1) and a wall x = 1 (y in 0 .. 1, z in 0 .. 1) meeting
 * at a right-angled crease, sampled at random about 1 cm apart with 0.5 mm noise; the
 * points within 3 cm of the crease have no segment (a crease band), the others are
 * segments 1 (floor) and 2 (wall). 200 points 5 cm above the floor, away from the wall,
 * have no segment either and lie on no plane. */
struct CreaseScene {
  Cloud::Ptr cloud = pcl::make_shared<Cloud>();
  Labels::Ptr labels = pcl::make_shared<Labels>();
  std::vector<Part> part;
};

CreaseScene
makeCreaseScene ()
{
  CreaseScene s;
  pcl_ext::RandomStream random (31);
  const auto add = [&s] (double x, double y, double z, Part part) {
    s.cloud->push_back (
        Point (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z)));
    pcl::Label l;
    l.label = part == kFloorSegmented ? 1u : part == kWallSegmented ? 2u : 0u;
    s.labels->push_back (l);
    s.part.push_back (part);
  };
  for (int i = 0; i < 10000; ++i) {
    const double x = random.uniform(), y = random.uniform();
    add (x, y, 0.0005 * random.gaussian(), x > 0.97 ? kFloorLeft : kFloorSegmented);
  }
  for (int i = 0; i < 10000; ++i) {
    const double y = random.uniform(), z = random.uniform();
    add (1.0 + 0.0005 * random.gaussian(), y, z, z < 0.03 ? kWallLeft : kWallSegmented);
  }
  for (int i = 0; i < 200; ++i)
    add (0.2 + 0.3 * random.uniform(), 0.2 + 0.3 * random.uniform(), 0.05, kAbove);
  return s;
}

Labels
assign (const CreaseScene& s, unsigned int threads)
{
  pcl_ext::LeftoverPlaneAssignment<Point> assignment;
  assignment.setInputCloud (s.cloud);
  assignment.setSegmentLabels (s.labels);
  assignment.setKSearch (50);
  assignment.setNumberOfThreads (threads);
  Labels out;
  EXPECT_TRUE (assignment.compute (out));
  return out;
}
} // namespace

TEST (LeftoverPlaneAssignment, CreasePointsJoinTheirOwnFaceOffPlanePointsStayOut)
{
  const CreaseScene s = makeCreaseScene();
  const Labels out = assign (s, 2);
  ASSERT_EQ (out.size(), s.cloud->size());
  // The band points within 1 cm of their face's segmented part, and how many of them
  // join it; any band point joining the other face.
  std::size_t floor_near = 0, floor_to_floor = 0, floor_to_wall = 0;
  std::size_t wall_near = 0, wall_to_wall = 0, wall_to_floor = 0, above_assigned = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint32_t l = out[i].label;
    switch (s.part[i]) {
    case kFloorSegmented:
      ASSERT_EQ (l, 1u);
      break;
    case kWallSegmented:
      ASSERT_EQ (l, 2u);
      break;
    case kFloorLeft:
      if ((*s.cloud)[i].x < 0.98f) {
        ++floor_near;
        floor_to_floor += l == 1u;
      }
      floor_to_wall += l == 2u;
      break;
    case kWallLeft:
      if ((*s.cloud)[i].z > 0.02f) {
        ++wall_near;
        wall_to_wall += l == 2u;
      }
      wall_to_floor += l == 1u;
      break;
    case kAbove:
      above_assigned += l != 0u;
      break;
    }
  }
  // Within a spacing of its face's segment a band point has that segment among its 12
  // nearest: nearly all of them join it (deeper in the band, only band points are
  // near). None joins the other face.
  ASSERT_GT (floor_near, 50u);
  ASSERT_GT (wall_near, 50u);
  EXPECT_GE (floor_to_floor, floor_near * 9 / 10);
  EXPECT_GE (wall_to_wall, wall_near * 9 / 10);
  EXPECT_EQ (floor_to_wall, 0u);
  EXPECT_EQ (wall_to_floor, 0u);
  // 5 cm above the floor is a hundred residuals off it.
  EXPECT_EQ (above_assigned, 0u);
}

TEST (LeftoverPlaneAssignment, AnyThreadCountGivesTheSameLabels)
{
  const CreaseScene s = makeCreaseScene();
  const Labels one = assign (s, 1), two = assign (s, 2);
  ASSERT_EQ (one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    ASSERT_EQ (one[i].label, two[i].label) << i;
}

TEST (LeftoverPlaneAssignment, BadInputGivesAnErrorAndNoOutput)
{
  const CreaseScene s = makeCreaseScene();
  pcl_ext::LeftoverPlaneAssignment<Point> assignment;
  Labels out;
  out.resize (2);
  EXPECT_FALSE (assignment.compute (out)); // no cloud
  EXPECT_TRUE (out.empty());
  assignment.setInputCloud (pcl::make_shared<Cloud>());
  EXPECT_FALSE (assignment.compute (out));
  assignment.setInputCloud (s.cloud);
  EXPECT_FALSE (assignment.compute (out)); // no labels
  auto wrong = pcl::make_shared<Labels>();
  wrong->resize (3);
  assignment.setSegmentLabels (wrong);
  EXPECT_FALSE (assignment.compute (out));
  assignment.setSegmentLabels (s.labels);
  assignment.setCandidateK (0);
  EXPECT_FALSE (assignment.compute (out));
  assignment.setCandidateK (12);
  assignment.setDistanceFactor (-1.0);
  EXPECT_FALSE (assignment.compute (out));
  assignment.setDistanceFactor (std::numeric_limits<double>::infinity());
  EXPECT_FALSE (assignment.compute (out));
  EXPECT_TRUE (out.empty());
  // Fewer points than the neighbourhood's k: the search refuses, no output.
  {
    auto tiny = pcl::make_shared<Cloud>();
    auto labels = pcl::make_shared<Labels>();
    for (int i = 0; i < 4; ++i) {
      tiny->push_back (Point (0.1f * i, 0.0f, 0.0f));
      labels->push_back (pcl::Label{i == 0 ? 0u : 1u});
    }
    pcl_ext::LeftoverPlaneAssignment<Point> small;
    small.setInputCloud (tiny);
    small.setSegmentLabels (labels);
    EXPECT_FALSE (small.compute (out));
    EXPECT_TRUE (out.empty());
  }
  // Non-finite points are never assigned; the others are as before.
  assignment.setDistanceFactor (3.0);
  auto cloud = pcl::make_shared<Cloud> (*s.cloud);
  (*cloud)[cloud->size() - 1].x = std::numeric_limits<float>::quiet_NaN();
  assignment.setInputCloud (cloud);
  ASSERT_TRUE (assignment.compute (out));
  EXPECT_EQ (out[cloud->size() - 1].label, 0u);
}
