/*
 * Tests of the picture options every tool that renders offers (-view, -png_max_z).
 */
#include <pcl_ext/apps/picture_options.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using pcl_ext::apps::PictureOptions;

namespace {
int
parse (PictureOptions& options, std::vector<const char*> args)
{
  args.insert (args.begin(), "pcl_ext_test");
  pcl_ext::apps::CommandLine cl ("pcl_ext_test", "test");
  options.addTo (cl);
  return cl.parse (static_cast<int> (args.size()), args.data());
}
} // namespace

TEST (PictureOptions, DefaultsAreAutomatic)
{
  PictureOptions options;
  ASSERT_EQ (parse (options, {}), -1);
  EXPECT_TRUE (options.valid());
  double height = 0.0;
  ASSERT_TRUE (options.maxHeight (height));
  EXPECT_TRUE (std::isnan (height)); // auto: a ceiling found in the data
}

TEST (PictureOptions, ViewsAndHeights)
{
  for (const char* view : {"top", "side", "oblique", "sensor", "auto"}) {
    PictureOptions options;
    ASSERT_EQ (parse (options, {"-view", view}), -1);
    EXPECT_TRUE (options.valid()) << view;
  }
  PictureOptions options;
  ASSERT_EQ (parse (options, {"-png_max_z", "none"}), -1);
  double height = 0.0;
  ASSERT_TRUE (options.maxHeight (height));
  EXPECT_TRUE (std::isinf (height));
  ASSERT_EQ (parse (options, {"-png_max_z", "-2.5"}), -1);
  ASSERT_TRUE (options.maxHeight (height));
  EXPECT_DOUBLE_EQ (height, -2.5);
}

TEST (PictureOptions, NonsenseIsRefused)
{
  testing::internal::CaptureStderr();
  for (const char* z : {"high", "", "nan", "inf", "3m"}) {
    PictureOptions options;
    options.max_z = z;
    EXPECT_FALSE (options.valid()) << "'" << z << "'";
  }
  PictureOptions options;
  options.view = "front";
  EXPECT_FALSE (options.valid());
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE (said.find ("-view must be"), std::string::npos);
  EXPECT_NE (said.find ("-png_max_z must be"), std::string::npos);
}
