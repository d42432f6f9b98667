/*
 * Tests of the registration picture: wall points coloured by their distance to the
 * footprint, the footprint over them, a colour bar and a legend.
 */
#include "render_test_helpers.h"

#include <pcl_ext/visualization/footprint_view.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace pcl_ext::visualization;

TEST (FootprintView, WallPointsColouredByTheirDistanceToTheFootprint)
{
  // A 10 x 6 footprint; a wall 0.2 inside its south edge and one on its west edge.
  const FootprintSegments footprint = {
      {{0, 0}, {10, 0}}, {{10, 0}, {10, 6}}, {{10, 6}, {0, 6}}, {{0, 6}, {0, 0}}};
  std::vector<Eigen::Vector3d> walls;
  for (int i = 10; i <= 90; ++i)
    for (int k = 0; k < 10; ++k) {
      walls.emplace_back (0.1 * i, 0.2, 0.3 * k);        // residual 0.2
      walls.emplace_back (0.0, 0.06 * i * 0.5, 0.3 * k); // residual 0
    }
  walls.emplace_back (std::nan (""), 0.0, 0.0);
  const View view = makeFootprintView ("fit", walls, footprint, 0.4);
  ASSERT_EQ (view.layers.size(), 2u);
  const auto& points = *view.layers[0].cloud;
  ASSERT_EQ (points.size(), walls.size() - 1); // the NaN point left out
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ (points[i].z, 0.0f); // flattened for the top view
    const Colour expected = mapColour (i % 2 == 0 ? 0.5f : 0.0f, ColourMap::Jet);
    EXPECT_EQ (points[i].r, expected.r);
    EXPECT_EQ (points[i].g, expected.g);
    EXPECT_EQ (points[i].b, expected.b);
  }
  // The footprint in black over the points; the bar from 0 to the given residual.
  const auto& outline = *view.layers[1].cloud;
  ASSERT_GT (outline.size(), 100u);
  EXPECT_GT (outline[0].z, 0.0f);
  EXPECT_EQ (outline[0].r + outline[0].g + outline[0].b, 0);
  EXPECT_EQ (view.colour_bar.min, 0.0f);
  EXPECT_FLOAT_EQ (view.colour_bar.max, 0.4f);
  EXPECT_FALSE (view.colour_bar.name.empty());
  ASSERT_EQ (view.legend.size(), 1u);
  // Without a given range, the bar ends at the residuals' 95th percentile: 0.2 here.
  EXPECT_NEAR (makeFootprintView ("fit", walls, footprint).colour_bar.max, 0.2f, 1e-6);
}

TEST (FootprintView, RenderedFromAboveWithTheColourBar)
{
  ASSERT_TRUE (displayAvailable());
  const FootprintSegments footprint = {
      {{0, 0}, {20, 0}}, {{20, 0}, {20, 8}}, {{20, 8}, {0, 8}}, {{0, 8}, {0, 0}}};
  std::vector<Eigen::Vector3d> walls;
  for (int i = 0; i <= 400; ++i)
    for (int k = 0; k < 5; ++k) {
      walls.emplace_back (0.05 * i, 0.1, k);
      walls.emplace_back (0.05 * i, 8.0, k);
    }
  RenderOptions options;
  options.width = 600;
  options.height = 400;
  options.view = ViewKind::Top;
  const std::string path = temporaryPng ("footprint");
  ASSERT_TRUE (
      renderToPng ({makeFootprintView ("fit", walls, footprint)}, path, options));
  const Picture picture = readPicture (path);
  // The outline (one pixel, black, grey where smoothed) frames the picture; the colour
  // bar's red end is at the right.
  const auto dark_grey = [] (const std::uint8_t* p) {
    const int hi = std::max ({p[0], p[1], p[2]}), lo = std::min ({p[0], p[1], p[2]});
    return hi < 150 && hi - lo < 25;
  };
  const PixelBox black = pixelBox (picture, dark_grey, 0, 40, 360, 360);
  expectFramed (black, 0, 0, 600, 400);
  const Colour top = mapColour (0.99f, ColourMap::Jet);
  EXPECT_GT (pixelBox (picture, near (top.r, top.g, top.b, 20), 360, 0, 240, 400).count,
             10u);
  std::remove (path.c_str());
}
