/*
 * Tests of the profile graph's segments (Sithole & Mapurisa, section 3): connected
 * components of the stacks' edges, with the curve fitting's breakpoints.
 */
#include <pcl_ext/segmentation/profile_graph.h>

#include <gtest/gtest.h>

#include <vector>

using namespace pcl_ext::profiles;

TEST (Graph, ComponentsAndBreakpoints)
{
  // Chain 0-1-2-3-4-5 with 2 and 3 breakpoints; a second stack links 3-4 only.
  std::vector<std::vector<GraphEdge>> edges = {{{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}},
                                               {{3, 4}}};
  std::vector<std::uint32_t> labels;
  EXPECT_EQ (labelSegments (7, edges, {}, labels), 2u); // point 6 is alone
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{0, 0, 0, 0, 0, 0, 1}));
  const std::vector<std::uint8_t> breaks = {0, 0, 1, 1, 0, 0, 0};
  EXPECT_EQ (labelSegments (7, edges, breaks, labels), 3u);
  // 2 rejoins the segment of 1; 3 that of 4 (two edges to it, none to a labelled 2
  // yet).
  EXPECT_EQ (labels[0], labels[2]);
  EXPECT_EQ (labels[3], labels[5]);
  EXPECT_NE (labels[0], labels[5]);
  // Breakpoints no wave reaches form their own component.
  EXPECT_EQ (labelSegments (3, {{{0, 1}}}, {1, 1, 0}, labels), 2u);
  EXPECT_EQ (labels[0], labels[1]);
  EXPECT_NE (labels[0], labels[2]);
}
