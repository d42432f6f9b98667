/*
 * UnionFind: disjoint sets whose root is the smallest element, whatever the order of
 * unions.
 */
#include <pcl_ext/common/union_find.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

TEST (UnionFind, SingletonsThenUnions)
{
  pcl_ext::UnionFind sets (6);
  for (std::uint32_t i = 0; i < 6; ++i)
    EXPECT_EQ (sets.find (i), i);
  EXPECT_TRUE (sets.unite (4, 2));
  EXPECT_TRUE (sets.unite (5, 4));
  EXPECT_FALSE (sets.unite (2, 5)); // already one set
  EXPECT_EQ (sets.find (5), 2u);    // the smallest element is the root
  EXPECT_EQ (sets.find (4), 2u);
  EXPECT_EQ (sets.find (3), 3u);
  EXPECT_TRUE (sets.unite (3, 0));
  EXPECT_TRUE (sets.unite (5, 3));
  for (const std::uint32_t i : {0u, 2u, 3u, 4u, 5u})
    EXPECT_EQ (sets.find (i), 0u);
  EXPECT_EQ (sets.find (1), 1u);
}

TEST (UnionFind, RootsDoNotDependOnTheOrderOfUnions)
{
  // A chain 0-1-...-99 plus a second chain 100-...-199, united in random orders.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
  for (std::uint32_t i = 0; i + 1 < 100; ++i) {
    links.emplace_back (i, i + 1);
    links.emplace_back (100 + i + 1, 100 + i);
  }
  std::vector<std::uint32_t> reference;
  for (int trial = 0; trial < 5; ++trial) {
    std::mt19937 rng (static_cast<unsigned> (trial));
    std::shuffle (links.begin(), links.end(), rng);
    pcl_ext::UnionFind sets (200);
    for (const auto& [a, b] : links)
      sets.unite (a, b);
    std::vector<std::uint32_t> roots (200);
    for (std::uint32_t i = 0; i < 200; ++i)
      roots[i] = sets.find (i);
    EXPECT_EQ (roots[99], 0u);
    EXPECT_EQ (roots[199], 100u);
    if (reference.empty())
      reference = roots;
    EXPECT_EQ (roots, reference) << "trial " << trial;
  }
}
