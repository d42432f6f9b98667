/*
 * CovarianceFeatureEstimation: eigenvalues and normals against closed-form clouds,
 * shared neighbourhoods, indices, bad input.
 */
#include "analytic_clouds.h"

#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/features/covariance_features.h>

#include <gtest/gtest.h>

#include <cmath>

using pcl_ext::test::Cloud;
using Features = pcl::PointCloud<pcl_ext::CovarianceFeatures>;

namespace {
Features
estimate (const Cloud::ConstPtr& cloud, int k)
{
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setKSearch (k);
  Features out;
  est.compute (out);
  return out;
}
} // namespace

TEST (CovarianceFeatureEstimation, PlaneHasVerticalNormalAndZeroSurfaceVariance)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.02, 0.5);
  const Features f = estimate (plane.cloud, 20);
  ASSERT_EQ (f.size(), plane.cloud->size());
  EXPECT_TRUE (f.is_dense);
  for (const auto& p : f) {
    // The viewpoint (origin) lies in the plane z = 0: either sign is towards it; |n_z|
    // = 1.
    EXPECT_NEAR (std::abs (p.normal_z), 1.0, 1e-5);
    EXPECT_NEAR (p.lambda0, 0.0, 1e-9);
    EXPECT_NEAR (p.surface_variance, 0.0, 1e-6);
    EXPECT_GT (p.lambda1, 0.0f);
    EXPECT_LE (p.lambda1, p.lambda2);
  }
}

TEST (CovarianceFeatureEstimation, EigenvaluesOfASquareGridAreClosedForm)
{
  // A 5 x 5 grid of spacing 1 with all 25 points as neighbours: var(x) = var(y) = 2.
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      cloud->push_back (pcl::PointXYZ (i, j, 3.0f));
  const Features f = estimate (cloud, 25);
  ASSERT_EQ (f.size(), 25u);
  for (const auto& p : f) {
    EXPECT_NEAR (p.lambda0, 0.0, 1e-6);
    EXPECT_NEAR (p.lambda1, 2.0, 1e-5);
    EXPECT_NEAR (p.lambda2, 2.0, 1e-5);
    // Flipped towards the origin, below the plane z = 3.
    EXPECT_NEAR (p.normal_z, -1.0, 1e-6);
    EXPECT_NEAR (p.planarity, 1.0, 1e-5);
    EXPECT_NEAR (p.verticality, 0.0, 1e-5);
  }
}

TEST (CovarianceFeatureEstimation, NoisyPlaneSmallestEigenvalueIsTheNoiseVariance)
{
  const double sigma = 0.002;
  const auto plane = pcl_ext::test::makePlane (2.0, 0.01, 0.3, sigma);
  const Features f = estimate (plane.cloud, 50);
  double mean_l0 = 0;
  for (const auto& p : f)
    mean_l0 += p.lambda0;
  mean_l0 /= static_cast<double> (f.size());
  // l0 is the smallest of three variances of 50 samples: a little below sigma^2.
  EXPECT_GT (mean_l0, 0.8 * sigma * sigma);
  EXPECT_LT (mean_l0, 1.05 * sigma * sigma);
}

TEST (CovarianceFeatureEstimation, SharedNeighbourhoodsGiveTheSameResultAndOverrideK)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.05, 0.001);
  auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<pcl::PointXYZ>>();
  nb->setInputCloud (cube.cloud);
  nb->setKSearch (30);
  ASSERT_TRUE (nb->compute());

  const Features own = estimate (cube.cloud, 30);
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cube.cloud);
  est.setNeighbourhoods (nb);
  Features shared;
  est.compute (shared); // no k or radius: the shared neighbourhoods decide
  ASSERT_EQ (shared.size(), own.size());
  for (std::size_t i = 0; i < own.size(); ++i) {
    EXPECT_FLOAT_EQ (shared[i].lambda0, own[i].lambda0);
    EXPECT_FLOAT_EQ (shared[i].surface_variance, own[i].surface_variance);
  }
}

TEST (CovarianceFeatureEstimation, IndicesGiveOneOutputPerIndex)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  auto indices = pcl::make_shared<pcl::Indices> (pcl::Indices{3, 100, 7});
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (plane.cloud);
  est.setIndices (indices);
  est.setKSearch (10);
  Features out;
  est.compute (out);
  ASSERT_EQ (out.size(), 3u);
  for (const auto& p : out)
    EXPECT_NEAR (std::abs (p.normal_z), 1.0, 1e-5);
}

TEST (CovarianceFeatureEstimationBadInput, EmptyCloudGivesEmptyOutput)
{
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (pcl::make_shared<Cloud>());
  est.setKSearch (10);
  Features out;
  out.resize (4);
  est.compute (out);
  EXPECT_TRUE (out.empty());
}

TEST (CovarianceFeatureEstimationBadInput, KLargerThanTheCloudGivesEmptyOutput)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.25); // 25 points
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (plane.cloud);
  est.setKSearch (26);
  Features out;
  est.compute (out);
  EXPECT_TRUE (out.empty());
}

TEST (CovarianceFeatureEstimationBadInput, KAndRadiusBothOrNeitherGiveEmptyOutput)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.1);
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (plane.cloud);
  Features out;
  est.compute (out);
  EXPECT_TRUE (out.empty());
  est.setKSearch (10);
  est.setRadiusSearch (0.2);
  est.compute (out);
  EXPECT_TRUE (out.empty());
}

TEST (CovarianceFeatureEstimationBadInput, NonFinitePointsGetNaNInANonDenseCloud)
{
  auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  (*plane.cloud)[10].x = std::numeric_limits<float>::quiet_NaN();
  (*plane.cloud)[20].y = std::numeric_limits<float>::infinity();
  plane.cloud->is_dense = false;
  const Features f = estimate (plane.cloud, 10);
  ASSERT_EQ (f.size(), plane.cloud->size());
  EXPECT_FALSE (f.is_dense);
  EXPECT_TRUE (std::isnan (f[10].normal_x));
  EXPECT_TRUE (std::isnan (f[20].surface_variance));
  EXPECT_NEAR (std::abs (f[11].normal_z), 1.0, 1e-5);
}

TEST (CovarianceFeatureEstimationBadInput,
      NonFinitePointsInACloudClaimingDenseDoNotCrash)
{
  auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  (*plane.cloud)[10].z = std::numeric_limits<float>::quiet_NaN();
  plane.cloud->is_dense = true; // wrong, as happens with hand-made clouds
  const Features f = estimate (plane.cloud, 10);
  ASSERT_EQ (f.size(), plane.cloud->size());
  EXPECT_TRUE (std::isnan (f[10].normal_x));
  EXPECT_FALSE (f.is_dense);
}

TEST (CovarianceFeatureEstimationBadInput, DuplicateAndCollinearPointsGetNaN)
{
  Cloud::Ptr duplicates (new Cloud);
  for (int i = 0; i < 20; ++i)
    duplicates->push_back (pcl::PointXYZ (1.f, 2.f, 3.f));
  Features f = estimate (duplicates, 10);
  ASSERT_EQ (f.size(), 20u);
  EXPECT_FALSE (f.is_dense);
  for (const auto& p : f)
    EXPECT_TRUE (std::isnan (p.normal_x) && std::isnan (p.lambda0));

  Cloud::Ptr line (new Cloud);
  for (int i = 0; i < 20; ++i)
    line->push_back (pcl::PointXYZ (0.1f * i, 0.2f * i, 0.3f * i));
  f = estimate (line, 10);
  ASSERT_EQ (f.size(), 20u);
  for (const auto& p : f)
    EXPECT_TRUE (std::isnan (p.normal_x));
}

TEST (CovarianceFeatureEstimationBadInput, SearchSurfaceOtherThanInputIsRefused)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.1);
  const auto other = pcl_ext::test::makePlane (1.0, 0.05);
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (plane.cloud);
  est.setSearchSurface (other.cloud);
  est.setKSearch (5);
  Features out;
  est.compute (out);
  EXPECT_TRUE (out.empty());
}
