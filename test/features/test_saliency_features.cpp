/*
 * Tests of the point-type-free part of Lim & Suter's features (saliency_features.h): the local
 * ground.
 */
#include <pcl_ext/features/saliency_features.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

// The local ground on a sloping street (10 % grade along x, 20 m x 20 m at 0.1 m spacing) with
// a pole (0.2 m across, 6 m tall) standing on it: the block minimum puts the ground under the
// lower edge of its block, so ground points sit up to (reach + 1) cells of slope above it; the
// opening follows the slope, and both see the pole's foot as ground and its top 6 m above it.
// Points within reach cells of the cloud's edge are left out: there the block is cut short.
TEST (SaliencyFeatures, LocalGroundOnASlope)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const float grade = 0.1f;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      cloud.push_back (pcl::PointXYZ (0.1f * i, 0.1f * j, grade * 0.1f * i));
  const float px = 10.05f, py = 10.05f, base = grade * px;
  for (int k = 0; k <= 60; ++k)
    for (int a = 0; a < 8; ++a)
      cloud.push_back (pcl::PointXYZ (px + 0.1f * std::cos (a * M_PI / 4),
                                      py + 0.1f * std::sin (a * M_PI / 4), base + 0.1f * k));
  for (const auto estimate :
       {pcl_ext::GroundEstimate::LowestInBlock, pcl_ext::GroundEstimate::Opening})
  {
    pcl_ext::LocalGround ground;
    ground.build (cloud, Eigen::Vector3f::UnitZ (), 1.f, 3, estimate);
    double worst = 0.0, sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < 200 * 200; ++i)
      if (cloud[i].x >= 3.f && cloud[i].x < 17.f && cloud[i].y >= 3.f && cloud[i].y < 17.f)
      {
        const double h = ground.heightAbove (cloud[i].getVector3fMap ());
        worst = std::max (worst, std::abs (h));
        sum += h;
        ++n;
      }
    const double mean = sum / static_cast<double> (n);
    const float top = ground.heightAbove (Eigen::Vector3f (px, py, base + 6.f));
    SCOPED_TRACE (pcl_ext::groundEstimateName (estimate));
    if (estimate == pcl_ext::GroundEstimate::Opening)
    {
      // Exact on a plane up to the 1 m cell: a cell's lowest point is its lower edge.
      EXPECT_LT (worst, grade * 1.f + 1e-3);
      EXPECT_NEAR (mean, grade * 0.5, 0.01);
      EXPECT_NEAR (top, 6.f, grade * 1.f + 0.01f);
    }
    else
    {
      // reach to (reach + 1) cells of slope above the ground under it: 0.35 m on average.
      EXPECT_NEAR (mean, grade * 3.5, 0.01);
      EXPECT_LT (worst, grade * 4.f + 1e-3);
      EXPECT_GT (top, 6.f);
      EXPECT_LT (top, 6.f + grade * 4.f + 0.01f);
    }
  }
  pcl_ext::GroundEstimate parsed;
  EXPECT_TRUE (pcl_ext::parseGroundEstimate ("opening", parsed));
  EXPECT_EQ (parsed, pcl_ext::GroundEstimate::Opening);
  EXPECT_FALSE (pcl_ext::parseGroundEstimate ("lowest", parsed));
}
