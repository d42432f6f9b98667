/*
 * Tests of the colour maps: colours by label, by class and by scalar, and coloured
 * clouds.
 */
#include <pcl_ext/common/segment_colours.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/visualization/colour_maps.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace pcl_ext::visualization;

TEST (ColourMaps, LabelsAreStableAndDistinct)
{
  using namespace pcl_ext::visualization;
  const auto a = colourByLabel ({0, 1, 2, 1});
  EXPECT_EQ (a[0].r, 170);
  EXPECT_EQ (a[1].r, a[3].r);
  EXPECT_TRUE (a[1].r != a[2].r || a[1].g != a[2].g || a[1].b != a[2].b);
  const auto s = colourByScalar ({0.0f, 1.0f, NAN}, ColourMap::Grey, 0.0f, 1.0f);
  EXPECT_EQ (s[0].r, 0);
  EXPECT_EQ (s[1].r, 255);
  EXPECT_EQ (s[2].r, 70);
  const auto c = colourByClass ({2});
  EXPECT_EQ (c[0].r, 225);
}

TEST (ColourMaps, LabelsTakeTheSegmentersColours)
{
  // Label L is segment L - 1 of getColoredCloud; 0 is grey.
  const std::vector<std::uint32_t> labels = {0, 1, 2, 17};
  const auto colours = colourByLabel (labels);
  ASSERT_EQ (colours.size(), 4u);
  EXPECT_EQ (colours[0].r, 170);
  EXPECT_EQ (colours[0].g, 170);
  EXPECT_EQ (colours[0].b, 170);
  for (std::size_t i = 1; i < labels.size(); ++i) {
    std::uint8_t rgb[3];
    pcl_ext::segmentColour (labels[i] - 1, rgb);
    EXPECT_EQ (colours[i].r, rgb[0]) << labels[i];
    EXPECT_EQ (colours[i].g, rgb[1]) << labels[i];
    EXPECT_EQ (colours[i].b, rgb[2]) << labels[i];
  }
}

TEST (ColourMaps, ClassColoursAsInTheFigures)
{
  using pcl_ext::PointClass;
  const auto c = colourByClass ({static_cast<std::uint32_t> (PointClass::Surface),
                                 static_cast<std::uint32_t> (PointClass::Edge),
                                 static_cast<std::uint32_t> (PointClass::Boundary),
                                 static_cast<std::uint32_t> (PointClass::Unknown),
                                 99});
  ASSERT_EQ (c.size(), 5u);
  EXPECT_GT (c[0].b, std::max (c[0].r, c[0].g)); // surface blue
  EXPECT_GT (c[1].r, std::max (c[1].g, c[1].b)); // edge red
  EXPECT_GT (c[2].g, std::max (c[2].r, c[2].b)); // boundary green
  for (const std::size_t i : {3, 4})             // unknown, and anything else, grey
  {
    EXPECT_EQ (c[i].r, c[i].g);
    EXPECT_EQ (c[i].g, c[i].b);
  }
}

TEST (ColourMaps, ScalarMapsAndTheirEnds)
{
  // Ends of each map, clamped outside [0, 1]; NaN dark grey.
  const Colour black = mapColour (0.f, ColourMap::Grey),
               white = mapColour (1.f, ColourMap::Grey);
  EXPECT_EQ (black.r + black.g + black.b, 0);
  EXPECT_EQ (white.r + white.g + white.b, 3 * 255);
  EXPECT_EQ (mapColour (0.5f, ColourMap::Grey).g, 128);
  EXPECT_EQ (mapColour (-3.f, ColourMap::Grey).r, 0);
  EXPECT_EQ (mapColour (7.f, ColourMap::Grey).r, 255);
  const Colour jet0 = mapColour (0.f, ColourMap::Jet),
               jet1 = mapColour (1.f, ColourMap::Jet);
  EXPECT_EQ (jet0.r, 0);
  EXPECT_EQ (jet0.g, 0);
  EXPECT_EQ (jet0.b, 128); // dark blue
  EXPECT_EQ (jet1.r, 128); // dark red
  EXPECT_EQ (jet1.g, 0);
  EXPECT_EQ (jet1.b, 0);
  // Viridis from matplotlib's first (68, 1, 84) to its last colour (253, 231, 37).
  const Colour v0 = mapColour (0.f, ColourMap::Viridis),
               v1 = mapColour (1.f, ColourMap::Viridis);
  EXPECT_EQ (v0.r, 68);
  EXPECT_EQ (v0.g, 1);
  EXPECT_EQ (v0.b, 84);
  EXPECT_EQ (v1.r, 253);
  EXPECT_EQ (v1.g, 231);
  EXPECT_EQ (v1.b, 37);
  const Colour nan =
      mapColour (std::numeric_limits<float>::quiet_NaN(), ColourMap::Viridis);
  EXPECT_EQ (nan.r, 70);
  EXPECT_EQ (nan.g, 70);
  EXPECT_EQ (nan.b, 70);
}

TEST (ColourMaps, ScalarRangeFromThePercentilesWhenNotGiven)
{
  // 0 .. 100: the 2nd percentile is 2, the 98th 98, so 50 sits mid-way and the outer
  // values are clamped to the ends.
  std::vector<float> values;
  for (int i = 0; i <= 100; ++i)
    values.push_back (static_cast<float> (i));
  values.push_back (std::numeric_limits<float>::quiet_NaN());
  const auto c = colourByScalar (values, ColourMap::Grey);
  ASSERT_EQ (c.size(), values.size());
  EXPECT_EQ (c[0].r, 0);
  EXPECT_EQ (c[2].r, 0);
  EXPECT_EQ (c[50].r, 128);
  EXPECT_EQ (c[98].r, 255);
  EXPECT_EQ (c[100].r, 255);
  EXPECT_EQ (c[101].r, 70); // NaN
  // A given range is used as it is.
  const auto given = colourByScalar (values, ColourMap::Grey, 0.f, 200.f);
  EXPECT_EQ (given[100].r, 128);
}

TEST (ColourMaps, ColouredCloudNeedsOneColourPerPoint)
{
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZI p;
    p.x = static_cast<float> (i);
    p.y = 1.f;
    p.z = 2.f;
    cloud.push_back (p);
  }
  cloud.is_dense = false;
  const std::vector<Colour> colours = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  const auto coloured = makeColouredCloud (cloud, colours);
  ASSERT_EQ (coloured->size(), 3u);
  EXPECT_FALSE (coloured->is_dense);
  EXPECT_EQ ((*coloured)[2].x, 2.f);
  EXPECT_EQ ((*coloured)[2].z, 2.f);
  EXPECT_EQ ((*coloured)[2].r, 7);
  EXPECT_EQ ((*coloured)[2].b, 9);
  EXPECT_TRUE (makeColouredCloud (cloud, {{1, 2, 3}})->empty());
}
