/*
 * NeighbourhoodOptions: the options a class searches its neighbourhoods with, their
 * checks, and shared neighbourhoods taken only when computed for the same cloud and
 * indices.
 */
#include <pcl_ext/search/neighbourhood_options.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

/** A class using the mixin the way pcl_ext's classifiers do. */
class Searcher : public pcl_ext::NeighbourhoodOptions<Point> {
public:
  bool
  check () const
  {
    return checkNeighbourhoodOptions ("[Searcher]", 3);
  }

  const pcl_ext::Neighbourhoods<Point>*
  prepare (const Cloud::ConstPtr& cloud, const pcl::IndicesConstPtr& indices = nullptr)
  {
    return prepareNeighbourhoods ("Searcher", cloud, indices);
  }

  void
  release ()
  {
    releaseNeighbourhoods();
  }
};

Cloud::Ptr
grid (int n, float spacing)
{
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      cloud->push_back (Point (spacing * i, spacing * j, 0.f));
  return cloud;
}
} // namespace

TEST (NeighbourhoodOptions, KAndRadiusClearEachOther)
{
  Searcher s;
  EXPECT_EQ (s.getKSearch(), 50);
  EXPECT_EQ (s.getRadiusSearch(), 0.0);
  s.setRadiusSearch (0.5);
  EXPECT_EQ (s.getKSearch(), 0);
  EXPECT_EQ (s.getRadiusSearch(), 0.5);
  s.setKSearch (12);
  EXPECT_EQ (s.getKSearch(), 12);
  EXPECT_EQ (s.getRadiusSearch(), 0.0);
  s.setMaxRadius (0.3);
  EXPECT_EQ (s.getMaxRadius(), 0.3);
  s.setNumberOfThreads (3);
  EXPECT_EQ (s.getNumberOfThreads(), 3u);
  EXPECT_FALSE (s.getSearchMethod());
  EXPECT_FALSE (s.getNeighbourhoods());
}

TEST (NeighbourhoodOptions, OwnSearchHonoursKAndTheMaximumRadius)
{
  const auto cloud = grid (10, 0.1f);
  Searcher s;
  s.setKSearch (20);
  const auto* nb = s.prepare (cloud);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ (nb->size(), cloud->size());
  EXPECT_EQ (nb->getKSearch(), 20);
  EXPECT_EQ ((*nb)[55].size(), 20u);
  // Capped at 0.15: an interior grid point keeps itself, its 4 neighbours at 0.1 and
  // the 4 diagonal ones at 0.141; those at 0.2 and beyond go.
  s.setMaxRadius (0.15);
  nb = s.prepare (cloud);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ ((*nb)[55].size(), 9u); // an interior point: itself, 4 at 0.1, 4 at 0.141
  s.release();
}

TEST (NeighbourhoodOptions, SharedNeighbourhoodsOnlyForTheirCloud)
{
  const auto cloud = grid (8, 0.1f);
  auto shared = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  shared->setInputCloud (cloud);
  shared->setKSearch (5);
  ASSERT_TRUE (shared->compute());
  Searcher s;
  s.setNeighbourhoods (shared);
  EXPECT_EQ (s.prepare (cloud), shared.get()); // taken as they are (k = 5, not 50)
  // Another cloud: a warning and a search of its own with the options (k = 50).
  const auto other = grid (8, 0.2f);
  const auto* own = s.prepare (other);
  ASSERT_NE (own, nullptr);
  EXPECT_NE (own, shared.get());
  EXPECT_EQ (own->getKSearch(), 50);
}

TEST (NeighbourhoodOptions, NonsenseOptionsAreRefused)
{
  const auto cloud = grid (5, 0.1f);
  Searcher s;
  EXPECT_TRUE (s.check());
  s.setKSearch (2);
  EXPECT_FALSE (s.check());
  s.setKSearch (-4);
  EXPECT_FALSE (s.check());
  s.setRadiusSearch (-1.0);
  EXPECT_FALSE (s.check());
  s.setRadiusSearch (std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE (s.check());
  s.setKSearch (10);
  s.setMaxRadius (-0.5);
  EXPECT_FALSE (s.check());
  s.setMaxRadius (std::numeric_limits<double>::infinity());
  EXPECT_FALSE (s.check());
  s.setMaxRadius (0.0);
  EXPECT_TRUE (s.check());
  // Neither k nor a radius: no search.
  s.setKSearch (0);
  EXPECT_EQ (s.prepare (cloud), nullptr);
  // More neighbours than points: the search refuses.
  s.setKSearch (1000);
  EXPECT_EQ (s.prepare (cloud), nullptr);
}
