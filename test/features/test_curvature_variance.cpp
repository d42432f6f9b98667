/*
 * CurvatureVarianceEstimation (eq. 5): near zero on smooth surfaces, planar or curved,
 * large at creases; curvatures from pcl::Normal or pcl_ext::CovarianceFeatures; bad
 * input.
 */
#include "analytic_clouds.h"

#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/features/curvature_variance.h>

#include <pcl/features/normal_3d.h>

#include <gtest/gtest.h>

using pcl_ext::test::Cloud;
using Variances = pcl::PointCloud<pcl_ext::CurvatureVariance>;

namespace {
pcl::PointCloud<pcl_ext::CovarianceFeatures>::Ptr
covariance (const Cloud::ConstPtr& cloud, int k)
{
  pcl::PointCloud<pcl_ext::CovarianceFeatures>::Ptr out (
      new pcl::PointCloud<pcl_ext::CovarianceFeatures>);
  pcl_ext::CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setKSearch (k);
  est.compute (*out);
  return out;
}

template <typename NormalT>
Variances
variances (const Cloud::ConstPtr& cloud,
           const typename pcl::PointCloud<NormalT>::ConstPtr& n,
           int k)
{
  pcl_ext::CurvatureVarianceEstimation<pcl::PointXYZ, NormalT> est;
  est.setInputCloud (cloud);
  est.setInputNormals (n);
  est.setKSearch (k);
  Variances out;
  est.compute (out);
  return out;
}
} // namespace

TEST (CurvatureVarianceEstimation, CubeCreasesHaveHighVarianceFacesNone)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02);
  const int k = 50;
  const auto cov = covariance (cube.cloud, k);
  const Variances v = variances<pcl_ext::CovarianceFeatures> (cube.cloud, cov, k);
  ASSERT_EQ (v.size(), cube.cloud->size());
  // k = 50 on a grid of spacing s reaches r = s sqrt(50 / pi) ~ 4 s: beyond 2 r from
  // any crease every neighbour is flat, so eq. 5 is exactly 0; within one spacing of a
  // crease the neighbourhoods mix flat and bent ones.
  const double r = cube.spacing * std::sqrt (k / M_PI);
  std::size_t near = 0, near_high = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (cube.crease_distance[i] > 2.2 * r)
      EXPECT_LT (v[i].curvature_variance, 1e-8) << i;
    if (cube.crease_distance[i] <= cube.spacing) {
      ++near;
      near_high += v[i].curvature_variance > 1e-4 ? 1 : 0; // the paper's tolerance
    }
  }
  ASSERT_GT (near, 100u);
  EXPECT_EQ (near_high, near);
}

TEST (CurvatureVarianceEstimation, CylinderIsCurvedButItsVarianceIsTiny)
{
  // Radius 10 spacings: kappa ~ r^2 / (32 R^2) ~ 5e-3, well above a plane's, but
  // constant.
  const auto cyl = pcl_ext::test::makeCylinder (0.1, 0.6, 0.01);
  const int k = 50;
  const auto cov = covariance (cyl.cloud, k);
  const Variances v = variances<pcl_ext::CovarianceFeatures> (cyl.cloud, cov, k);
  const double r = cyl.spacing * std::sqrt (k / M_PI);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (cyl.border_distance[i] > 2.2 * r) {
      EXPECT_GT ((*cov)[i].surface_variance, 1e-3f);
      EXPECT_LT (v[i].curvature_variance, 1e-6f);
    }
}

TEST (CurvatureVarianceEstimation, CurvatureFieldOfPclNormalsIsUsed)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.05, 0.001);
  const int k = 30;
  const auto cov = covariance (cube.cloud, k);
  // The same kappa through pcl::Normal::curvature gives exactly the same variances.
  pcl::PointCloud<pcl::Normal>::Ptr copied (new pcl::PointCloud<pcl::Normal>);
  for (const auto& f : *cov)
    copied->push_back (
        pcl::Normal (f.normal_x, f.normal_y, f.normal_z, f.surface_variance));
  const Variances ours = variances<pcl_ext::CovarianceFeatures> (cube.cloud, cov, k);
  const Variances through_normal = variances<pcl::Normal> (cube.cloud, copied, k);
  ASSERT_EQ (through_normal.size(), ours.size());
  for (std::size_t i = 0; i < ours.size(); ++i)
    EXPECT_EQ (through_normal[i].curvature_variance, ours[i].curvature_variance);

  // pcl::NormalEstimation's curvature is eq. 4 too (float, FLANN's choice among
  // equidistant grid neighbours): the paper's 1e-4 test gives the same verdict almost
  // everywhere.
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  ne.setInputCloud (cube.cloud);
  ne.setKSearch (k);
  ne.compute (*normals);
  const Variances from_pcl = variances<pcl::Normal> (cube.cloud, normals, k);
  std::size_t agree = 0;
  for (std::size_t i = 0; i < ours.size(); ++i)
    agree += (from_pcl[i].curvature_variance > 1e-4f) ==
             (ours[i].curvature_variance > 1e-4f);
  EXPECT_GE (agree, static_cast<std::size_t> (0.99 * ours.size()));
}

TEST (CurvatureVarianceEstimationBadInput, MissingOrWrongSizedNormalsGiveEmptyOutput)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.1);
  pcl_ext::CurvatureVarianceEstimation<pcl::PointXYZ, pcl::Normal> est;
  est.setInputCloud (plane.cloud);
  est.setKSearch (10);
  Variances out;
  est.compute (out);
  EXPECT_TRUE (out.empty());
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  normals->resize (plane.cloud->size() - 1);
  est.setInputNormals (normals);
  est.compute (out);
  EXPECT_TRUE (out.empty());
}

TEST (CurvatureVarianceEstimationBadInput, NaNCurvaturesAndPointsAreSkipped)
{
  auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  normals->resize (plane.cloud->size());
  for (auto& n : *normals)
    n.curvature = 0.01f;
  (*normals)[5].curvature = std::numeric_limits<float>::quiet_NaN();
  (*plane.cloud)[7].x = std::numeric_limits<float>::quiet_NaN();
  plane.cloud->is_dense = false;
  const Variances v = variances<pcl::Normal> (plane.cloud, normals, 10);
  ASSERT_EQ (v.size(), plane.cloud->size());
  EXPECT_FALSE (v.is_dense);
  EXPECT_TRUE (std::isnan (v[7].curvature_variance));
  EXPECT_FLOAT_EQ (v[5].curvature_variance,
                   0.0f); // its neighbours' curvatures are all 0.01
  EXPECT_FLOAT_EQ (v[100].curvature_variance, 0.0f);
}

TEST (CurvatureVarianceEstimationBadInput, EmptyCloudAndKTooLargeGiveEmptyOutput)
{
  pcl_ext::CurvatureVarianceEstimation<pcl::PointXYZ, pcl::Normal> est;
  est.setInputCloud (pcl::make_shared<Cloud>());
  est.setInputNormals (pcl::make_shared<pcl::PointCloud<pcl::Normal>>());
  est.setKSearch (5);
  Variances out;
  est.compute (out);
  EXPECT_TRUE (out.empty());

  const auto plane = pcl_ext::test::makePlane (1.0, 0.5); // 9 points
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  normals->resize (plane.cloud->size());
  est.setInputCloud (plane.cloud);
  est.setInputNormals (normals);
  est.setKSearch (10);
  est.compute (out);
  EXPECT_TRUE (out.empty());
}
