/*
 * ChiSquaredBoundaryEstimation (eq. 6-8): borders of planes and cylinders found,
 * interiors kept, the printed (unscaled) form, the range-noise option, bad input. The
 * quantile and the statistic itself are tested with their kernels
 * (test_local_variance.cpp).
 */
#include "analytic_clouds.h"

#include <pcl_ext/features/chi_squared_boundary.h>

#include <gtest/gtest.h>

#include <iostream>
#include <random>

using pcl_ext::test::Cloud;
using Boundaries = pcl::PointCloud<pcl::Boundary>;

namespace {
Boundaries
boundaries (const Cloud::ConstPtr& cloud,
            int k,
            double confidence = 0.95,
            bool scale = true,
            double noise_sigma = 0.0)
{
  pcl_ext::ChiSquaredBoundaryEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setKSearch (k);
  est.setConfidence (confidence);
  est.setScaleByNeighbourhoodSize (scale);
  est.setNoiseStandardDeviation (noise_sigma);
  Boundaries out;
  est.compute (out);
  return out;
}
} // namespace

TEST (ChiSquaredBoundaryEstimation, JitteredPlaneBorderFoundInteriorKept)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.01, 0.6, 0.0005);
  const int k = 50;
  const Boundaries b = boundaries (plane.cloud, k);
  ASSERT_EQ (b.size(), plane.cloud->size());
  const double r = plane.spacing * std::sqrt (k / M_PI);
  std::size_t border = 0, border_found = 0, interior = 0, interior_found = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (plane.border_distance[i] <= 0.5 * plane.spacing) {
      ++border;
      border_found += b[i].boundary_point;
    }
    else if (plane.border_distance[i] > r) {
      ++interior;
      interior_found += b[i].boundary_point;
    }
  }
  // Every point on the border is outside the 95% region of its centroid; the interior
  // ones exceed it at most at the chi2 rate (1 - confidence).
  EXPECT_EQ (border_found, border);
  EXPECT_LE (static_cast<double> (interior_found), 0.05 * interior);
}

TEST (ChiSquaredBoundaryEstimation, CylinderEndsAreBoundaries)
{
  const auto cyl = pcl_ext::test::makeCylinder (0.2, 0.5, 0.01);
  const Boundaries b = boundaries (cyl.cloud, 40);
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (cyl.border_distance[i] == 0.0)
      EXPECT_EQ (b[i].boundary_point, 1) << i;
    if (cyl.border_distance[i] > 0.08)
      EXPECT_EQ (b[i].boundary_point, 0) << i;
  }
}

TEST (ChiSquaredBoundaryEstimation, PrintedFormMissesStraightBorders)
{
  // The printed eq. 6 (no factor n) gives ~2.57 on a straight border, below 5.991: it
  // finds the corners only. This is why the statistic is scaled by the neighbourhood
  // size.
  const auto plane = pcl_ext::test::makePlane (1.0, 0.01);
  const Boundaries printed = boundaries (plane.cloud, 50, 0.95, false);
  std::size_t straight = 0, straight_found = 0;
  for (std::size_t i = 0; i < printed.size(); ++i) {
    const auto& p = (*plane.cloud)[i];
    const bool corner =
        std::min (p.x, 1.f - p.x) < 0.1f && std::min (p.y, 1.f - p.y) < 0.1f;
    if (plane.border_distance[i] == 0.0 && !corner) {
      ++straight;
      straight_found += printed[i].boundary_point;
    }
  }
  ASSERT_GT (straight, 100u);
  EXPECT_EQ (straight_found, 0u);
}

TEST (ChiSquaredBoundaryEstimation, NoiseOptionWidensTheRegionAndKeepsBorders)
{
  // A plane on a 3 mm grid (k = 50 neighbours span 1.2 cm) with 1.5 mm range noise
  // along beams 60 degrees off the normal, so each point is also moved along the plane.
  // The noise term only widens the confidence region (u^2 / (l1 / n + sigma^2) <= u^2 /
  // (l1 / n)): it removes boundary points, never adds one, and the border's centroid
  // offset (about 0.42 neighbourhood radii) still exceeds it.
  const double spacing = 0.003, sigma = 0.0015;
  auto plane = pcl_ext::test::makePlane (0.3, spacing);
  std::mt19937 rng (7);
  std::normal_distribution<double> g (0.0, sigma);
  const Eigen::Vector3f beam (std::sin (M_PI / 3), 0.f, std::cos (M_PI / 3));
  for (auto& p : *plane.cloud)
    p.getVector3fMap() += static_cast<float> (g (rng)) * beam;
  const Boundaries paper = boundaries (plane.cloud, 50);
  const Boundaries noise = boundaries (plane.cloud, 50, 0.95, true, sigma);
  ASSERT_EQ (noise.size(), plane.cloud->size());
  ASSERT_EQ (paper.size(), noise.size());
  std::size_t added = 0, removed = 0, border = 0, border_found = 0;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    added += noise[i].boundary_point && !paper[i].boundary_point;
    removed += paper[i].boundary_point && !noise[i].boundary_point;
    if (plane.border_distance[i] <= 0.5 * spacing) {
      ++border;
      border_found += noise[i].boundary_point;
    }
  }
  EXPECT_EQ (added, 0u);
  EXPECT_GT (removed, 0u);
  EXPECT_GE (double (border_found) / border, 0.95);
}

TEST (ChiSquaredBoundaryEstimationBadInput, ConfidenceOutOfRangeGivesEmptyOutput)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.1);
  for (const double confidence :
       {0.0, 1.0, -0.1, 1.5, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_TRUE (boundaries (plane.cloud, 10, confidence).empty()) << confidence;
  for (const double sigma : {-0.001,
                             std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()})
    EXPECT_TRUE (boundaries (plane.cloud, 10, 0.95, true, sigma).empty()) << sigma;
}

TEST (ChiSquaredBoundaryEstimationBadInput,
      DegenerateAndNonFinitePointsAreNotBoundaries)
{
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < 15; ++i)
    cloud->push_back (pcl::PointXYZ (0.5f, 0.5f, 0.5f)); // duplicates
  for (int i = 0; i < 15; ++i)
    cloud->push_back (pcl::PointXYZ (10.f + i, 0.f, 0.f)); // collinear
  cloud->push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f));
  cloud->is_dense = false;
  const Boundaries b = boundaries (cloud, 10);
  ASSERT_EQ (b.size(), cloud->size());
  EXPECT_FALSE (b.is_dense);
  for (const auto& p : b)
    EXPECT_EQ (p.boundary_point, 0);
}

TEST (ChiSquaredBoundaryEstimationBadInput, EmptyCloudGivesEmptyOutput)
{
  EXPECT_TRUE (boundaries (pcl::make_shared<Cloud>(), 10).empty());
}
