/*
 * Tests of the segment colours and of a cloud coloured by segment (getColoredCloud()).
 */
#include <pcl_ext/common/segment_colours.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace {
struct Rgb {
  int r, g, b;
};

Rgb
colour (std::size_t segment)
{
  std::uint8_t rgb[3];
  pcl_ext::segmentColour (segment, rgb);
  return {rgb[0], rgb[1], rgb[2]};
}
} // namespace

TEST (SegmentColours, KnownColoursAndBrightness)
{
  // Segment 0: hue 0.11 of the circle (sector 0 of the HSV hexagon, 66 % of the way),
  // value 0.95, saturation 0.85: (0.95, 0.95 (1 - 0.85 * 0.34), 0.95 * 0.15) of 255.
  const Rgb first = colour (0);
  EXPECT_EQ (first.r, 242);
  EXPECT_EQ (first.g, 172);
  EXPECT_EQ (first.b, 36);
  // Even numbers at value 0.95, odd at 0.75: the brightest channel is 242 or 191.
  for (std::size_t s = 0; s < 50; ++s) {
    const Rgb c = colour (s);
    EXPECT_EQ (std::max ({c.r, c.g, c.b}), s % 2 ? 191 : 242) << s;
    // Saturation 0.85: the dimmest channel is 15 % of the brightest.
    EXPECT_EQ (std::min ({c.r, c.g, c.b}), s % 2 ? 28 : 36) << s;
  }
}

TEST (SegmentColours, NeighbouringNumbersAreDistinctAndColoursStable)
{
  for (std::size_t s = 0; s < 200; ++s) {
    const Rgb a = colour (s), b = colour (s + 1);
    EXPECT_GT (std::abs (a.r - b.r) + std::abs (a.g - b.g) + std::abs (a.b - b.b), 60)
        << s;
    const Rgb again = colour (s);
    EXPECT_EQ (a.r, again.r);
    EXPECT_EQ (a.g, again.g);
    EXPECT_EQ (a.b, again.b);
  }
}

TEST (SegmentColours, ColouredCloudIsWhiteWhereUnsegmented)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 6; ++i)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (i), 2.f * i, -1.f));
  cloud.width = 3;
  cloud.height = 2;
  cloud.is_dense = false;
  std::vector<pcl::PointIndices> segments (2);
  segments[0].indices = {0, 2};
  segments[1].indices = {5};
  const auto coloured = pcl_ext::colourBySegment (cloud, segments);
  ASSERT_EQ (coloured->size(), 6u);
  EXPECT_EQ (coloured->width, 3u);
  EXPECT_EQ (coloured->height, 2u);
  EXPECT_FALSE (coloured->is_dense);
  const Rgb c0 = colour (0), c1 = colour (1);
  for (std::size_t i = 0; i < 6; ++i) {
    const auto& p = (*coloured)[i];
    EXPECT_EQ (p.x, cloud[i].x);
    EXPECT_EQ (p.y, cloud[i].y);
    EXPECT_EQ (p.z, cloud[i].z);
    const Rgb expected = i == 0 || i == 2 ? c0 : i == 5 ? c1 : Rgb{255, 255, 255};
    EXPECT_EQ (p.r, expected.r) << i;
    EXPECT_EQ (p.g, expected.g) << i;
    EXPECT_EQ (p.b, expected.b) << i;
  }
  // Nothing to colour: an empty cloud.
  EXPECT_TRUE (pcl_ext::colourBySegment (cloud, {})->empty());
  EXPECT_TRUE (
      pcl_ext::colourBySegment (pcl::PointCloud<pcl::PointXYZ>(), segments)->empty());
}
