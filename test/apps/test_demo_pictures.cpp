/*
 * Every picture pcl_ext_demo writes frames its subject: the drawn pixels (anything not
 * the white background) cover at least half of the picture's width or height and touch
 * none of its edges (nothing cut at the frame), and every panel has a title in its top
 * band.
 */
#include "../app_test.h"
#include "../visualization/render_test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {
class DemoPictures : public pcl_ext::test::AppTest {
protected:
  DemoPictures() : AppTest (PCL_EXT_DEMO_EXE) {}
};

bool
drawn (const std::uint8_t* p)
{
  return p[0] < 235 || p[1] < 235 || p[2] < 235;
}

TEST_F (DemoPictures, EveryPictureFramesItsSubjectAndHasATitle)
{
  if (!std::getenv ("DISPLAY"))
    GTEST_SKIP() << "no X display for rendering";
  ASSERT_EQ (run (dir_ + " -threads 2"), 0) << output_;
  std::vector<std::string> pictures;
  for (const auto& entry : std::filesystem::directory_iterator (dir_))
    if (entry.path().extension() == ".png")
      pictures.push_back (entry.path().string());
  std::sort (pictures.begin(), pictures.end());
  // The demo's generated-scene steps: the scenes, the classification, the
  // segmentations, the profiles, the registration and the CRF.
  ASSERT_GE (pictures.size(), 15u) << output_;
  for (const auto& file : pictures) {
    SCOPED_TRACE (file);
    const Picture picture = readPicture (file);
    ASSERT_GT (picture.width, 0);
    const PixelBox box = pixelBox (picture, drawn, 0, 0, picture.width, picture.height);
    ASSERT_GT (box.count, 0u);
    EXPECT_GT (box.x0, 0);
    EXPECT_GT (box.y0, 0);
    EXPECT_LT (box.x1, picture.width - 1);
    EXPECT_LT (box.y1, picture.height - 1);
    EXPECT_TRUE (2 * (box.x1 - box.x0) >= picture.width ||
                 2 * (box.y1 - box.y0) >= picture.height)
        << "drawn box " << box.x0 << ".." << box.x1 << " x " << box.y0 << ".."
        << box.y1;
    // A title: drawn pixels in the top band, left of the middle of the picture.
    const int band = std::max (10, picture.height / 20);
    EXPECT_GT (pixelBox (picture, drawn, 0, 0, picture.width / 2, band).count, 20u)
        << "no title";
  }
}
} // namespace
