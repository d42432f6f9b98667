/*
 * pcl_ext::NearestOfEachSegment (the partner search of Belton & Lichti section 4)
 * against a brute-force search, for queries grouped in any order.
 */
#include <pcl_ext/segmentation/nearest_of_each_segment.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <random>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using LabelCloud = pcl::PointCloud<pcl::Label>;
using Partners = pcl_ext::NearestOfEachSegment<Point>;

/** Points on a 1 m square grid patch split into stripes (segments 1-5, some 0), with
 * duplicated positions so that equal distances occur. */
struct Scene {
  Cloud::Ptr cloud{new Cloud};
  LabelCloud::Ptr segments{new LabelCloud};
  pcl::IndicesPtr candidates{new pcl::Indices};
};

Scene
makeScene (double x0)
{
  Scene s;
  std::mt19937 rng (5);
  std::uniform_real_distribution<double> jitter (-0.004, 0.004);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const bool on_grid = (i + j) % 3 == 0; // exact grid positions: equal distances
      Point p (static_cast<float> (x0 + 0.025 * i + (on_grid ? 0.0 : jitter (rng))),
               static_cast<float> (0.025 * j + (on_grid ? 0.0 : jitter (rng))),
               static_cast<float> (on_grid ? 0.0 : jitter (rng)));
      s.cloud->push_back (p);
      pcl::Label l;
      l.label = static_cast<std::uint32_t> ((i / 8 + j / 20) % 6); // 0: no segment
      s.segments->push_back (l);
      if (l.label != 0 && (i + 2 * j) % 5 != 0)
        s.candidates->push_back (static_cast<pcl::index_t> (s.cloud->size() - 1));
    }
  return s;
}

/** The nearest candidate of each other segment strictly within the reach, by (float
 * squared distance, index), closest first. */
std::vector<pcl::index_t>
bruteForce (const Scene& s, pcl::index_t query, double reach)
{
  const Point& q = (*s.cloud)[query];
  const std::uint32_t own = (*s.segments)[query].label;
  const float limit = static_cast<float> (reach * reach);
  std::map<std::uint32_t, std::pair<float, pcl::index_t>> best;
  for (const auto j : *s.candidates) {
    const Point& p = (*s.cloud)[j];
    const float dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
    const float d = dx * dx + dy * dy + dz * dz;
    const std::uint32_t seg = (*s.segments)[j].label;
    if (!(d < limit) || seg == own)
      continue;
    const auto candidate = std::make_pair (d, j);
    auto it = best.find (seg);
    if (it == best.end())
      best.emplace (seg, candidate);
    else if (candidate < it->second)
      it->second = candidate;
  }
  std::vector<std::pair<float, pcl::index_t>> sorted;
  for (const auto& b : best)
    sorted.push_back (b.second);
  std::sort (sorted.begin(), sorted.end());
  std::vector<pcl::index_t> out;
  for (const auto& b : sorted)
    out.push_back (b.second);
  return out;
}
} // namespace

TEST (NearestOfEachSegment, EqualsABruteForceSearchForAnyGrouping)
{
  // Far from the origin too: the float distances are compared as the tree computes
  // them.
  for (const double x0 : {0.0, 300000.0}) {
    const Scene s = makeScene (x0);
    Partners partners;
    partners.setInput (s.cloud, s.segments, s.candidates);
    // Every point a query, with reaches from none to a quarter of the patch, in the
    // cloud's order, reversed and shuffled, in batches of 1, 7 and all.
    pcl::Indices order (s.cloud->size());
    std::vector<double> reach_of (s.cloud->size());
    std::mt19937 rng (9);
    std::uniform_real_distribution<double> reach (0.0, 0.25);
    for (std::size_t i = 0; i < order.size(); ++i) {
      order[i] = static_cast<pcl::index_t> (i);
      reach_of[i] = i % 17 == 0 ? 0.0 : reach (rng);
    }
    std::vector<pcl::Indices> orders{order, order, order};
    std::reverse (orders[1].begin(), orders[1].end());
    std::shuffle (orders[2].begin(), orders[2].end(), rng);
    std::size_t found = 0;
    Partners::Scratch scratch;
    for (const auto& o : orders)
      for (const std::size_t batch : {std::size_t (1), std::size_t (7), o.size()})
        for (std::size_t first = 0; first < o.size(); first += batch) {
          const pcl::Indices queries (o.begin() + first,
                                      o.begin() + std::min (o.size(), first + batch));
          std::vector<double> reaches;
          for (const auto q : queries)
            reaches.push_back (reach_of[q]);
          std::vector<std::size_t> offsets;
          std::vector<pcl::index_t> nearest;
          partners.find (queries, reaches, scratch, offsets, nearest);
          ASSERT_EQ (offsets.size(), queries.size() + 1);
          for (std::size_t q = 0; q < queries.size(); ++q) {
            const std::vector<pcl::index_t> row (nearest.begin() + offsets[q],
                                                 nearest.begin() + offsets[q + 1]);
            ASSERT_EQ (row, bruteForce (s, queries[q], reaches[q]))
                << "query " << queries[q] << " reach " << reaches[q];
            found += row.size();
          }
        }
    EXPECT_GT (found, s.cloud->size()); // most queries have partners
  }
}

TEST (NearestOfEachSegment, NoCandidatesOrNoReachGiveEmptyRows)
{
  const Scene s = makeScene (0.0);
  Partners partners;
  partners.setInput (s.cloud, s.segments, pcl::IndicesPtr (new pcl::Indices));
  Partners::Scratch scratch;
  std::vector<std::size_t> offsets;
  std::vector<pcl::index_t> nearest;
  const pcl::Indices queries{0, 1, 2};
  partners.find (queries, {1.0, 1.0, 1.0}, scratch, offsets, nearest);
  EXPECT_EQ (offsets, (std::vector<std::size_t>{0, 0, 0, 0}));
  EXPECT_TRUE (nearest.empty());
  partners.setInput (s.cloud, s.segments, s.candidates);
  partners.find (queries, {0.0, -1.0, 0.5}, scratch, offsets, nearest);
  EXPECT_EQ (offsets[1], 0u);
  EXPECT_EQ (offsets[2], 0u);
  EXPECT_GT (offsets[3], 0u);
  // A reach per query is required.
  partners.find (queries, {0.5}, scratch, offsets, nearest);
  EXPECT_TRUE (nearest.empty());
  partners.clear();
  partners.find (queries, {0.5, 0.5, 0.5}, scratch, offsets, nearest);
  EXPECT_TRUE (nearest.empty());
}

TEST (NearestOfEachSegment, BadInputGivesEmptyRows)
{
  const Scene s = makeScene (0.0);
  Partners partners;
  Partners::Scratch scratch;
  std::vector<std::size_t> offsets;
  std::vector<pcl::index_t> nearest;
  // Labels not one per point: no tree, empty rows.
  LabelCloud::Ptr short_labels (new LabelCloud);
  short_labels->resize (s.cloud->size() - 1);
  partners.setInput (s.cloud, short_labels, s.candidates);
  partners.find ({0, 1}, {0.5, 0.5}, scratch, offsets, nearest);
  EXPECT_EQ (offsets, (std::vector<std::size_t>{0, 0, 0}));
  EXPECT_TRUE (nearest.empty());
  partners.setInput (nullptr, s.segments, s.candidates);
  partners.find ({0, 1}, {0.5, 0.5}, scratch, offsets, nearest);
  EXPECT_TRUE (nearest.empty());
  // A query index out of range: empty rows, whatever the others.
  partners.setInput (s.cloud, s.segments, s.candidates);
  const auto n = static_cast<pcl::index_t> (s.cloud->size());
  partners.find ({0, n, -1}, {0.5, 0.5, 0.5}, scratch, offsets, nearest);
  EXPECT_EQ (offsets.size(), 4u);
  EXPECT_TRUE (nearest.empty());
  // Candidates out of range or not finite, and a query that is not finite: left out.
  Scene with_nan = makeScene (0.0);
  (*with_nan.cloud)[5].x = std::numeric_limits<float>::quiet_NaN();
  pcl::IndicesPtr candidates (new pcl::Indices (*with_nan.candidates));
  candidates->push_back (-3);
  candidates->push_back (n + 10);
  candidates->push_back (5);
  partners.setInput (with_nan.cloud, with_nan.segments, candidates);
  partners.find ({5, 100}, {0.5, 0.3}, scratch, offsets, nearest);
  ASSERT_EQ (offsets.size(), 3u);
  EXPECT_EQ (offsets[1], 0u); // the NaN query has none
  const std::vector<pcl::index_t> row (nearest.begin() + offsets[1],
                                       nearest.begin() + offsets[2]);
  EXPECT_EQ (row, bruteForce (with_nan, 100, 0.3));
  EXPECT_FALSE (row.empty());
  EXPECT_EQ (std::count (nearest.begin(), nearest.end(), 5), 0);
}
