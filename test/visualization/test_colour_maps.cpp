/*
 * Tests of the colour maps: colours by label, by class and by scalar, and coloured clouds.
 */
#include <pcl_ext/visualization/colour_maps.h>

#include <gtest/gtest.h>

#include <cmath>
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
