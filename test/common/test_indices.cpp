/*
 * Tests of the index check every class runs before it reads the points its indices
 * name, and of the grouping of a classifier's labels by class.
 */
#include <pcl_ext/common/indices.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

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

TEST (Indices, GroupByClassNamesThePointsOfEachRow)
{
  pcl::PointCloud<pcl::Label> labels;
  for (const std::uint32_t l : {2, 0, 2, 7, 1})
    labels.push_back (pcl::Label{l});
  pcl::PCLHeader header;
  header.frame_id = "scan";
  const auto clamp = [] (std::uint32_t l) { return std::min<std::size_t> (l, 2); };
  std::vector<pcl::PointIndices> grouped (5); // replaced, not appended to
  // Without indices row r is point r; label 7 is clamped into the last class.
  pcl_ext::groupByClass (labels, nullptr, 3, clamp, header, grouped);
  ASSERT_EQ (grouped.size(), 3u);
  EXPECT_EQ (grouped[0].indices, (pcl::Indices{1}));
  EXPECT_EQ (grouped[1].indices, (pcl::Indices{4}));
  EXPECT_EQ (grouped[2].indices, (pcl::Indices{0, 2, 3}));
  for (const auto& g : grouped)
    EXPECT_EQ (g.header.frame_id, "scan");
  // With indices row r is point indices[r]; a class of 3 or more leaves the row out.
  const pcl::Indices indices{10, 11, 12, 13, 14};
  const auto exact = [] (std::uint32_t l) { return std::size_t (l); };
  pcl_ext::groupByClass (labels, &indices, 3, exact, header, grouped);
  ASSERT_EQ (grouped.size(), 3u);
  EXPECT_EQ (grouped[0].indices, (pcl::Indices{11}));
  EXPECT_EQ (grouped[1].indices, (pcl::Indices{14}));
  EXPECT_EQ (grouped[2].indices, (pcl::Indices{10, 12}));
}
