/*
 * Tests of the shared neighbourhoods: agreement with brute force, bad input,
 * determinism.
 */
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/search/nanoflann_kdtree.h>

#include <pcl/common/point_tests.h>
#include <pcl/search/kdtree.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <string>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

Cloud::Ptr
randomCloud (std::size_t n, unsigned seed, float offset = 0.0f)
{
  Cloud::Ptr cloud (new Cloud);
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  for (std::size_t i = 0; i < n; ++i)
    cloud->push_back (Point (offset + u (rng), u (rng), 0.3f * u (rng)));
  return cloud;
}

struct Neighbour {
  float d2;
  pcl::index_t index;
  bool
  operator<(const Neighbour& o) const
  {
    return d2 < o.d2 || (d2 == o.d2 && index < o.index);
  }
};

std::vector<Neighbour>
bruteForce (const Cloud& cloud, const Point& q)
{
  std::vector<Neighbour> all;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!pcl::isFinite (cloud[i]))
      continue;
    const float dx = cloud[i].x - q.x, dy = cloud[i].y - q.y, dz = cloud[i].z - q.z;
    all.push_back ({dx * dx + dy * dy + dz * dz, static_cast<pcl::index_t> (i)});
  }
  std::sort (all.begin(), all.end());
  return all;
}

std::vector<std::size_t>
rowSizes (const pcl_ext::Neighbourhoods<Point>& nb)
{
  std::vector<std::size_t> sizes;
  for (std::size_t r = 0; r < nb.size(); ++r)
    sizes.push_back (nb[r].size());
  return sizes;
}

// Rows must hold the true k nearest (compared by distance, which is robust to ties).
void
expectKnnMatchesBruteForce (const Cloud& cloud,
                            const pcl_ext::Neighbourhoods<Point>& nb,
                            int k)
{
  ASSERT_EQ (nb.size(), cloud.size());
  for (std::size_t r = 0; r < cloud.size(); ++r) {
    const auto row = nb[r];
    if (!pcl::isFinite (cloud[r])) {
      EXPECT_TRUE (row.empty());
      continue;
    }
    const auto truth = bruteForce (cloud, cloud[r]);
    ASSERT_EQ (row.size(), static_cast<std::size_t> (k));
    for (int i = 0; i < k; ++i) {
      EXPECT_NEAR (row.sqr_distances[i], truth[i].d2, 1e-6f)
          << "row " << r << " rank " << i;
      const Point& p = cloud[row[i]];
      const float dx = p.x - cloud[r].x, dy = p.y - cloud[r].y, dz = p.z - cloud[r].z;
      EXPECT_NEAR (row.sqr_distances[i], dx * dx + dy * dy + dz * dz, 1e-6f);
    }
  }
}
} // namespace

TEST (Neighbourhoods, KnnAgreesWithBruteForce)
{
  const auto cloud = randomCloud (1500, 1);
  pcl_ext::Neighbourhoods<Point> nb;
  nb.setInputCloud (cloud);
  nb.setKSearch (12);
  ASSERT_TRUE (nb.compute());
  expectKnnMatchesBruteForce (*cloud, nb, 12);
  // The query point itself comes first, at distance 0.
  for (std::size_t r = 0; r < cloud->size(); ++r)
    EXPECT_EQ (nb[r].sqr_distances[0], 0.0f);
}

// From 24 neighbours the whole-cloud pass searches leaf by leaf (a different code
// path).
TEST (Neighbourhoods, KnnAgreesWithBruteForceLeafByLeaf)
{
  auto cloud = randomCloud (1500, 2);
  for (std::size_t i = 0; i < 100; ++i) {
    const Point twin = (*cloud)[i]; // some points twice: equal distances
    cloud->push_back (twin);
  }
  for (const int k : {24, 40}) {
    pcl_ext::Neighbourhoods<Point> one, two;
    for (auto* nb : {&one, &two}) {
      nb->setInputCloud (cloud);
      nb->setKSearch (k);
    }
    one.setNumberOfThreads (1);
    two.setNumberOfThreads (2);
    ASSERT_TRUE (one.compute());
    ASSERT_TRUE (two.compute());
    expectKnnMatchesBruteForce (*cloud, one, k);
    EXPECT_EQ (one.getNeighbourIndices(), two.getNeighbourIndices());
    EXPECT_EQ (one.getSquaredDistances(), two.getSquaredDistances());
  }
}

TEST (Neighbourhoods, RadiusAgreesWithBruteForce)
{
  const auto cloud = randomCloud (1500, 2);
  pcl_ext::Neighbourhoods<Point> nb;
  nb.setInputCloud (cloud);
  nb.setRadiusSearch (0.08);
  ASSERT_TRUE (nb.compute());
  ASSERT_EQ (nb.size(), cloud->size());
  for (std::size_t r = 0; r < cloud->size(); ++r) {
    const auto truth = bruteForce (*cloud, (*cloud)[r]);
    std::size_t expected = 0;
    while (expected < truth.size() && truth[expected].d2 <= 0.08f * 0.08f)
      ++expected;
    const auto row = nb[r];
    // Points exactly on the sphere may fall either side in float arithmetic.
    EXPECT_NEAR (static_cast<double> (row.size()), static_cast<double> (expected), 1.0);
    for (std::size_t i = 0; i < row.size(); ++i) {
      EXPECT_LE (row.sqr_distances[i], 0.08f * 0.08f * (1.0f + 1e-5f));
      if (i > 0)
        EXPECT_LE (row.sqr_distances[i - 1], row.sqr_distances[i]);
    }
  }
  nb.setMaxNeighbours (5);
  ASSERT_TRUE (nb.compute());
  for (std::size_t r = 0; r < cloud->size(); ++r) {
    EXPECT_LE (nb[r].size(), 5u);
    const auto truth = bruteForce (*cloud, (*cloud)[r]);
    for (std::size_t i = 0; i < nb[r].size(); ++i)
      EXPECT_NEAR (nb[r].sqr_distances[i], truth[i].d2, 1e-6f);
  }
}

TEST (Neighbourhoods, MaxRadiusCutsTheKNearestRows)
{
  // k nearest within a radius: the rows of a radius search limited to k, from the k
  // search.
  const auto cloud = randomCloud (1500, 4);
  pcl_ext::Neighbourhoods<Point> capped, radius;
  capped.setInputCloud (cloud);
  capped.setKSearch (20);
  capped.setMaxRadius (0.08);
  ASSERT_TRUE (capped.compute());
  radius.setInputCloud (cloud);
  radius.setRadiusSearch (0.08);
  radius.setMaxNeighbours (20);
  ASSERT_TRUE (radius.compute());
  ASSERT_EQ (capped.size(), cloud->size());
  std::size_t cut = 0;
  for (std::size_t r = 0; r < cloud->size(); ++r) {
    const auto truth = bruteForce (*cloud, (*cloud)[r]);
    std::size_t expected = 0;
    while (expected < 20 && expected < truth.size() &&
           truth[expected].d2 <= 0.08f * 0.08f)
      ++expected;
    cut += expected < 20;
    // Points exactly on the sphere may fall either side in float arithmetic.
    EXPECT_NEAR (
        static_cast<double> (capped[r].size()), static_cast<double> (expected), 1.0);
    EXPECT_NEAR (static_cast<double> (capped[r].size()),
                 static_cast<double> (radius[r].size()),
                 1.0);
    for (std::size_t i = 0; i < capped[r].size(); ++i) {
      EXPECT_NEAR (capped[r].sqr_distances[i], truth[i].d2, 1e-6f);
      EXPECT_LE (capped[r].sqr_distances[i], 0.08f * 0.08f);
    }
  }
  EXPECT_GT (cut, 100u); // the cap matters for this cloud
  capped.setMaxRadius (-1.0);
  EXPECT_FALSE (capped.compute());
  EXPECT_TRUE (capped.empty());
}

TEST (Neighbourhoods, IndicesSelectRowsButSearchTheWholeCloud)
{
  const auto cloud = randomCloud (800, 3);
  pcl::IndicesPtr indices (new pcl::Indices{5, 700, 42, 42});
  pcl_ext::Neighbourhoods<Point> nb;
  nb.setInputCloud (cloud);
  nb.setIndices (indices);
  nb.setKSearch (6);
  ASSERT_TRUE (nb.compute());
  ASSERT_EQ (nb.size(), 4u);
  for (std::size_t r = 0; r < indices->size(); ++r) {
    const auto truth = bruteForce (*cloud, (*cloud)[(*indices)[r]]);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR (nb[r].sqr_distances[i], truth[i].d2, 1e-6f);
  }
  EXPECT_EQ (nb.getRowOfPoint (700), 1);
  EXPECT_EQ (nb.getRowOfPoint (42), 2);
  EXPECT_EQ (nb.getRowOfPoint (6), -1);
  EXPECT_TRUE (nb.isComputedFor (cloud, indices));
  EXPECT_FALSE (nb.isComputedFor (cloud, nullptr));
}

TEST (Neighbourhoods, NonFinitePointsGetEmptyRowsWhateverIsDenseSays)
{
  for (const bool claimed_dense : {false, true}) {
    auto cloud = randomCloud (600, 4);
    (*cloud)[10].x = NAN;
    (*cloud)[20].y = std::numeric_limits<float>::infinity();
    (*cloud)[599].z = NAN;
    cloud->is_dense = claimed_dense;
    pcl_ext::Neighbourhoods<Point> nb;
    nb.setInputCloud (cloud);
    nb.setKSearch (8);
    ASSERT_TRUE (nb.compute());
    EXPECT_EQ (nb.getNumberOfSearchablePoints(), 597u);
    expectKnnMatchesBruteForce (*cloud, nb, 8);
    for (const auto j : nb.getNeighbourIndices())
      EXPECT_TRUE (j != 10 && j != 20 && j != 599);
  }
}

TEST (Neighbourhoods, DuplicatePointsAreOrdinaryNeighbours)
{
  auto cloud = randomCloud (300, 5);
  const Cloud copy = *cloud;
  *cloud += copy; // every point twice
  pcl_ext::Neighbourhoods<Point> nb;
  nb.setInputCloud (cloud);
  nb.setKSearch (4);
  ASSERT_TRUE (nb.compute());
  expectKnnMatchesBruteForce (*cloud, nb, 4);
  for (std::size_t r = 0; r < cloud->size(); ++r)
    EXPECT_EQ (nb[r].sqr_distances[1], 0.0f); // its twin
}

TEST (Neighbourhoods, AStackOfCopiesOfOnePointGivesEachCopyTheCopiesOfSmallestIndex)
{
  // 200,000 copies of one point (a file whose coordinates collapsed, no-return points
  // at the origin) among 2,000 others, every fourth point of the cloud a copy beyond
  // the first 2,000: each copy's k nearest are the k copies of smallest index, at
  // distance 0, whichever pass searches it (a search that walked every copy for every
  // copy would not finish).
  auto cloud = randomCloud (2000, 9);
  const Point stack (0.5f, 0.5f, 0.1f);
  std::vector<pcl::index_t> copies;
  for (std::size_t i = 0; i < 200000; ++i) {
    if (i % 4 == 0)
      cloud->push_back (Point (0.5f + 1e-3f * static_cast<float> (i % 997),
                               0.4f,
                               0.2f)); // others between the copies
    copies.push_back (static_cast<pcl::index_t> (cloud->size()));
    cloud->push_back (stack);
  }
  pcl::IndicesPtr every_other (new pcl::Indices);
  for (std::size_t i = 0; i < cloud->size(); i += 2)
    every_other->push_back (static_cast<pcl::index_t> (i));
  for (const int k : {50, 10}) {
    for (const bool subset : {false, true}) {
      pcl_ext::Neighbourhoods<Point> nb;
      nb.setInputCloud (cloud);
      if (subset)
        nb.setIndices (every_other);
      nb.setKSearch (k);
      nb.setNumberOfThreads (2);
      ASSERT_TRUE (nb.compute());
      std::size_t checked = 0;
      for (std::size_t r = 0; r < nb.size(); ++r) {
        const pcl::index_t i =
            subset ? (*every_other)[r] : static_cast<pcl::index_t> (r);
        const auto row = nb[r];
        ASSERT_EQ (row.size(), static_cast<std::size_t> (k));
        if (!((*cloud)[i].getVector3fMap() == stack.getVector3fMap()))
          continue;
        for (int j = 0; j < k; ++j) {
          ASSERT_EQ (row[j], copies[static_cast<std::size_t> (j)])
              << "k " << k << (subset ? " subset" : "") << " row " << r;
          ASSERT_EQ (row.sqr_distances[j], 0.0f);
        }
        ++checked;
      }
      EXPECT_EQ (checked, subset ? 100000u : 200000u);
      // The other points' rows as brute force ranks them (a sample).
      for (std::size_t r = 0; r < nb.size(); r += 7919) {
        const pcl::index_t i =
            subset ? (*every_other)[r] : static_cast<pcl::index_t> (r);
        const auto truth = bruteForce (*cloud, (*cloud)[i]);
        for (int j = 0; j < k; ++j)
          ASSERT_EQ (nb[r][j], truth[static_cast<std::size_t> (j)].index)
              << "k " << k << " row " << r << " rank " << j;
      }
    }
  }
}

TEST (Neighbourhoods, BadInputGivesAnErrorAndNothing)
{
  pcl_ext::Neighbourhoods<Point> nb;
  EXPECT_FALSE (nb.compute()); // no input

  nb.setInputCloud (Cloud::Ptr (new Cloud));
  nb.setKSearch (5);
  EXPECT_FALSE (nb.compute());
  EXPECT_TRUE (nb.empty());

  const auto cloud = randomCloud (10, 6);
  nb.setInputCloud (cloud);
  nb.setKSearch (11); // k larger than the cloud
  EXPECT_FALSE (nb.compute());
  EXPECT_TRUE (nb.empty());
  nb.setKSearch (10); // exactly the cloud: fine
  EXPECT_TRUE (nb.compute());
  EXPECT_EQ (nb.size(), 10u);
  nb.setKSearch (0); // neither k nor radius
  EXPECT_FALSE (nb.compute());
  EXPECT_TRUE (nb.empty());
  nb.setKSearch (-3);
  EXPECT_FALSE (nb.compute());
  nb.setRadiusSearch (-1.0);
  EXPECT_FALSE (nb.compute());
  nb.setRadiusSearch (std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE (nb.compute());
  nb.setRadiusSearch (std::numeric_limits<double>::infinity());
  EXPECT_FALSE (nb.compute());

  Cloud::Ptr all_nan (new Cloud);
  all_nan->resize (20, Point (NAN, NAN, NAN));
  all_nan->is_dense = false;
  nb.setInputCloud (all_nan);
  nb.setKSearch (1);
  EXPECT_FALSE (nb.compute());
  EXPECT_TRUE (nb.empty());

  nb.setInputCloud (cloud);
  nb.setIndices (pcl::IndicesPtr (new pcl::Indices{0, 10})); // 10 is out of range
  EXPECT_FALSE (nb.compute());
  nb.setIndices (pcl::IndicesPtr (new pcl::Indices{0, -1}));
  EXPECT_FALSE (nb.compute());
  EXPECT_TRUE (nb.empty());
}

TEST (Neighbourhoods, DeterministicForAnyThreadCountAndSearchMethod)
{
  const auto cloud = randomCloud (20000, 7, 6000.0f);
  pcl_ext::Neighbourhoods<Point> one, two, flann;
  for (auto* nb : {&one, &two, &flann}) {
    nb->setInputCloud (cloud);
    nb->setKSearch (16);
  }
  one.setNumberOfThreads (1);
  two.setNumberOfThreads (2);
  flann.setSearchMethod (
      pcl::search::KdTree<Point>::Ptr (new pcl::search::KdTree<Point>));
  ASSERT_TRUE (one.compute());
  ASSERT_TRUE (two.compute());
  ASSERT_TRUE (flann.compute());
  EXPECT_EQ (rowSizes (one), rowSizes (two));
  EXPECT_EQ (one.getNeighbourIndices(), two.getNeighbourIndices());
  EXPECT_EQ (one.getSquaredDistances(), two.getSquaredDistances());
  ASSERT_EQ (one.getSquaredDistances().size(), flann.getSquaredDistances().size());
  for (std::size_t i = 0; i < one.getSquaredDistances().size(); ++i)
    ASSERT_NEAR (one.getSquaredDistances()[i], flann.getSquaredDistances()[i], 1e-6f);

  pcl_ext::Neighbourhoods<Point> r1, r2;
  for (auto* nb : {&r1, &r2}) {
    nb->setInputCloud (cloud);
    nb->setRadiusSearch (0.02);
  }
  r1.setNumberOfThreads (1);
  r2.setNumberOfThreads (2);
  ASSERT_TRUE (r1.compute());
  ASSERT_TRUE (r2.compute());
  EXPECT_EQ (rowSizes (r1), rowSizes (r2));
  EXPECT_EQ (r1.getNeighbourIndices(), r2.getNeighbourIndices());
}

TEST (Neighbourhoods, WithoutStoredDistancesTheRowsAndDistancesAreTheSame)
{
  // Leaf by leaf (k >= 24) and point by point (k < 24), capped at a radius, for chosen
  // rows, and by radius: the same rows, and distances computed from the coordinates
  // equal to those the search stored, bit for bit. With k, the rows take k indices a
  // point (a point with NaN coordinates included, its row empty) and no distances.
  auto cloud = randomCloud (3000, 11, 500.0f);
  (*cloud)[17].x = std::numeric_limits<float>::quiet_NaN();
  const pcl::IndicesPtr some (new pcl::Indices{3, 2999, 17, 1200});
  struct Setting {
    int k;
    double radius, max_radius;
    pcl::IndicesPtr indices;
  };
  const std::vector<Setting> settings{{50, 0.0, 0.0, nullptr},
                                      {8, 0.0, 0.0, nullptr},
                                      {50, 0.0, 0.04, nullptr},
                                      {30, 0.0, 0.0, some},
                                      {0, 0.05, 0.0, nullptr}};
  for (const auto& setting : settings) {
    pcl_ext::Neighbourhoods<Point> stored, computed;
    for (auto* nb : {&stored, &computed}) {
      nb->setInputCloud (cloud);
      if (setting.indices)
        nb->setIndices (setting.indices);
      if (setting.k > 0) {
        nb->setKSearch (setting.k);
        nb->setMaxRadius (setting.max_radius);
      }
      else
        nb->setRadiusSearch (setting.radius);
    }
    computed.setStoreSquaredDistances (false);
    ASSERT_TRUE (stored.compute());
    ASSERT_TRUE (computed.compute());
    const std::string what = "k " + std::to_string (setting.k) + ", radius " +
                             std::to_string (setting.radius) + ", cap " +
                             std::to_string (setting.max_radius);
    EXPECT_TRUE (computed.getSquaredDistances().empty()) << what;
    ASSERT_EQ (rowSizes (stored), rowSizes (computed)) << what;
    std::size_t compared = 0;
    for (std::size_t r = 0; r < stored.size(); ++r) {
      EXPECT_EQ (computed[r].sqr_distances, nullptr);
      for (std::size_t i = 0; i < stored[r].size(); ++i, ++compared) {
        ASSERT_EQ (stored[r][i], computed[r][i]) << what << ", row " << r;
        ASSERT_EQ (stored[r].sqr_distances[i], computed.getSquaredDistance (r, i))
            << what << ", row " << r;
        ASSERT_EQ (stored.getSquaredDistance (r, i), stored[r].sqr_distances[i]);
      }
    }
    EXPECT_GT (compared, stored.size()) << what;
    const std::size_t nan_row = setting.indices ? 2 : 17;
    EXPECT_TRUE (computed[nan_row].empty()) << what;
    if (setting.k > 0 && setting.max_radius == 0.0)
      EXPECT_EQ (computed.getNeighbourIndices().size(),
                 computed.size() * static_cast<std::size_t> (setting.k))
          << what;
  }
}
