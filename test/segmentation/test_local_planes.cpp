/*
 * Plane fits (Belton & Lichti 2006, sections 3 and 4): the least-squares plane of a
 * segment, the local planes of neighbourhoods and the intersection of two of them.
 */
#include <pcl_ext/segmentation/local_planes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
} // namespace

TEST (FitSegmentPlane, RecoversATiltedPlaneFarFromTheOrigin)
{
  // z = 0.1 (x - x0) - 0.2 (y - y0) + 3 with 2 mm noise in z, over 40 m x 2.5 m at
  // x0 = 6,000,000 m, y0 = 500,000 m. Floats there are 0.5 m (x) and 1/32 m (y) apart,
  // so the grid is made of representable coordinates: the fit must lose nothing beyond
  // the noise.
  const Eigen::Vector3d n_true = Eigen::Vector3d (-0.1, 0.2, 1.0).normalized();
  std::mt19937 rng (3);
  std::normal_distribution<double> noise (0.0, 0.002);
  Cloud cloud;
  pcl::Indices indices;
  const double x0 = 6000000.0, y0 = 500000.0;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j) {
      const double x = x0 + 0.5 * i, y = y0 + 0.03125 * j;
      const double z = 0.1 * (x - x0) - 0.2 * (y - y0) + 3.0 + noise (rng);
      cloud.push_back (Point (
          static_cast<float> (x), static_cast<float> (y), static_cast<float> (z)));
      indices.push_back (static_cast<pcl::index_t> (cloud.size() - 1));
    }
  const auto plane =
      pcl_ext::fitSegmentPlane (cloud, indices, Eigen::Vector3d (x0, y0, 100.0));
  ASSERT_TRUE (plane.isValid());
  EXPECT_EQ (plane.size, cloud.size());
  EXPECT_GT (plane.normal.dot (n_true),
             1.0 - 1e-6); // and turned up, towards the viewpoint
  EXPECT_NEAR (plane.normal.dot (plane.centroid) + plane.d, 0.0, 1e-6);
  // A z offset dz is a distance dz * n_z from the plane.
  EXPECT_NEAR (plane.rms, 0.002 * n_true.z(), 0.0003);
  EXPECT_GT (plane.max_residual, 2.5 * plane.rms);
  EXPECT_LT (plane.max_residual, 6.0 * plane.rms);
  // The same fit seen from below is turned down.
  const auto below =
      pcl_ext::fitSegmentPlane (cloud, indices, Eigen::Vector3d (x0, y0, -100.0));
  EXPECT_LT (below.normal.dot (n_true), -1.0 + 1e-6);
  EXPECT_NEAR (below.d, -plane.d, 1e-6 * std::abs (plane.d));
}

TEST (FitSegmentPlane, OneOrTwoPointsOrALineHaveNoPlane)
{
  Cloud cloud;
  for (int i = 0; i < 5; ++i)
    cloud.push_back (Point (0.1f * i, 0.2f * i, 0.f)); // collinear
  const Eigen::Vector3d view (0, 0, 1);
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices{0}, view).isValid());
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices{0, 1}, view).isValid());
  EXPECT_FALSE (
      pcl_ext::fitSegmentPlane (cloud, pcl::Indices{0, 1, 2, 3, 4}, view).isValid());
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices{}, view).isValid());
  EXPECT_TRUE (
      std::isnan (pcl_ext::fitSegmentPlane (cloud, pcl::Indices{0}, view).normal.x()));
}

TEST (FitLocalPlane, TotalLeastSquaresAndGivenNormal)
{
  // A tilted 1 m square, 5 cm grid, away from the origin; the normal of z = 0.5 x.
  Cloud cloud;
  const double x0 = 5000.0, y0 = 6000.0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      cloud.push_back (Point (static_cast<float> (x0 + 0.05 * i),
                              static_cast<float> (y0 + 0.05 * j),
                              static_cast<float> (0.5 * 0.05 * i)));
  std::vector<pcl::index_t> indices (cloud.size());
  for (std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = static_cast<pcl::index_t> (i);
  const Eigen::Vector3d n_true = Eigen::Vector3d (-0.5, 0.0, 1.0).normalized();
  pcl_ext::LocalPlane plane;
  ASSERT_TRUE (
      pcl_ext::fitLocalPlane (cloud, indices.begin(), indices.end(), nullptr, plane));
  EXPECT_EQ (plane.size, cloud.size());
  EXPECT_GT (std::abs (plane.normal.dot (n_true)), 1.0 - 1e-5);
  EXPECT_LT (plane.rms, 1e-3); // the floats' rounding only
  EXPECT_NEAR (
      std::abs (plane.signedDistance (plane.centroid + 0.3 * plane.normal)), 0.3, 1e-9);
  // Given a normal, the plane takes it (normalised) through the centroid; the residual
  // is the spread along it.
  const Eigen::Vector3d up (0.0, 0.0, 2.0);
  ASSERT_TRUE (
      pcl_ext::fitLocalPlane (cloud, indices.begin(), indices.end(), &up, plane));
  EXPECT_NEAR (plane.normal.z(), 1.0, 1e-12);
  EXPECT_GT (plane.rms, 0.1); // z spans 0.5 m
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  EXPECT_FALSE (
      pcl_ext::fitLocalPlane (cloud, indices.begin(), indices.end(), &zero, plane));
  // Fewer than 3 points, or collinear ones, have no plane.
  EXPECT_FALSE (pcl_ext::fitLocalPlane (
      cloud, indices.begin(), indices.begin() + 2, nullptr, plane));
  Cloud line;
  for (int i = 0; i < 5; ++i)
    line.push_back (Point (0.25f * i, 0.5f * i, 0.f)); // exactly collinear
  const std::vector<pcl::index_t> all{0, 1, 2, 3, 4};
  EXPECT_FALSE (pcl_ext::fitLocalPlane (line, all.begin(), all.end(), nullptr, plane));
}

TEST (FitLocalPlane, FromSumsTakenPointByPointAsFromIndices)
{
  // Two faces of a box corner at x = 6,000,000 m (a floor z = 0 and a wall x = x0),
  // their points interleaved and sorted into two sums one at a time, as a caller
  // assigning each point to its nearer plane does: the same planes, bit for bit, as
  // from each face's indices.
  Cloud cloud;
  const double x0 = 6000000.0, y0 = 300000.0;
  pcl::Indices floor, wall;
  pcl_ext::CovarianceSums floor_sums, wall_sums;
  for (int i = 1; i <= 12; ++i)
    for (int j = 0; j < 12; ++j) {
      cloud.push_back (Point (static_cast<float> (x0 + 0.25 * i),
                              static_cast<float> (y0 + 0.125 * j),
                              0.0f));
      floor.push_back (static_cast<pcl::index_t> (cloud.size() - 1));
      cloud.push_back (Point (static_cast<float> (x0),
                              static_cast<float> (y0 + 0.125 * j),
                              static_cast<float> (0.03125 * i)));
      wall.push_back (static_cast<pcl::index_t> (cloud.size() - 1));
    }
  for (std::size_t i = 0; i < cloud.size(); ++i)
    (i % 2 == 0 ? floor_sums : wall_sums)
        .add (cloud[i].getVector3fMap().cast<double>());
  EXPECT_EQ (floor_sums.size(), floor.size());
  pcl_ext::LocalPlane from_sums, from_indices;
  ASSERT_TRUE (pcl_ext::fitLocalPlane (floor_sums, nullptr, from_sums));
  ASSERT_TRUE (pcl_ext::fitLocalPlane (
      cloud, floor.begin(), floor.end(), nullptr, from_indices));
  EXPECT_GT (std::abs (from_sums.normal.z()), 1.0 - 1e-12);
  EXPECT_EQ (from_sums.normal, from_indices.normal);
  EXPECT_EQ (from_sums.centroid, from_indices.centroid);
  EXPECT_EQ (from_sums.rms, from_indices.rms);
  EXPECT_NEAR (from_sums.centroid.x(), x0 + 0.25 * 6.5, 1e-9);
  ASSERT_TRUE (pcl_ext::fitLocalPlane (wall_sums, nullptr, from_sums));
  ASSERT_TRUE (
      pcl_ext::fitLocalPlane (cloud, wall.begin(), wall.end(), nullptr, from_indices));
  EXPECT_GT (std::abs (from_sums.normal.x()), 1.0 - 1e-12);
  EXPECT_EQ (from_sums.normal, from_indices.normal);
  EXPECT_EQ (from_sums.d, from_indices.d);
  // No points, or two, have no plane.
  pcl_ext::CovarianceSums few;
  EXPECT_FALSE (pcl_ext::fitLocalPlane (few, nullptr, from_sums));
  few.add (Eigen::Vector3d (x0, y0, 0.0));
  few.add (Eigen::Vector3d (x0 + 1.0, y0, 0.0));
  EXPECT_FALSE (pcl_ext::fitLocalPlane (few, nullptr, from_sums));
}

TEST (IntersectLocalPlanes, TwoFacesOfABoxMeetOnTheirCrease)
{
  // The planes x = 1 and y = 2 meet on the vertical line (1, 2, z); the point returned
  // is the one nearest the midpoint of the two given points.
  const auto a = pcl_ext::Plane::throughPoint (Eigen::Vector3d::UnitX(),
                                               Eigen::Vector3d (1.0, 0.0, 0.0));
  auto b = pcl_ext::Plane::throughPoint (-Eigen::Vector3d::UnitY(),
                                         Eigen::Vector3d (0.0, 2.0, 0.0));
  Eigen::Vector3d point, direction;
  ASSERT_TRUE (pcl_ext::intersectLocalPlanes (a,
                                              b,
                                              Eigen::Vector3d (1.1, 1.5, 3.0),
                                              Eigen::Vector3d (0.5, 2.1, 5.0),
                                              point,
                                              direction));
  EXPECT_NEAR (point.x(), 1.0, 1e-12);
  EXPECT_NEAR (point.y(), 2.0, 1e-12);
  EXPECT_NEAR (point.z(), 4.0, 1e-12);
  EXPECT_NEAR (std::abs (direction.z()), 1.0, 1e-12);
  EXPECT_NEAR (pcl_ext::normalAngle (a.normal, b.normal), M_PI / 2, 1e-12);
  EXPECT_NEAR (pcl_ext::normalAngle (a.normal, -a.normal), 0.0, 1e-12);
  // Parallel planes have no line of intersection.
  b = pcl_ext::Plane::throughPoint (-Eigen::Vector3d::UnitX(), b.centroid);
  EXPECT_FALSE (pcl_ext::intersectLocalPlanes (
      a, b, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), point, direction));
}
