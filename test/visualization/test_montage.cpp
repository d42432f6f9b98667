/*
 * Tests of montages: one tile per labelling of a cloud, every tile its own size however
 * many there are. Renders, so it needs an X display (scripts/test.sh starts Xvfb when
 * none is set).
 */
#include "render_test_helpers.h"

#include <pcl_ext/visualization/montage.h>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

TEST (Montage, MontageTilesKeepTheirSizeAndEmptyTilesShowTheBackground)
{
  ASSERT_TRUE (pcl_ext::visualization::displayAvailable())
      << "this test needs an X display; scripts/test.sh starts Xvfb when none is set";
  using namespace pcl_ext::visualization;
  const RenderOptions one = makeMontageOptions (1, 200, 150);
  EXPECT_EQ (one.columns, 1);
  EXPECT_EQ (one.width, 200);
  EXPECT_EQ (one.height, 150);
  const RenderOptions nine = makeMontageOptions (9, 200, 150, 4);
  EXPECT_EQ (nine.columns, 4);
  EXPECT_EQ (nine.width, 800);
  EXPECT_EQ (nine.height, 450);

  // Three tiles in rows of two: the fourth place must be background, not the window's
  // black.
  const auto cloud = sphereCloud (5000);
  std::vector<std::uint32_t> labels;
  for (const auto& p : cloud)
    labels.push_back (p.z > 0 ? 1 : 2);
  std::vector<View> views;
  for (const char* title : {"a", "b", "c"})
    views.push_back (makeLabelView (title, cloud, labels, 3.0));
  const RenderOptions options = makeMontageOptions (views.size(), 160, 120, 2);
  const std::string path = temporaryPng ("montage");
  std::remove (path.c_str());
  ASSERT_TRUE (renderToPng (views, path, options));
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName (path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions (dims);
  ASSERT_EQ (dims[0], 320);
  ASSERT_EQ (dims[1], 240);
  // PNG rows start at the bottom in VTK: the empty place is x >= 160, y < 120.
  std::size_t drawn_bottom_left = 0, not_background_bottom_right = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 320; ++x) {
      const auto* px = static_cast<unsigned char*> (image->GetScalarPointer (x, y, 0));
      const bool background = px[0] > 245 && px[1] > 245 && px[2] > 245;
      if (!background)
        (x < 160 ? drawn_bottom_left : not_background_bottom_right) += 1;
    }
  EXPECT_GT (drawn_bottom_left, 500u);
  EXPECT_EQ (not_background_bottom_right, 0u);
  std::remove (path.c_str());
}

TEST (Montage, TileSizesColumnsAndLimits)
{
  using namespace pcl_ext::visualization;
  const RenderOptions five = makeMontageOptions (5, 300, 200, 2); // rows of 2: 3 rows
  EXPECT_EQ (five.columns, 2);
  EXPECT_EQ (five.width, 600);
  EXPECT_EQ (five.height, 600);
  const RenderOptions none = makeMontageOptions (0, 300, 200); // taken as one tile
  EXPECT_EQ (none.columns, 1);
  EXPECT_EQ (none.width, 300);
  EXPECT_EQ (none.height, 200);
  const RenderOptions one_column = makeMontageOptions (3, 300, 200, 0);
  EXPECT_EQ (one_column.columns, 1);
  EXPECT_EQ (one_column.height, 600);
  // Tiles no smaller than 16 pixels, the image no larger than 16384.
  const RenderOptions tiny = makeMontageOptions (2, 1, 1);
  EXPECT_EQ (tiny.width, 32);
  EXPECT_EQ (tiny.height, 16);
  const RenderOptions huge = makeMontageOptions (4, 10000, 10000, 4);
  EXPECT_EQ (huge.width, 16384);
  EXPECT_EQ (huge.height, 10000);
}

TEST (Montage, LabelViewColoursTheCloudByLabel)
{
  using namespace pcl_ext::visualization;
  const auto cloud = sphereCloud (10);
  std::vector<std::uint32_t> labels (10, 1);
  labels[3] = 0;
  const View view = makeLabelView ("split", cloud, labels, 4.0);
  EXPECT_EQ (view.title, "split");
  ASSERT_EQ (view.layers.size(), 1u);
  EXPECT_EQ (view.layers[0].point_size, 4.0);
  ASSERT_EQ (view.layers[0].cloud->size(), 10u);
  const auto expected = colourByLabel (labels);
  for (std::size_t i = 0; i < 10; ++i) {
    const auto& p = (*view.layers[0].cloud)[i];
    EXPECT_EQ (p.x, cloud[i].x);
    EXPECT_EQ (p.r, expected[i].r);
    EXPECT_EQ (p.g, expected[i].g);
    EXPECT_EQ (p.b, expected[i].b);
  }
  // Labels that do not match the cloud: an empty tile.
  const View empty = makeLabelView ("bad", cloud, std::vector<std::uint32_t> (3, 1));
  ASSERT_EQ (empty.layers.size(), 1u);
  EXPECT_TRUE (empty.layers[0].cloud->empty());
}

TEST (Montage, SegmentsTakeTheLabelOfTheTruthTheyOverlapMost)
{
  using pcl_ext::visualization::matchLabelsToReference;
  // Truth: 1 1 1 1 2 2 2 0 3 3. Result: 7 7 7 5 5 5 5 0 9 4.
  const std::vector<std::uint32_t> truth = {1, 1, 1, 1, 2, 2, 2, 0, 3, 3};
  const std::vector<std::uint32_t> result = {7, 7, 7, 5, 5, 5, 5, 0, 9, 4};
  const auto matched = matchLabelsToReference (result, truth);
  // 7 overlaps 1 by 3, 5 overlaps 2 by 3 (and 1 by 1, already taken), 9 and 4 overlap 3
  // by one each: 4 (the smaller label) takes it, 9 gets a new label above the truth's.
  const std::vector<std::uint32_t> expected = {1, 1, 1, 2, 2, 2, 2, 0, 4, 3};
  EXPECT_EQ (matched, expected);
  EXPECT_EQ (matchLabelsToReference ({1, 2}, {1}), (std::vector<std::uint32_t>{1, 2}));
}
