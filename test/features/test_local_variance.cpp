/*
 * Tests of Belton & Lichti's per-neighbourhood kernels (local_variance.h): the
 * tangent-plane test, the neighbourhood covariance, the chi-squared quantile and the
 * centroid offset statistic (eq. 6-8), the projected normals (section 5), the curvature
 * variance (eq. 5).
 */
#include <pcl_ext/features/local_variance.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

TEST (ChiSquaredStatistic, QuantileIsTheChiSquaredTwoDegreesOfFreedom)
{
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.95), 5.991, 1e-3);
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.99), 9.210, 1e-3);
  EXPECT_NEAR (pcl_ext::chiSquaredQuantile2 (0.5), 1.386, 1e-3);
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (1.0)));
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (0.0)));
  EXPECT_TRUE (std::isnan (pcl_ext::chiSquaredQuantile2 (-0.5)));
}

TEST (ChiSquaredStatistic, StatisticOfAHalfDiscMatchesTheClosedForm)
{
  // Index point at the middle of the diameter of a dense uniform half disc: centroid
  // offset 4 r / (3 pi), variance across r^2 / 4 - (4 r / (3 pi))^2: statistic 2.57
  // (unscaled).
  Cloud cloud;
  cloud.push_back (pcl::PointXYZ (0, 0, 0));
  const int n = 400;
  for (int i = -n; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      if (i * i + j * j <= n * n && (i != 0 || j != 0))
        cloud.push_back (pcl::PointXYZ (i / float (n), j / float (n), 0));
  pcl::Indices all (cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  pcl_ext::LocalCovariance local;
  ASSERT_TRUE (
      pcl_ext::computeNeighbourhoodCovariance (cloud, all.begin(), all.end(), local));
  const double c = 4.0 / (3.0 * M_PI);
  EXPECT_NEAR (pcl_ext::centroidOffsetStatistic (Eigen::Vector3d::Zero(), local, false),
               c * c / (0.25 - c * c),
               0.02); // 0.5% of a 400-step grid's discretisation
}

TEST (LocalVariance, TangentPlaneNeedsThreePointsAndTwoSpreadDirections)
{
  EXPECT_TRUE (pcl_ext::hasTangentPlane (Eigen::Vector3d (0.0, 1.0, 1.0), 3));
  EXPECT_TRUE (pcl_ext::hasTangentPlane (Eigen::Vector3d (1e-9, 2e-8, 1.0), 10));
  EXPECT_FALSE (
      pcl_ext::hasTangentPlane (Eigen::Vector3d (0.0, 1.0, 1.0), 2)); // too few
  EXPECT_FALSE (
      pcl_ext::hasTangentPlane (Eigen::Vector3d (0.0, 0.0, 1.0), 10)); // a line
  EXPECT_FALSE (
      pcl_ext::hasTangentPlane (Eigen::Vector3d (0.0, 1e-9, 1.0), 10));  // nearly
  EXPECT_FALSE (pcl_ext::hasTangentPlane (Eigen::Vector3d::Zero(), 10)); // one point
  EXPECT_FALSE (pcl_ext::hasTangentPlane (
      Eigen::Vector3d (0.0, std::numeric_limits<double>::quiet_NaN(), 1.0), 10));
}

TEST (LocalVariance, NeighbourhoodCovarianceOfAPlaneAndALine)
{
  // A 3 x 4 grid in the plane z = 2, spacing 1, around (1, 1.5, 2): the population
  // variance is 2/3 along x, 5/4 along y, 0 across the plane.
  Cloud cloud;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      cloud.push_back (
          pcl::PointXYZ (static_cast<float> (i), static_cast<float> (j), 2.f));
  cloud.push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f));
  pcl::Indices all (cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  pcl_ext::LocalCovariance local;
  ASSERT_TRUE (
      pcl_ext::computeNeighbourhoodCovariance (cloud, all.begin(), all.end(), local));
  EXPECT_EQ (local.size, 12u); // the NaN point is left out
  EXPECT_NEAR ((local.centroid - Eigen::Vector3d (1.0, 1.5, 2.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR (local.eigen.values[0], 0.0, 1e-12);
  EXPECT_NEAR (local.eigen.values[1], 2.0 / 3.0, 1e-12);
  EXPECT_NEAR (local.eigen.values[2], 5.0 / 4.0, 1e-12);
  EXPECT_NEAR (std::abs (local.eigen.normal().z()), 1.0, 1e-12);
  EXPECT_NEAR (std::abs (local.eigen.vectors.col (2).y()), 1.0, 1e-12);
  // The first three points of a row are collinear: no tangent plane; two points are too
  // few.
  EXPECT_FALSE (pcl_ext::computeNeighbourhoodCovariance (
      cloud, all.begin(), all.begin() + 3, local));
  EXPECT_EQ (local.size, 3u);
  EXPECT_FALSE (pcl_ext::computeNeighbourhoodCovariance (
      cloud, all.begin(), all.begin() + 2, local));
}

TEST (LocalVariance, CentroidOffsetStatisticScalesAndNoise)
{
  // Tangent directions y (l1 = 1) and z (l2 = 4) around the origin, n = 10 points; the
  // index point is 2 along each: u^2 / l1 + v^2 / l2 = 4 + 1 = 5, times n = 50. With
  // the noise variance 0.5: 4 / (1 / 10 + 0.5) + 4 / (4 / 10 + 0.5) = 100 / 9.
  pcl_ext::LocalCovariance local;
  local.eigen.values = Eigen::Vector3d (0.0, 1.0, 4.0);
  local.eigen.vectors = Eigen::Matrix3d::Identity();
  local.size = 10;
  const Eigen::Vector3d p (7.0, 2.0, 2.0); // the offset along the normal does not count
  EXPECT_NEAR (pcl_ext::centroidOffsetStatistic (p, local), 50.0, 1e-12);
  EXPECT_NEAR (pcl_ext::centroidOffsetStatistic (p, local, false), 5.0, 1e-12);
  EXPECT_NEAR (
      pcl_ext::centroidOffsetStatistic (p, local, true, 0.5), 100.0 / 9.0, 1e-12);
  EXPECT_NEAR (
      pcl_ext::centroidOffsetStatistic (Eigen::Vector3d (3.0, 0.0, 0.0), local),
      0.0,
      1e-12);
}

TEST (LocalVariance, ProjectedNormalsTurnAcrossACylinderAxis)
{
  // Neighbour normals of a cylinder along y seen at a point with normal z: they turn
  // about y, in the x-z plane, so the normal changes most along x and not at all along
  // y. Every other normal is flipped: the result does not depend on the orientation.
  pcl_ext::ProjectedNormalAccumulator acc (Eigen::Vector3d (0.0, 0.0, 2.0));
  double mean_sin2 = 0.0;
  const int m = 9;
  for (int k = 0; k < m; ++k) {
    const double a = -0.4 + 0.1 * k;
    const double sign = k % 2 ? -1.0 : 1.0;
    acc.add (sign * Eigen::Vector3d (std::sin (a), 0.0, std::cos (a)));
    mean_sin2 += std::sin (a) * std::sin (a) / m;
  }
  acc.add (Eigen::Vector3d::Zero()); // skipped
  acc.add (
      Eigen::Vector3d (std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0)); // skipped
  EXPECT_EQ (acc.count(), static_cast<std::size_t> (m));
  pcl_ext::ProjectedNormalDirections d;
  ASSERT_TRUE (acc.compute (d));
  EXPECT_NEAR (std::abs (d.max_direction.x()), 1.0, 1e-12);
  EXPECT_NEAR (std::abs (d.min_direction.y()), 1.0, 1e-12);
  EXPECT_NEAR (d.max_change, mean_sin2, 1e-12);
  EXPECT_NEAR (d.min_change, 0.0, 1e-12);
  // Fewer than two normals: no directions.
  pcl_ext::ProjectedNormalAccumulator one (Eigen::Vector3d::UnitZ());
  one.add (Eigen::Vector3d::UnitX());
  EXPECT_FALSE (one.compute (d));
}

TEST (LocalVariance, CurvatureVarianceIsThePopulationVarianceOfTheFiniteValues)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {1.0, nan, 2.0, 3.0, 4.0};
  const std::vector<int> all = {0, 1, 2, 3, 4};
  const auto of = [&values] (int i) { return values[static_cast<std::size_t> (i)]; };
  std::size_t count = 0;
  EXPECT_NEAR (
      pcl_ext::curvatureVariance (all.begin(), all.end(), of, count), 1.25, 1e-12);
  EXPECT_EQ (count, 4u);
  // Shifted sums: a large common offset does not cancel the variance away.
  const auto offset = [&values] (int i) {
    return 1e8 + values[static_cast<std::size_t> (i)];
  };
  EXPECT_NEAR (
      pcl_ext::curvatureVariance (all.begin(), all.end(), offset, count), 1.25, 1e-6);
  // Fewer finite values than asked for: NaN.
  EXPECT_TRUE (std::isnan (
      pcl_ext::curvatureVariance (all.begin(), all.begin() + 3, of, count)));
  EXPECT_EQ (count, 2u);
  EXPECT_NEAR (pcl_ext::curvatureVariance (all.begin(), all.begin() + 3, of, count, 2),
               0.25,
               1e-12);
}
