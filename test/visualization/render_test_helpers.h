/*
 * Helpers for the rendering tests: a cloud to render and a temporary PNG path.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <unistd.h>

inline pcl::PointCloud<pcl::PointXYZ>
sphereCloud (int n)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < n; ++i) {
    // Fibonacci sphere: even coverage, no randomness.
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt (1.0 - z * z);
    const double phi = i * 2.399963229728653;
    cloud.push_back (pcl::PointXYZ (r * std::cos (phi), r * std::sin (phi), z));
  }
  return cloud;
}

inline std::string
temporaryPng (const std::string& stem)
{
  return testing::TempDir() + "/" + stem + "_" + std::to_string (::getpid()) + ".png";
}

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <vector>

/** A PNG read back: rows from the top, 3 bytes per pixel. */
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  const std::uint8_t*
  at (int x, int y) const
  {
    return &rgb[3 * (static_cast<std::size_t> (y) * width + x)];
  }
};

inline Picture
readPicture (const std::string& path)
{
  Picture picture;
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile (path.c_str()))
    return picture;
  reader->SetFileName (path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions (dims);
  picture.width = dims[0];
  picture.height = dims[1];
  picture.rgb.resize (3 * static_cast<std::size_t> (dims[0]) * dims[1]);
  const int channels = image->GetNumberOfScalarComponents();
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      // VTK's rows start at the bottom.
      const auto* px = static_cast<unsigned char*> (image->GetScalarPointer (x, y, 0));
      for (int c = 0; c < 3; ++c)
        picture
            .rgb[3 * (static_cast<std::size_t> (dims[1] - 1 - y) * dims[0] + x) + c] =
            px[std::min (c, channels - 1)];
    }
  return picture;
}

/** The bounding box [x0, x1] x [y0, y1] (rows from the top) of the pixels of \a region
 * (x, y, width, height) for which \a wanted holds, and how many there are. */
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  std::size_t count = 0;
};

inline PixelBox
pixelBox (const Picture& picture,
          const std::function<bool (const std::uint8_t*)>& wanted,
          int rx,
          int ry,
          int rw,
          int rh)
{
  PixelBox box;
  for (int y = ry; y < ry + rh; ++y)
    for (int x = rx; x < rx + rw; ++x)
      if (wanted (picture.at (x, y))) {
        box.x0 = std::min (box.x0, x);
        box.x1 = std::max (box.x1, x);
        box.y0 = std::min (box.y0, y);
        box.y1 = std::max (box.y1, y);
        ++box.count;
      }
  return box;
}

/** Whether a pixel is within \a tolerance of colour (r, g, b) in every channel. */
inline std::function<bool (const std::uint8_t*)>
near (int r, int g, int b, int tolerance = 40)
{
  return [=] (const std::uint8_t* p) {
    return std::abs (p[0] - r) <= tolerance && std::abs (p[1] - g) <= tolerance &&
           std::abs (p[2] - b) <= tolerance;
  };
}

/** The check of a picture's subject: its pixels' bounding box covers at least
 * half of the panel's width or height and touches none of its edges. */
inline void
expectFramed (const PixelBox& box, int rx, int ry, int rw, int rh)
{
  ASSERT_GT (box.count, 0u);
  EXPECT_TRUE (box.x1 - box.x0 + 1 >= rw / 2 || box.y1 - box.y0 + 1 >= rh / 2)
      << "subject " << box.x1 - box.x0 + 1 << " x " << box.y1 - box.y0 + 1
      << " pixels in a panel of " << rw << " x " << rh;
  EXPECT_GT (box.x0, rx);
  EXPECT_GT (box.y0, ry);
  EXPECT_LT (box.x1, rx + rw - 1);
  EXPECT_LT (box.y1, ry + rh - 1);
}
