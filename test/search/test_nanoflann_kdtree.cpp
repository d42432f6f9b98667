/*
 * Tests of NanoflannKdTree as a pcl::search::Search, alone and inside stock PCL
 * classes.
 */
#include <pcl_ext/search/nanoflann_kdtree.h>

#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>

#include <gtest/gtest.h>

#include <random>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

Cloud::Ptr
wavyPatch (std::size_t n, unsigned seed)
{
  Cloud::Ptr cloud (new Cloud);
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-1.0f, 1.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const float x = u (rng), y = u (rng);
    cloud->push_back (Point (x, y, 0.1f * std::sin (3 * x) * std::cos (2 * y)));
  }
  return cloud;
}
} // namespace

TEST (NanoflannKdTree, MatchesPclKdTree)
{
  const auto cloud = wavyPatch (5000, 11);
  pcl_ext::search::NanoflannKdTree<Point> ours;
  pcl::search::KdTree<Point> flann;
  ours.setInputCloud (cloud);
  flann.setInputCloud (cloud);
  EXPECT_EQ (ours.getName(), "NanoflannKdTree");
  pcl::Indices a, b;
  std::vector<float> da, db;
  for (std::size_t i = 0; i < cloud->size(); i += 7) {
    ASSERT_EQ (ours.nearestKSearch ((*cloud)[i], 10, a, da), 10);
    ASSERT_EQ (flann.nearestKSearch ((*cloud)[i], 10, b, db), 10);
    for (int j = 0; j < 10; ++j)
      EXPECT_NEAR (da[j], db[j], 1e-6f);
    ours.radiusSearch ((*cloud)[i], 0.05, a, da);
    flann.radiusSearch ((*cloud)[i], 0.05, b, db);
    std::sort (b.begin(), b.end());
    pcl::Indices sorted_a = a;
    std::sort (sorted_a.begin(), sorted_a.end());
    EXPECT_EQ (sorted_a, b);
    EXPECT_TRUE (std::is_sorted (da.begin(), da.end()));
  }
  // By index, through the base class.
  ASSERT_EQ (ours.nearestKSearch (3, 1, a, da), 1);
  EXPECT_EQ (a[0], 3);
}

TEST (NanoflannKdTree, DropsIntoStockNormalEstimation)
{
  const auto cloud = wavyPatch (3000, 12);
  pcl::NormalEstimation<Point, pcl::Normal> ne;
  ne.setInputCloud (cloud);
  ne.setKSearch (15);
  pcl::PointCloud<pcl::Normal> with_ours, with_flann;
  ne.setSearchMethod (pcl_ext::search::NanoflannKdTree<Point>::Ptr (
      new pcl_ext::search::NanoflannKdTree<Point>));
  ne.compute (with_ours);
  ne.setSearchMethod (pcl::search::KdTree<Point>::Ptr (new pcl::search::KdTree<Point>));
  ne.compute (with_flann);
  ASSERT_EQ (with_ours.size(), with_flann.size());
  for (std::size_t i = 0; i < with_ours.size(); ++i) {
    const float dot =
        with_ours[i].getNormalVector3fMap().dot (with_flann[i].getNormalVector3fMap());
    EXPECT_NEAR (std::abs (dot), 1.0f, 1e-4f);
  }
}

TEST (NanoflannKdTree, IndicesNonFiniteAndEmpty)
{
  auto cloud = wavyPatch (100, 13);
  (*cloud)[0].x = NAN;
  cloud->is_dense = true; // wrongly claimed: must still be safe
  pcl::IndicesPtr indices (new pcl::Indices{0, 1, 2, 3, 50});
  pcl_ext::search::NanoflannKdTree<Point> tree;
  tree.setInputCloud (cloud, indices);
  pcl::Indices nn;
  std::vector<float> d2;
  EXPECT_EQ (tree.nearestKSearch ((*cloud)[50], 10, nn, d2),
             4); // 4 finite indexed points
  for (const auto j : nn)
    EXPECT_NE (j, 0);
  EXPECT_EQ (tree.nearestKSearch (Point (NAN, 0, 0), 3, nn, d2), 0);
  EXPECT_TRUE (nn.empty());
  EXPECT_EQ (tree.nearestKSearch ((*cloud)[50], 0, nn, d2), 0);
  EXPECT_EQ (tree.radiusSearch ((*cloud)[50], -1.0, nn, d2), 0);

  tree.setInputCloud (Cloud::Ptr (new Cloud));
  EXPECT_EQ (tree.nearestKSearch (Point (0, 0, 0), 3, nn, d2), 0);
  EXPECT_EQ (tree.radiusSearch (Point (0, 0, 0), 1.0, nn, d2), 0);
}
