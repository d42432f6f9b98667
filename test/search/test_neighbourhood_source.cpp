/*
 * Tests of NeighbourhoodSource: shared neighbourhoods taken when computed for the same
 * cloud and indices, otherwise a search of its own with exactly one of k and a radius.
 */
#include <pcl_ext/search/neighbourhood_source.h>

#include <pcl/search/kdtree.h>

#include <gtest/gtest.h>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Source = pcl_ext::NeighbourhoodSource<Point>;

/** An n x n sourceGrid at z = 0; point i * n + j at (spacing i, spacing j, 0). */
Cloud::Ptr
sourceGrid (int n, float spacing)
{
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      cloud->push_back (Point (spacing * i, spacing * j, 0.f));
  return cloud;
}
} // namespace

TEST (NeighbourhoodSource, OwnSearchWithKOrARadius)
{
  const auto cloud = sourceGrid (10, 0.1f);
  Source source;
  EXPECT_FALSE (source.getShared());
  const auto* nb = source.prepare ("Test::compute", cloud, nullptr, 6, 0.0, nullptr, 1);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ (nb->size(), 100u);
  EXPECT_EQ (nb->getKSearch(), 6);
  for (std::size_t r = 0; r < nb->size(); ++r)
    EXPECT_EQ ((*nb)[r].size(), 6u) << r;
  // A radius just over the spacing: an interior point, itself and its four sourceGrid
  // neighbours.
  nb = source.prepare ("Test::compute", cloud, nullptr, 0, 0.1001, nullptr, 2);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ (nb->getRadiusSearch(), 0.1001);
  EXPECT_EQ (nb->getNumberOfThreads(), 2u);
  EXPECT_EQ ((*nb)[55].size(), 5u);
  EXPECT_EQ ((*nb)[0].size(), 3u); // a corner
  // Indices: one row per index; a search method of the caller's is used.
  const auto indices = pcl::make_shared<pcl::Indices> (pcl::Indices{55, 0});
  const auto kdtree = pcl::make_shared<pcl::search::KdTree<Point>>();
  nb = source.prepare ("Test::compute", cloud, indices, 4, 0.0, kdtree, 1);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ (nb->size(), 2u);
  EXPECT_EQ (nb->getSearchMethod().get(), kdtree.get());
  EXPECT_EQ ((*nb)[0][0], 55);
  EXPECT_EQ ((*nb)[1][0], 0);
  // With k, the maximum radius keeps the k nearest within it.
  nb = source.prepare ("Test::compute", cloud, nullptr, 20, 0.0, nullptr, 1, 0.15);
  ASSERT_NE (nb, nullptr);
  EXPECT_EQ ((*nb)[55].size(), 9u); // itself, 4 at 0.1, 4 at 0.141
  source.release();
}

TEST (NeighbourhoodSource, ExactlyOneOfKAndRadiusUnlessShared)
{
  const auto cloud = sourceGrid (5, 0.1f);
  Source source;
  testing::internal::CaptureStderr();
  EXPECT_EQ (source.prepare ("Test::compute", cloud, nullptr, 0, 0.0, nullptr, 1),
             nullptr);
  EXPECT_EQ (source.prepare ("Test::compute", cloud, nullptr, 5, 0.2, nullptr, 1),
             nullptr);
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_NE (message.find ("[pcl_ext::Test::compute] Set exactly one of k"),
             std::string::npos)
      << message;
  // A search that fails (more neighbours than points): null as well.
  testing::internal::CaptureStderr();
  EXPECT_EQ (source.prepare ("Test::compute", cloud, nullptr, 100, 0.0, nullptr, 1),
             nullptr);
  testing::internal::GetCapturedStderr();
}

TEST (NeighbourhoodSource, SharedOnlyForTheirCloudAndIndices)
{
  const auto cloud = sourceGrid (8, 0.1f);
  auto shared = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  shared->setInputCloud (cloud);
  shared->setKSearch (5);
  ASSERT_TRUE (shared->compute());
  Source source;
  source.setShared (shared);
  EXPECT_EQ (source.getShared().get(), shared.get());
  // Taken as they are, whatever k and radius the caller has (none here).
  EXPECT_EQ (source.prepare ("Test::compute", cloud, nullptr, 0, 0.0, nullptr, 1),
             shared.get());
  EXPECT_EQ (source.prepare ("Test::compute", cloud, nullptr, 9, 0.0, nullptr, 1),
             shared.get());
  // Other indices, or another cloud: a warning and a search of its own with the
  // caller's k.
  const auto indices = pcl::make_shared<pcl::Indices> (pcl::Indices{3, 4});
  testing::internal::CaptureStderr();
  const auto* own =
      source.prepare ("Test::compute", cloud, indices, 3, 0.0, nullptr, 1);
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_NE (message.find ("not computed for this cloud"), std::string::npos)
      << message;
  ASSERT_NE (own, nullptr);
  EXPECT_NE (own, shared.get());
  EXPECT_EQ (own->size(), 2u);
  EXPECT_EQ ((*own)[0].size(), 3u);
  testing::internal::CaptureStderr();
  own = source.prepare (
      "Test::compute", sourceGrid (8, 0.2f), nullptr, 3, 0.0, nullptr, 1);
  testing::internal::GetCapturedStderr();
  ASSERT_NE (own, nullptr);
  EXPECT_NE (own, shared.get());
  EXPECT_EQ (own->getKSearch(), 3);
  // Computed for the same indices: taken.
  auto shared_indexed = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  shared_indexed->setInputCloud (cloud);
  shared_indexed->setIndices (indices);
  shared_indexed->setKSearch (4);
  ASSERT_TRUE (shared_indexed->compute());
  source.setShared (shared_indexed);
  EXPECT_EQ (source.prepare ("Test::compute", cloud, indices, 0, 0.0, nullptr, 1),
             shared_indexed.get());
}
