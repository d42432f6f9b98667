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
#include <cstdlib>
#include <fstream>
#include <unistd.h>
#include <limits>

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

// A DISPLAY naming no server: an error and no file, where VTK alone aborts the process.
TEST (OffscreenRenderer, ADisplayThatCannotBeOpenedIsRefused)
{
  using namespace pcl_ext::visualization;
  const char* before = std::getenv ("DISPLAY");
  const std::string saved = before ? before : "";
  setenv ("DISPLAY", ":9876", 1);
  EXPECT_FALSE (displayAvailable());
  const std::string path = temporaryPng ("no_display");
  std::remove (path.c_str());
  const auto cloud = sphereCloud (100);
  View view{
      "no display",
      {{makeColouredCloud (cloud, std::vector<Colour> (100, Colour{1, 2, 3})), 2.0}}};
  EXPECT_FALSE (renderToPng ({view}, path));
  EXPECT_FALSE (std::ifstream (path).good());
  if (before)
    setenv ("DISPLAY", saved.c_str(), 1);
  else
    unsetenv ("DISPLAY");
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

namespace {
using namespace pcl_ext::visualization;

/** A long box's surface (8 x 2 x 3, spacing about 0.05) in one colour. */
pcl::PointCloud<pcl::PointXYZ>
boxCloud ()
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const double step = 0.05;
  for (double a = 0; a <= 8.0; a += step)
    for (double b = 0; b <= 3.0; b += step) {
      cloud.push_back (pcl::PointXYZ (a, 0.0, b));
      cloud.push_back (pcl::PointXYZ (a, 2.0, b));
    }
  for (double a = 0; a <= 2.0; a += step)
    for (double b = 0; b <= 3.0; b += step) {
      cloud.push_back (pcl::PointXYZ (0.0, a, b));
      cloud.push_back (pcl::PointXYZ (8.0, a, b));
    }
  for (double a = 0; a <= 8.0; a += step)
    for (double b = 0; b <= 2.0; b += step)
      cloud.push_back (pcl::PointXYZ (a, b, 0.0));
  return cloud;
}

View
oneColour (const pcl::PointCloud<pcl::PointXYZ>& cloud, Colour colour)
{
  View view;
  view.layers.push_back (
      {makeColouredCloud (cloud, std::vector<Colour> (cloud.size(), colour))});
  return view;
}
} // namespace

TEST (OffscreenRenderer, EveryViewFramesTheSubjectDespiteFarOutliers)
{
  ASSERT_TRUE (displayAvailable());
  // The box in blue; 40 far points (0.4 %) in red, as a few far returns of a scan.
  auto box = boxCloud();
  pcl::PointCloud<pcl::PointXYZ> far;
  for (int i = 0; i < 40; ++i)
    far.push_back (pcl::PointXYZ (60.0 + i, -50.0 + 2.0 * i, 10.0 + (i % 5)));
  View view = oneColour (box, {40, 60, 220});
  view.title = "box";
  view.layers.push_back (oneColour (far, {230, 20, 20}).layers.front());
  for (const ViewKind kind :
       {ViewKind::Auto, ViewKind::Top, ViewKind::Side, ViewKind::Oblique}) {
    RenderOptions options;
    options.width = 400;
    options.height = 300;
    options.view = kind;
    const std::string path = temporaryPng ("framed_" + viewKindName (kind));
    ASSERT_TRUE (renderToPng ({view}, path, options));
    const Picture picture = readPicture (path);
    ASSERT_EQ (picture.width, 400);
    SCOPED_TRACE (viewKindName (kind));
    expectFramed (
        pixelBox (picture, near (40, 60, 220, 60), 0, 0, 400, 300), 0, 0, 400, 300);
    std::remove (path.c_str());
  }
}

TEST (OffscreenRenderer, SensorViewLooksFromTheSensorAtAScene)
{
  ASSERT_TRUE (displayAvailable());
  // A depth camera's image: a table top (y = 0.3, below the camera) seen from the
  // origin, an organised cloud in the camera's frame (y down). Its top must face the
  // camera's up.
  pcl::PointCloud<pcl::PointXYZ> table;
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 60; ++c)
      table.push_back (pcl::PointXYZ (-0.6 + 0.02 * c, 0.3, 1.0 + 0.02 * r));
  table.width = 60;
  table.height = 40;
  RenderOptions options;
  setSceneFrame (table, options);
  EXPECT_NEAR (options.up.y(), -1.0, 1e-9);
  EXPECT_TRUE (options.sensor.isZero());
  options.width = 320;
  options.height = 240;
  const std::string path = temporaryPng ("sensor");
  ASSERT_TRUE (renderToPng ({oneColour (table, {40, 60, 220})}, path, options));
  const Picture picture = readPicture (path);
  expectFramed (
      pixelBox (picture, near (40, 60, 220, 60), 0, 0, 320, 240), 0, 0, 320, 240);
  std::remove (path.c_str());
}

TEST (OffscreenRenderer, CeilingLeftOutByDefaultAndKeptOnRequest)
{
  ASSERT_TRUE (displayAvailable());
  // A room: the box's floor and walls in blue, a ceiling at z = 3 in red.
  const auto walls = boxCloud();
  pcl::PointCloud<pcl::PointXYZ> ceiling;
  for (double a = 0; a <= 8.0; a += 0.05)
    for (double b = 0; b <= 2.0; b += 0.05)
      ceiling.push_back (pcl::PointXYZ (a, b, 3.0));
  View room = oneColour (walls, {40, 60, 220});
  room.layers.push_back (oneColour (ceiling, {230, 20, 20}).layers.front());
  RenderOptions options;
  options.width = 400;
  options.height = 300;
  const std::string path = temporaryPng ("ceiling");
  ASSERT_TRUE (renderToPng ({room}, path, options));
  const auto red = near (230, 20, 20, 40);
  EXPECT_EQ (pixelBox (readPicture (path), red, 0, 0, 400, 300).count, 0u);
  expectFramed (pixelBox (readPicture (path), near (40, 60, 220, 60), 0, 0, 400, 300),
                0,
                0,
                400,
                300);
  options.max_height = std::numeric_limits<double>::infinity();
  ASSERT_TRUE (renderToPng ({room}, path, options));
  EXPECT_GT (pixelBox (readPicture (path), red, 0, 0, 400, 300).count, 1000u);
  std::remove (path.c_str());
}

TEST (OffscreenRenderer, LegendAndColourBarBesideTheSubject)
{
  ASSERT_TRUE (displayAvailable());
  const auto cloud = sphereCloud (20000);
  std::vector<float> height;
  for (const auto& p : cloud)
    height.push_back (p.z);
  View view;
  view.title = "height";
  view.layers.push_back (
      {makeColouredCloud (cloud, colourByScalar (height, ColourMap::Jet))});
  view.legend = {{"edge", {225, 30, 30}}, {"unsegmented", {170, 170, 170}}};
  view.colour_bar = {"height (m)", -1.0f, 1.0f, ColourMap::Grey};
  RenderOptions options;
  options.width = 640;
  options.height = 400;
  const std::string path = temporaryPng ("legend");
  ASSERT_TRUE (renderToPng ({view}, path, options));
  const Picture picture = readPicture (path);
  // The legend column is at the right: the swatches' exact colours and the grey bar's
  // dark and light ends are there; the sphere (no grey in Jet) is left of it.
  const int column = 640 - 640 * 2 / 5;
  EXPECT_GT (
      pixelBox (picture, near (225, 30, 30, 4), column, 0, 640 - column, 400).count,
      50u);
  EXPECT_GT (
      pixelBox (picture, near (170, 170, 170, 4), column, 0, 640 - column, 400).count,
      50u);
  EXPECT_GT (
      pixelBox (picture, near (20, 20, 20, 12), column, 0, 640 - column, 400).count,
      20u);
  EXPECT_GT (
      pixelBox (picture, near (235, 235, 235, 12), column, 0, 640 - column, 400).count,
      20u);
  const auto sphere = [] (const std::uint8_t* p) {
    const int hi = std::max ({p[0], p[1], p[2]}), lo = std::min ({p[0], p[1], p[2]});
    return hi - lo > 60; // Jet's saturated colours, not text, grey or background
  };
  const PixelBox subject = pixelBox (picture, sphere, 0, 0, 640, 400);
  expectFramed (subject, 0, 0, 640, 400);
  // The swatch's red is in Jet too: the subject must stay left of the legend's text.
  const PixelBox text = pixelBox (
      picture, near (0, 0, 0, 60), subject.x1 + 1, 0, 640 - subject.x1 - 1, 400);
  EXPECT_GT (text.count, 30u);
  std::remove (path.c_str());
}
