/*
 * Tests of KdTree3f's search of many tree points at once against brute force, including
 * distance ties, duplicates and leaves that straddle sparse points.
 */
#include <pcl_ext/search/kdtree_3f.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace {
/** A scanned-like mix: a dense wavy patch, a lattice (many equal distances), every
 * lattice point twice (zero distances) and a few sparse points far away, so that some
 * leaves hold points much farther apart than their neighbourhoods. */
std::vector<float>
mixedCloud ()
{
  std::vector<float> xyz;
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> u (-1.0f, 1.0f);
  for (int i = 0; i < 3000; ++i) {
    const float x = u (rng), y = u (rng);
    xyz.insert (xyz.end(), {x, y, 0.1f * std::sin (3 * x) * std::cos (2 * y)});
  }
  for (int copy = 0; copy < 2; ++copy)
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j)
        xyz.insert (xyz.end(), {3.0f + 0.05f * i, 0.05f * j, 0.0f});
  for (int i = 0; i < 40; ++i)
    xyz.insert (xyz.end(), {10.0f + 5.0f * u (rng), 10.0f * u (rng), 3.0f * u (rng)});
  return xyz;
}

/** The k nearest of the point at tree position q by (squared distance, tree position).
 */
std::vector<std::pair<float, std::size_t>>
bruteForce (const pcl_ext::search::KdTree3f& tree, std::size_t q, std::size_t k)
{
  std::vector<std::pair<float, std::size_t>> all;
  const float* a = tree.point (q);
  for (std::size_t pos = 0; pos < tree.size(); ++pos) {
    const float* b = tree.point (pos);
    const float dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    all.emplace_back (dx * dx + dy * dy + dz * dz, pos);
  }
  // Equal distances in the order of the points' indices, as the searches rank them.
  std::partial_sort (
      all.begin(), all.begin() + k, all.end(), [&tree] (const auto& u, const auto& v) {
        return u.first < v.first ||
               (u.first == v.first &&
                tree.pointIndex (u.second) < tree.pointIndex (v.second));
      });
  all.resize (k);
  return all;
}

pcl_ext::search::KdTree3f&
mixedTree ()
{
  static pcl_ext::search::KdTree3f tree;
  if (tree.size() == 0) {
    auto xyz = mixedCloud();
    std::vector<pcl::index_t> ids (xyz.size() / 3);
    for (std::size_t i = 0; i < ids.size(); ++i)
      ids[i] = static_cast<pcl::index_t> (1000 + i); // not the positions
    tree.build (std::move (xyz), std::move (ids), 24);
  }
  return tree;
}
} // namespace

TEST (KdTree3f, LeavesCoverEveryPositionOnceInOrder)
{
  const auto& tree = mixedTree();
  const auto leaves = tree.leafRanges();
  ASSERT_FALSE (leaves.empty());
  std::size_t next = 0;
  for (const auto& leaf : leaves) {
    EXPECT_EQ (leaf.first, next);
    EXPECT_GT (leaf.second, leaf.first);
    EXPECT_LE (leaf.second - leaf.first, 24u);
    next = leaf.second;
  }
  EXPECT_EQ (next, tree.size());
}

TEST (KdTree3f, SearchOfLeavesIsExactWithTiesInPointIndexOrder)
{
  const auto& tree = mixedTree();
  for (const std::size_t k : {1u, 2u, 16u, 50u}) {
    std::vector<pcl::index_t> indices;
    std::vector<float> d2;
    std::size_t ties = 0;
    for (const auto& leaf : tree.leafRanges()) {
      const std::size_t n = leaf.second - leaf.first;
      indices.assign (n * k, -1);
      d2.assign (n * k, -1.0f);
      ASSERT_EQ (tree.nearestKSearchOfPoints (
                     leaf.first, leaf.second, k, indices.data(), d2.data()),
                 k);
      for (std::size_t i = 0; i < n; ++i) {
        const auto truth = bruteForce (tree, leaf.first + i, k);
        for (std::size_t j = 0; j < k; ++j) {
          ASSERT_EQ (d2[i * k + j], truth[j].first)
              << "k " << k << " point " << leaf.first + i;
          ASSERT_EQ (indices[i * k + j], tree.pointIndex (truth[j].second))
              << "k " << k << " point " << leaf.first + i << " rank " << j;
          ties += j > 0 && truth[j].first == truth[j - 1].first;
        }
      }
    }
    if (k > 1) // the duplicates and the lattice give equal distances within a row
      EXPECT_GT (ties, 0u) << "k " << k;
  }
}

TEST (KdTree3f, SingleSearchRanksTiesByPointIndexToo)
{
  // The duplicates and the lattice of the mixed cloud put ties at the k-th neighbour:
  // the one query at a time must keep the same ones as the search of leaves.
  const auto& tree = mixedTree();
  const std::size_t k = 16;
  std::vector<pcl::index_t> indices (k);
  std::vector<float> d2 (k);
  for (std::size_t pos = 0; pos < tree.size(); ++pos) {
    ASSERT_EQ (tree.nearestKSearch (tree.point (pos), k, indices.data(), d2.data()), k);
    const auto truth = bruteForce (tree, pos, k);
    for (std::size_t j = 0; j < k; ++j) {
      ASSERT_EQ (d2[j], truth[j].first) << "point " << pos;
      ASSERT_EQ (indices[j], tree.pointIndex (truth[j].second))
          << "point " << pos << " rank " << j;
    }
  }
}

TEST (KdTree3f, SearchOfAPointDoesNotDependOnItsRange)
{
  const auto& tree = mixedTree();
  const std::size_t k = 20, n = tree.size();
  std::vector<pcl::index_t> by_leaf (n * k), alone (n * k), by_block (n * k);
  std::vector<float> d_leaf (n * k), d_alone (n * k), d_block (n * k);
  for (const auto& leaf : tree.leafRanges())
    tree.nearestKSearchOfPoints (
        leaf.first, leaf.second, k, &by_leaf[leaf.first * k], &d_leaf[leaf.first * k]);
  for (std::size_t pos = 0; pos < n; ++pos)
    tree.nearestKSearchOfPoints (pos, pos + 1, k, &alone[pos * k], &d_alone[pos * k]);
  // Runs of 37 positions, across leaf borders and across the far sparse points.
  for (std::size_t first = 0; first < n; first += 37) {
    const std::size_t last = std::min (n, first + 37);
    tree.nearestKSearchOfPoints (
        first, last, k, &by_block[first * k], &d_block[first * k]);
  }
  EXPECT_EQ (by_leaf, alone);
  EXPECT_EQ (by_leaf, by_block);
  EXPECT_EQ (d_leaf, d_alone);
  EXPECT_EQ (d_leaf, d_block);
}

TEST (KdTree3f, SearchOfPointsHandlesEdgeCases)
{
  pcl_ext::search::KdTree3f empty;
  pcl::index_t index = -1;
  float d2 = -1.0f;
  EXPECT_EQ (empty.nearestKSearchOfPoints (0, 1, 1, &index, &d2), 0u);
  EXPECT_TRUE (empty.leafRanges().empty());

  // k = 0 finds nothing; an empty range writes nothing.
  pcl_ext::search::KdTree3f one;
  one.build ({0, 0, 0}, {4});
  EXPECT_EQ (one.nearestKSearchOfPoints (0, 1, 0, &index, &d2), 0u);
  EXPECT_EQ (one.nearestKSearchOfPoints (1, 1, 1, &index, &d2), 1u);
  EXPECT_EQ (index, -1);
  EXPECT_EQ (d2, -1.0f);
  ASSERT_EQ (one.nearestKSearchOfPoints (0, 1, 1, &index, &d2), 1u);
  EXPECT_EQ (index, 4);
  EXPECT_EQ (d2, 0.0f);

  // k larger than the tree: every point, k clamped; a range past the end is clamped
  // too.
  pcl_ext::search::KdTree3f three;
  three.build ({0, 0, 0, 1, 0, 0, 1, 0, 0}, {7, 8, 9});
  std::vector<pcl::index_t> indices (3 * 5, -1);
  std::vector<float> sqr (3 * 5, -1.0f);
  ASSERT_EQ (three.nearestKSearchOfPoints (0, 10, 5, indices.data(), sqr.data()), 3u);
  for (std::size_t pos = 0; pos < 3; ++pos) {
    // The rows are k = 3 wide. The two points at (1, 0, 0) see each other at distance 0
    // and the origin at 1; the origin sees both at 1.
    const bool origin = three.pointIndex (pos) == 7;
    const float expected[3] = {0.0f, origin ? 1.0f : 0.0f, 1.0f};
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_EQ (sqr[pos * 3 + j], expected[j]) << "position " << pos << " rank " << j;
    if (origin)
      EXPECT_EQ (indices[pos * 3], 7);
    else {
      EXPECT_EQ (indices[pos * 3] + indices[pos * 3 + 1], 8 + 9);
      EXPECT_EQ (indices[pos * 3 + 2], 7);
    }
  }
}

TEST (KdTree3f, TheTreeIsTheSameBuiltOnAnyNumberOfThreads)
{
  // Large enough for the parallel build (the serial one below 65,536 points): the mixed
  // cloud 30 times over, shifted, with its duplicates and sparse points.
  const auto base = mixedCloud();
  std::vector<float> xyz;
  for (int copy = 0; copy < 30; ++copy)
    for (std::size_t i = 0; i < base.size(); i += 3)
      xyz.insert (xyz.end(),
                  {base[i] + 0.5f * static_cast<float> (copy % 6),
                   base[i + 1] + 0.7f * static_cast<float> (copy / 6),
                   base[i + 2]});
  std::vector<pcl::index_t> ids (xyz.size() / 3);
  for (std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = static_cast<pcl::index_t> (i);
  ASSERT_GT (ids.size(), 65536u);

  pcl_ext::search::KdTree3f serial;
  serial.build (xyz, ids, 24, 1);
  for (const unsigned int threads : {2u, 3u, 8u}) {
    pcl_ext::search::KdTree3f parallel;
    parallel.build (xyz, ids, 24, threads);
    ASSERT_EQ (parallel.size(), serial.size());
    EXPECT_EQ (parallel.leafRanges(), serial.leafRanges()) << threads << " threads";
    for (std::size_t pos = 0; pos < serial.size(); ++pos) {
      ASSERT_EQ (parallel.pointIndex (pos), serial.pointIndex (pos)) << pos;
      ASSERT_TRUE (std::equal (
          serial.point (pos), serial.point (pos) + 3, parallel.point (pos)));
    }
    // The searches walk the nodes' split values: the same results from both trees.
    std::vector<pcl::index_t> a (50), b (50);
    std::vector<float> da (50), db (50);
    for (std::size_t pos = 0; pos < serial.size(); pos += 997) {
      ASSERT_EQ (serial.nearestKSearch (serial.point (pos), 50, a.data(), da.data()),
                 50u);
      ASSERT_EQ (parallel.nearestKSearch (serial.point (pos), 50, b.data(), db.data()),
                 50u);
      EXPECT_EQ (a, b) << pos;
      EXPECT_EQ (da, db) << pos;
    }
  }
}
