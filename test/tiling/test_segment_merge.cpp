/*
 * SegmentMerge: segments joined through the halos, ids numbered by first point whatever
 * the order of the joins.
 */
#include <pcl_ext/tiling/segment_merge.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using pcl_ext::tiling::SegmentMerge;

namespace {
struct Join {
  SegmentMerge::Key owner, other;
};
} // namespace

TEST (SegmentMerge, AWallAcrossFourTilesCornerIsOneSegment)
{
  // Points 0-3 are owned by tiles 0-3 (segment 0 in each, the wall); each tile also
  // saw the neighbouring tiles' wall points in its halo, as its own segment 0. Point 4
  // is a second object of tile 2 (segment 1), point 5 lies in no segment.
  std::vector<Join> joins;
  for (std::uint32_t t = 0; t < 4; ++t)
    joins.push_back ({SegmentMerge::key (t, 0), SegmentMerge::key ((t + 1) % 4, 0)});
  std::vector<SegmentMerge::Key> owners{SegmentMerge::key (0, 0),
                                        SegmentMerge::key (1, 0),
                                        SegmentMerge::key (2, 0),
                                        SegmentMerge::key (3, 0),
                                        SegmentMerge::key (2, 1),
                                        SegmentMerge::kNoKey};
  std::mt19937 rng (3);
  for (int order = 0; order < 10; ++order) {
    std::shuffle (joins.begin(), joins.end(), rng);
    SegmentMerge merge;
    for (const auto& j : joins)
      merge.join (j.owner, j.other);
    std::vector<std::uint32_t> ids;
    for (const auto k : owners)
      ids.push_back (merge.number (k));
    EXPECT_EQ (ids,
               (std::vector<std::uint32_t>{0, 0, 0, 0, 1, SegmentMerge::kNoSegment}));
    EXPECT_EQ (merge.getNumberOfSegments(), 2u);
  }
}

TEST (SegmentMerge, ASegmentSeenOnlyInAHaloAddsNothing)
{
  SegmentMerge merge;
  // Tile 1 labelled tile 0's points 0-2 as its segment 5 (in its halo): they are tile
  // 0's segment 0. Segment 5 of tile 1 owns no point: it must not appear.
  merge.join (SegmentMerge::key (0, 0), SegmentMerge::key (1, 5));
  merge.join (SegmentMerge::key (0, 0), SegmentMerge::kNoKey); // no label in tile 2
  EXPECT_EQ (merge.number (SegmentMerge::key (0, 0)), 0u);
  EXPECT_EQ (merge.number (SegmentMerge::key (1, 2)), 1u);
  EXPECT_EQ (merge.number (SegmentMerge::key (0, 0)), 0u);
  EXPECT_EQ (merge.getNumberOfSegments(), 2u);
}

TEST (SegmentMerge, ChainsOfTilesJoinTransitively)
{
  // A long wall over 50 tiles in a row, joined pairwise through the halos in a random
  // order, then a second wall in every other tile that touches nothing.
  std::vector<Join> joins;
  for (std::uint32_t t = 0; t + 1 < 50; ++t)
    joins.push_back ({SegmentMerge::key (t + 1, 0), SegmentMerge::key (t, 0)});
  std::shuffle (joins.begin(), joins.end(), std::mt19937 (11));
  SegmentMerge merge;
  for (const auto& j : joins)
    merge.join (j.owner, j.other);
  // Points in order: tile 0's second wall (id 0), the long wall (id 1), then the second
  // walls of tiles 2, 4, ... (ids 2, 3, ...), each followed by a point of the long
  // wall.
  EXPECT_EQ (merge.number (SegmentMerge::key (0, 1)), 0u);
  EXPECT_EQ (merge.number (SegmentMerge::key (0, 0)), 1u);
  for (std::uint32_t t = 2; t < 50; t += 2) {
    EXPECT_EQ (merge.number (SegmentMerge::key (t, 1)), t / 2 + 1);
    EXPECT_EQ (merge.number (SegmentMerge::key (t + 1, 0)), 1u);
  }
  EXPECT_EQ (merge.getNumberOfSegments(), 26u);
}

TEST (SegmentMerge, NumberedBySizeOverTheJoinedTiles)
{
  // A wall over tiles 0 and 1 (3 + 2 points, first point 10), a roof in tile 1 (4
  // points, first 2), a box in tile 0 (4 points, first 7: after the roof in a tie) and
  // a speck in tile 2 (1 point): largest first, ties by first point, the speck dropped
  // at a minimum size of 2, whatever the order of the calls.
  for (int order = 0; order < 2; ++order) {
    SegmentMerge merge;
    if (order == 0)
      merge.join (SegmentMerge::key (1, 0), SegmentMerge::key (0, 0));
    merge.addPoints (SegmentMerge::key (0, 0), 3, 10);
    merge.addPoints (SegmentMerge::key (1, 0), 2, 12);
    merge.addPoints (SegmentMerge::key (1, 1), 4, 2);
    merge.addPoints (SegmentMerge::key (0, 1), 4, 7);
    merge.addPoints (SegmentMerge::key (2, 0), 1, 0);
    if (order == 1)
      merge.join (SegmentMerge::key (0, 0), SegmentMerge::key (1, 0));
    merge.numberBySize (2);
    EXPECT_EQ (merge.getNumberOfSegments(), 3u);
    EXPECT_EQ (merge.number (SegmentMerge::key (2, 0)), SegmentMerge::kNoSegment);
    EXPECT_EQ (merge.number (SegmentMerge::key (1, 0)), 0u);
    EXPECT_EQ (merge.number (SegmentMerge::key (0, 0)), 0u);
    EXPECT_EQ (merge.number (SegmentMerge::key (0, 1)), 2u);
    EXPECT_EQ (merge.number (SegmentMerge::key (1, 1)), 1u);
    EXPECT_EQ (merge.number (SegmentMerge::key (3, 0)), SegmentMerge::kNoSegment);
    EXPECT_EQ (merge.number (SegmentMerge::kNoKey), SegmentMerge::kNoSegment);
  }
}
