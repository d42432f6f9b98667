/*
 * Test of the offscreen renderer: the PNG exists, has the asked size, and shows the
 * cloud. Needs an X display (scripts/test.sh starts Xvfb when none is set).
 */
#include "render_test_helpers.h"

#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/montage.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <unistd.h>

TEST (OffscreenRenderer, WritesPngOfRequestedSizeShowingTheCloud)
{
  ASSERT_TRUE (pcl_ext::visualization::displayAvailable())
      << "this test needs an X display; scripts/test.sh starts Xvfb when none is set";
  const auto cloud = sphereCloud (20000);
  std::vector<float> height;
  for (const auto& p : cloud)
    height.push_back (p.z);
  using namespace pcl_ext::visualization;
  View scalar{"height", {{makeColouredCloud (cloud, colourByScalar (height)), 3.0}}};
  std::vector<std::uint32_t> labels;
  for (const auto& p : cloud)
    labels.push_back (p.x > 0 ? 1 : 2);
  View labelled{"labels", {{makeColouredCloud (cloud, colourByLabel (labels)), 3.0}}};

  RenderOptions options;
  options.width = 640;
  options.height = 300;
  const std::string path = temporaryPng ("render");
  std::remove (path.c_str());
  ASSERT_TRUE (renderToPng ({scalar, labelled}, path, options));

  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  ASSERT_TRUE (reader->CanReadFile (path.c_str()));
  reader->SetFileName (path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions (dims);
  EXPECT_EQ (dims[0], 640);
  EXPECT_EQ (dims[1], 300);
  // Count pixels that differ from the white background, in each half (one panel each).
  std::size_t left = 0, right = 0;
  const int channels = image->GetNumberOfScalarComponents();
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const auto* px = static_cast<unsigned char*> (image->GetScalarPointer (x, y, 0));
      bool background = true;
      for (int c = 0; c < std::min (channels, 3); ++c)
        background = background && px[c] > 245;
      if (!background)
        (x < dims[0] / 2 ? left : right) += 1;
    }
  EXPECT_GT (left, 2000u);
  EXPECT_GT (right, 2000u);
  std::remove (path.c_str());
}

TEST (OffscreenRenderer, RefusesNothingToDrawAndBadSizesWithoutWriting)
{
  using namespace pcl_ext::visualization;
  const std::string path = temporaryPng ("refused");
  std::remove (path.c_str());
  EXPECT_FALSE (renderToPng ({}, path));
  View empty{
      "empty",
      {{pcl::PointCloud<pcl::PointXYZRGB>::Ptr (new pcl::PointCloud<pcl::PointXYZRGB>),
        2.0}}};
  EXPECT_FALSE (renderToPng ({empty}, path));
  const auto cloud = sphereCloud (100);
  View ok{
      "ok",
      {{makeColouredCloud (cloud, std::vector<Colour> (100, Colour{1, 2, 3})), 2.0}}};
  RenderOptions tiny;
  tiny.width = 0;
  EXPECT_FALSE (renderToPng ({ok}, path, tiny));
  EXPECT_FALSE (renderToPng ({ok}, "/nonexistent-folder/x.png"));
  EXPECT_FALSE (std::ifstream (path).good());
}

TEST (OffscreenRenderer, LongTitlesStayInsideTheirPanel)
{
  ASSERT_TRUE (pcl_ext::visualization::displayAvailable());
  using namespace pcl_ext::visualization;
  const auto cloud = sphereCloud (2000);
  const std::vector<std::uint32_t> labels (cloud.size(), 1);
  // At the height's font size (18 px) these 40 characters need about 400 of the panel's
  // 320 pixels; the second line is short.
  const std::vector<View> views = {
      makeLabelView ("variance_lsi (pcl_ext): IoU 0.711, 38 seg\n12 s", cloud, labels),
      makeLabelView ("b", cloud, labels)};
  const RenderOptions options = makeMontageOptions (views.size(), 320, 400, 2);
  const std::string path = temporaryPng ("long_titles");
  std::remove (path.c_str());
  ASSERT_TRUE (renderToPng (views, path, options));
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName (path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions (dims);
  ASSERT_EQ (dims[0], 640);
  ASSERT_EQ (dims[1], 400);
  // Text is black on white: count dark pixels in the first panel's title band (the top
  // 70 rows; VTK's rows start at the bottom), in its last 24 columns and elsewhere.
  std::size_t title = 0, right_margin = 0;
  for (int y = 400 - 70; y < 400; ++y)
    for (int x = 0; x < 320; ++x) {
      const auto* px = static_cast<unsigned char*> (image->GetScalarPointer (x, y, 0));
      if (px[0] < 128 && px[1] < 128 && px[2] < 128)
        (x >= 320 - 24 ? right_margin : title) += 1;
    }
  EXPECT_GT (title, 100u);
  EXPECT_EQ (right_margin, 0u);
  std::remove (path.c_str());
}
