/*
 * Tests of the index check every class runs before it reads the points its indices
 * name.
 */
#include <pcl_ext/common/indices.h>

#include <gtest/gtest.h>

#include <string>

TEST (Indices, InRangeForEveryPointOfTheCloud)
{
  EXPECT_TRUE (pcl_ext::indicesInRange ({0, 1, 4}, 5, "[test]"));
  EXPECT_TRUE (
      pcl_ext::indicesInRange ({4, 4, 0}, 5, "[test]")); // repeats are not errors
  EXPECT_TRUE (pcl_ext::indicesInRange ({}, 0, "[test]"));
  EXPECT_TRUE (pcl_ext::indicesInRange ({}, 5, "[test]"));
}

TEST (Indices, OutOfRangeIsReportedWithTheCallerAndTheFirstBadIndex)
{
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::indicesInRange ({0, 5, 7}, 5, "[pcl_ext::Test::compute]"));
  std::string message = testing::internal::GetCapturedStderr();
  EXPECT_NE (
      message.find ("[pcl_ext::Test::compute] Index 5 is out of range for a cloud of 5 "
                    "points."),
      std::string::npos)
      << message;
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::indicesInRange ({2, -1}, 5, "[test]"));
  message = testing::internal::GetCapturedStderr();
  EXPECT_NE (message.find ("Index -1 is out of range"), std::string::npos) << message;
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::indicesInRange ({0}, 0, "[test]"));
  testing::internal::GetCapturedStderr();
}
