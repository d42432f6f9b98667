/*
 * Tests of Belton & Lichti's per-neighbourhood kernels (local_variance.h): the chi-squared
 * quantile and the centroid offset statistic (eq. 6-8).
 */
#include <pcl_ext/features/local_variance.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

TEST (ChiSquaredBoundaryEstimation, QuantileIsTheChiSquaredTwoDegreesOfFreedom)
{
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.95), 5.991, 1e-3);
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.99), 9.210, 1e-3);
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.5), 1.386, 1e-3);
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (1.0)));
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (0.0)));
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (-0.5)));
}

TEST (ChiSquaredBoundaryEstimation, StatisticOfAHalfDiscMatchesTheClosedForm)
{
  // Index point at the middle of the diameter of a dense uniform half disc: centroid offset
  // 4 r / (3 pi), variance across r^2 / 4 - (4 r / (3 pi))^2: statistic 2.57 (unscaled).
  Cloud cloud;
  cloud.push_back (pcl::PointXYZ (0, 0, 0));
  const int n = 400;
  for (int i = -n; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      if (i * i + j * j <= n * n && (i != 0 || j != 0))
        cloud.push_back (pcl::PointXYZ (i / float (n), j / float (n), 0));
  pcl::Indices all (cloud.size ());
  for (std::size_t i = 0; i < all.size (); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  pcl_ext::LocalCovariance local;
  ASSERT_TRUE (pcl_ext::computeNeighbourhoodCovariance (cloud, all.begin (), all.end (), local));
  const double c = 4.0 / (3.0 * M_PI);
  EXPECT_NEAR (pcl_ext::centroidOffsetStatistic (Eigen::Vector3d::Zero (), local, false),
               c * c / (0.25 - c * c), 0.02);  // 0.5% of a 400-step grid's discretisation
}
