/*
 * Tests of NeighbourhoodFeature, the base every pcl_ext feature estimator shares: its
 * own search or shared neighbourhoods, the per-row loop over dense and non-dense
 * clouds, the normals check of FeatureFromNormals-style estimators, threads.
 */
#include <pcl_ext/features/neighbourhood_feature.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Output = pcl::PointCloud<pcl::Intensity>;

/** A feature as small as they come: the number of neighbours of each point (its row's
 * size), valid from three on; NaN for a non-finite point. */
class NeighbourCount
: public pcl_ext::NeighbourhoodFeature<pcl::Feature<Point, pcl::Intensity>, Point> {
public:
  NeighbourCount() { feature_name_ = "NeighbourCount"; }

protected:
  void
  computeFeature (Output& output) override
  {
    output.is_dense = computeRows (
        output,
        16,
        [this] (std::size_t r, pcl::Intensity& out) {
          out.intensity = static_cast<float> ((*nb_)[r].size());
          return (*nb_)[r].size() >= 3;
        },
        [] (pcl::Intensity& out) {
          out.intensity = std::numeric_limits<float>::quiet_NaN();
        });
  }
};

/** The same count, from an estimator that takes normals as PCL's FeatureFromNormals
 * does. */
class NeighbourCountWithNormals
: public pcl_ext::NeighbourhoodFeatureFromNormals<Point, pcl::Normal, pcl::Intensity> {
public:
  NeighbourCountWithNormals() { feature_name_ = "NeighbourCountWithNormals"; }

protected:
  void
  computeFeature (Output& output) override
  {
    for (std::size_t r = 0; r < output.size(); ++r)
      output[r].intensity = static_cast<float> ((*nb_)[r].size());
  }
};

/** An n x n grid at z = 0; point i * n + j at (0.1 i, 0.1 j, 0). */
Cloud::Ptr
grid (int n)
{
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      cloud->push_back (Point (0.1f * i, 0.1f * j, 0.f));
  return cloud;
}
} // namespace

TEST (NeighbourhoodFeature, OwnSearchWithKOrARadiusAndIndices)
{
  const auto cloud = grid (10);
  NeighbourCount est;
  EXPECT_EQ (est.getNumberOfThreads(), 0u);
  EXPECT_FALSE (est.getNeighbourhoods());
  est.setInputCloud (cloud);
  est.setKSearch (5);
  Output out;
  est.compute (out);
  ASSERT_EQ (out.size(), 100u);
  EXPECT_TRUE (out.is_dense);
  for (const auto& p : out)
    EXPECT_EQ (p.intensity, 5.f);
  // A radius just over the spacing: 5 inside, 4 on a side, 3 in a corner. As in
  // pcl::Feature, k must be cleared: both set are refused.
  est.setRadiusSearch (0.1001);
  est.compute (out);
  EXPECT_TRUE (out.empty());
  est.setKSearch (0);
  est.compute (out);
  ASSERT_EQ (out.size(), 100u);
  EXPECT_EQ (out[55].intensity, 5.f);
  EXPECT_EQ (out[5].intensity, 4.f);
  EXPECT_EQ (out[0].intensity, 3.f);
  // One output per index.
  est.setIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{0, 55}));
  est.compute (out);
  ASSERT_EQ (out.size(), 2u);
  EXPECT_EQ (out[0].intensity, 3.f);
  EXPECT_EQ (out[1].intensity, 5.f);
}

TEST (NeighbourhoodFeature, SharedNeighbourhoodsReplaceKAndRadius)
{
  const auto cloud = grid (10);
  auto shared = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  shared->setInputCloud (cloud);
  shared->setKSearch (7);
  ASSERT_TRUE (shared->compute());
  NeighbourCount est;
  est.setNeighbourhoods (shared);
  EXPECT_EQ (est.getNeighbourhoods().get(), shared.get());
  est.setInputCloud (cloud);
  est.setKSearch (3);
  Output out;
  est.compute (out);
  ASSERT_EQ (out.size(), 100u);
  for (const auto& p : out)
    EXPECT_EQ (p.intensity, 7.f);
  // Neither k nor a radius: the shared rows are enough.
  NeighbourCount no_k;
  no_k.setNeighbourhoods (shared);
  no_k.setInputCloud (cloud);
  no_k.compute (out);
  ASSERT_EQ (out.size(), 100u);
  EXPECT_EQ (out[0].intensity, 7.f);
}

TEST (NeighbourhoodFeature, NonFinitePointsAreInvalidWhetherOrNotTheCloudSaysDense)
{
  auto cloud = grid (6);
  (*cloud)[14].x = std::numeric_limits<float>::quiet_NaN();
  cloud->is_dense = false;
  NeighbourCount est;
  est.setInputCloud (cloud);
  est.setKSearch (4);
  Output out;
  est.compute (out);
  ASSERT_EQ (out.size(), 36u);
  EXPECT_FALSE (out.is_dense);
  EXPECT_TRUE (std::isnan (out[14].intensity)); // the non-dense loop skips it
  EXPECT_EQ (out[13].intensity, 4.f);
  // A cloud claiming to be dense: the point has an empty row, which fails later.
  cloud->is_dense = true;
  est.compute (out);
  ASSERT_EQ (out.size(), 36u);
  EXPECT_FALSE (out.is_dense);
  EXPECT_EQ (out[14].intensity, 0.f);
  EXPECT_EQ (out[13].intensity, 4.f);
}

TEST (NeighbourhoodFeature, RefusalsGiveEmptyOutput)
{
  const auto cloud = grid (5);
  Output out;
  out.resize (3);
  NeighbourCount est;
  est.compute (out); // no input
  EXPECT_TRUE (out.empty());
  est.setInputCloud (Cloud::Ptr (new Cloud));
  est.setKSearch (3);
  out.resize (3);
  est.compute (out); // an empty cloud
  EXPECT_TRUE (out.empty());
  est.setInputCloud (cloud);
  est.setSearchSurface (grid (6)); // another search surface
  est.compute (out);
  EXPECT_TRUE (out.empty());
  est.setSearchSurface (cloud); // the input itself is fine
  est.compute (out);
  EXPECT_EQ (out.size(), 25u);
  est.setKSearch (0); // neither k nor a radius
  est.compute (out);
  EXPECT_TRUE (out.empty());
}

TEST (NeighbourhoodFeature, NormalsOnePerInputPoint)
{
  const auto cloud = grid (5);
  NeighbourCountWithNormals est;
  est.setInputCloud (cloud);
  est.setKSearch (4);
  Output out;
  est.compute (out); // no normals
  EXPECT_TRUE (out.empty());
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  normals->resize (24);
  est.setInputNormals (normals);
  est.compute (out); // one short
  EXPECT_TRUE (out.empty());
  normals->resize (25);
  est.setIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{6, 7}));
  est.compute (out); // indexed like the input, not like the indices
  ASSERT_EQ (out.size(), 2u);
  EXPECT_EQ (out[0].intensity, 4.f);
}

TEST (NeighbourhoodFeature, SameRowsForAnyThreadCount)
{
  const auto cloud = grid (20);
  NeighbourCount one, two;
  for (NeighbourCount* est : {&one, &two}) {
    est->setInputCloud (cloud);
    est->setRadiusSearch (0.25);
  }
  one.setNumberOfThreads (1);
  two.setNumberOfThreads (2);
  EXPECT_EQ (two.getNumberOfThreads(), 2u);
  Output a, b;
  one.compute (a);
  two.compute (b);
  ASSERT_EQ (a.size(), 400u);
  ASSERT_EQ (b.size(), 400u);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ (a[i].intensity, b[i].intensity) << i;
  // An interior point: the 21 grid points within 2.5 spacings.
  EXPECT_EQ (a[10 * 20 + 10].intensity, 21.f);
}
