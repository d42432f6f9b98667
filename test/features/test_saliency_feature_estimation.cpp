/*
 * Tests of SaliencyFeatureEstimation: Lim & Suter's saliency features (eq. 12) and the
 * other section 4.1 features, per point or region, on PCL point types.
 */
#include "crf_test_clouds.h"

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/features/saliency_feature_estimation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using pcl_ext::SaliencyFeatureEstimation;

namespace {
enum Column {
  kClutter,
  kSurface,
  kCurve,
  kNormalAngle,
  kTangentAngle,
  kHeight,
  kLogRadius
};

Eigen::MatrixXf
features (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
          const pcl::Indices& indices,
          float r)
{
  SaliencyFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setIndices (pcl::make_shared<pcl::Indices> (indices));
  est.setRadius (r);
  Eigen::MatrixXf f;
  est.compute (f);
  return f;
}
} // namespace

TEST (SaliencyFeatureEstimation, Equation12FromTheEigenvalues)
{
  const auto cloud = crf_test::floorAndWall (0.05, 0.004);
  const pcl::index_t centre = 40 * 80 + 40; // (2.05, 2.0, 0) on the floor
  const float r = 0.3f;
  const Eigen::MatrixXf f = features (cloud, {centre}, r);
  ASSERT_EQ (f.rows(), 1);
  ASSERT_EQ (f.cols(), 7);
  pcl::Indices inside;
  for (std::size_t i = 0; i < cloud->size(); ++i)
    if (((*cloud)[i].getVector3fMap() - (*cloud)[centre].getVector3fMap()).norm() <= r)
      inside.push_back (static_cast<pcl::index_t> (i));
  Eigen::Matrix3d cov;
  Eigen::Vector3d c;
  pcl_ext::EigenDecomposition eig;
  pcl_ext::computeLocalCovariance (*cloud, inside, cov, c);
  pcl_ext::computeEigenDecomposition (cov, eig);
  const Eigen::Vector3d l = eig.values;
  EXPECT_NEAR (f (0, kClutter), std::log (l (0)), 1e-3);
  EXPECT_NEAR (f (0, kSurface), std::log (l (1) / r - l (0)), 1e-3);
  EXPECT_NEAR (f (0, kCurve), std::log (l (2) / r - l (1) / r), 2e-2);
  // A disc of radius r has in-plane variance r^2 / 4 and the noise variance across it.
  EXPECT_NEAR (l (1), r * r / 4, 0.15 * r * r / 4);
  EXPECT_NEAR (std::sqrt (l (0)), 0.004, 0.001);
  EXPECT_NEAR (f (0, kNormalAngle), 0.f, 0.05f);      // horizontal floor
  EXPECT_NEAR (f (0, kTangentAngle), M_PI / 2, 0.05); // its directions are horizontal
  EXPECT_NEAR (f (0, kHeight), 0.f, 0.02f);
  EXPECT_NEAR (f (0, kLogRadius), std::log (r), 1e-5);
}

TEST (SaliencyFeatureEstimation, WallAnglesAndHeight)
{
  const auto cloud = crf_test::floorAndWall (0.05, 0.002);
  const std::size_t floor_points = 79 * 80;
  const pcl::index_t wall =
      static_cast<pcl::index_t> (floor_points + 59 * 80 + 40); // z = 3
  const Eigen::MatrixXf f = features (cloud, {wall}, 0.3f);
  ASSERT_EQ (f.rows(), 1);
  EXPECT_NEAR (f (0, kNormalAngle), M_PI / 2, 0.05); // vertical wall
  EXPECT_NEAR (f (0, kHeight), 3.f, 0.02f);          // above the floor beside it
}

TEST (SaliencyFeatureEstimation, LinesTellPolesFromWires)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i < 200; ++i)
    cloud->push_back (pcl::PointXYZ (0, 0, 0.02f * i)); // a pole
  for (int i = 0; i < 200; ++i)
    cloud->push_back (pcl::PointXYZ (5.f + 0.02f * i, 0, 6)); // a wire
  const Eigen::MatrixXf f = features (cloud, {100, 300}, 0.2f);
  ASSERT_EQ (f.rows(), 2);
  EXPECT_NEAR (f (0, kTangentAngle), 0.f, 0.01f);
  EXPECT_NEAR (f (1, kTangentAngle), M_PI / 2, 0.01);
  // A line is all curveness: the two smaller eigenvalues vanish.
  EXPECT_GT (f (0, kCurve), f (0, kSurface) + 5.f);
}

TEST (SaliencyFeatureEstimation, ColourAndIntensityWhenThePointTypeHasThem)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>>();
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      pcl::PointXYZRGB p;
      p.r = 200;
      p.g = 50;
      p.b = 0;
      p.x = 0.05f * i;
      p.y = 0.05f * j;
      cloud->push_back (p);
    }
  SaliencyFeatureEstimation<pcl::PointXYZRGB> est;
  est.setInputCloud (cloud);
  est.setRadius (0.2f);
  Eigen::MatrixXf f;
  est.compute (f);
  ASSERT_EQ (f.rows(), 400);
  ASSERT_EQ (est.getFeatureNames().size(), 10u);
  EXPECT_EQ (est.getFeatureNames()[7], "red");
  EXPECT_NEAR (f (0, 7), 0.8f, 1e-5f);
  EXPECT_NEAR (f (0, 8), 0.2f, 1e-5f);
  EXPECT_NEAR (f (0, 9), 0.0f, 1e-5f);
  auto ic = pcl::make_shared<pcl::PointCloud<pcl::PointXYZI>>();
  for (int i = 0; i < 50; ++i) {
    pcl::PointXYZI p;
    p.x = 0.1f * i;
    p.y = 0.f;
    p.z = 0.f;
    p.intensity = 0.25f;
    ic->push_back (p);
  }
  SaliencyFeatureEstimation<pcl::PointXYZI> ei;
  ei.setInputCloud (ic);
  ei.setRadius (0.5f);
  ei.compute (f);
  ASSERT_EQ (est.getFeatureNames().size(), 10u);
  ASSERT_EQ (ei.getFeatureNames().back(), "intensity");
  EXPECT_NEAR (f (10, 7), 0.25f, 1e-6f);
}

TEST (SaliencyFeatureEstimation, BadInputGivesEmptyOutput)
{
  Eigen::MatrixXf f;
  SaliencyFeatureEstimation<pcl::PointXYZ> est;
  est.compute (f); // no input
  EXPECT_EQ (f.size(), 0);
  auto empty = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  est.setInputCloud (empty);
  est.setRadius (1.f);
  est.compute (f);
  EXPECT_EQ (f.size(), 0);
  const auto cloud = crf_test::floorAndWall (0.1, 0.002);
  EXPECT_EQ (features (cloud, {0}, 0.f).size(), 0);            // no radius
  EXPECT_EQ (features (cloud, {0}, std::nanf ("")).size(), 0); // NaN radius
  (*cloud)[3].z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ (features (cloud, {3}, 0.3f).size(), 0);      // a NaN centre
  const Eigen::MatrixXf ok = features (cloud, {4}, 0.3f); // NaN neighbours skipped
  ASSERT_EQ (ok.rows(), 1);
  EXPECT_TRUE (ok.allFinite());
  auto one = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  one->push_back (pcl::PointXYZ (0, 0, 0));
  const Eigen::MatrixXf single = features (one, {0}, 1.f); // degenerate but finite
  ASSERT_EQ (single.rows(), 1);
  EXPECT_TRUE (single.allFinite());
  SaliencyFeatureEstimation<pcl::PointXYZ> mismatch;
  mismatch.setInputCloud (cloud);
  mismatch.setRadii ({0.1f, 0.2f}); // two radii, all points indexed
  mismatch.compute (f);
  EXPECT_EQ (f.size(), 0);
}

TEST (SaliencyFeatureEstimation, MultiScaleFeaturesTellPolesWiresAndGround)
{
  // A 1 cm-spaced vertical pole 4 m tall, a horizontal wire 6 m above the ground, and a
  // 5 cm-spaced ground plane under both, far enough from each other for the 2 m scale.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int x = 0; x < 400; ++x)
    for (int y = 0; y < 200; ++y)
      cloud->push_back (pcl::PointXYZ (x * 0.05f, y * 0.05f, 0.f));
  const pcl::index_t ground = 100 * 200 + 100; // (5, 5, 0)
  const pcl::index_t pole =
      static_cast<pcl::index_t> (cloud->size()) + 200; // (5, 2, 2)
  for (int z = 1; z <= 400; ++z)
    cloud->push_back (pcl::PointXYZ (5.f, 2.f, z * 0.01f));
  const pcl::index_t wire =
      static_cast<pcl::index_t> (cloud->size()) + 500; // (15, 7.5, 6)
  for (int x = 0; x <= 1000; ++x)
    cloud->push_back (pcl::PointXYZ (10.f + x * 0.01f, 7.5f, 6.f));
  SaliencyFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{ground, pole, wire}));
  est.setRadius (0.3f);
  est.setFeatureScales (pcl_ext::defaultFeatureScales());
  Eigen::MatrixXf f;
  est.compute (f);
  const auto& names = est.getFeatureNames();
  ASSERT_EQ (f.rows(), 3);
  ASSERT_EQ (f.cols(), static_cast<Eigen::Index> (names.size()));
  ASSERT_EQ (names.size(), 7u + 3u * 11u + 2u);
  auto col = [&] (const std::string& name) {
    const auto it = std::find (names.begin(), names.end(), name);
    EXPECT_NE (it, names.end()) << name;
    return it - names.begin();
  };
  for (const char* s : {"@0.5", "@1", "@2"}) {
    const std::string at = s;
    EXPECT_NEAR (f (0, col ("planarity" + at)), 1.f, 0.02f) << at;
    EXPECT_NEAR (f (0, col ("normal_angle" + at)), 0.f, 0.01f) << at;
    EXPECT_NEAR (f (0, col ("top_above" + at)), 0.f, 1e-5f) << at;
    EXPECT_NEAR (f (1, col ("linearity" + at)), 1.f, 0.02f) << at;
    EXPECT_NEAR (f (1, col ("tangent_angle" + at)), 0.f, 0.01f) << at; // vertical
    EXPECT_NEAR (f (2, col ("linearity" + at)), 1.f, 1e-3f) << at;
    EXPECT_NEAR (f (2, col ("tangent_angle" + at)), M_PI / 2, 0.01f)
        << at; // horizontal
    // A wire has nothing above or below it; the pole's middle sees its own points both
    // ways.
    EXPECT_NEAR (f (2, col ("top_above" + at)), 0.f, 1e-5f) << at;
    EXPECT_NEAR (f (2, col ("bottom_below" + at)), 0.f, 1e-5f) << at;
  }
  // Within 0.5 m and 1 m the pole centre (2 m up) sees only the pole; at 2 m it reaches
  // the ground, and its extent both ways is the radius.
  EXPECT_NEAR (f (1, col ("top_above@1")), 1.f, 0.011f);
  EXPECT_NEAR (f (1, col ("bottom_below@2")), 2.f, 0.011f);
  // The density is the count within R: 101 wire points within 0.5 m at 1 cm.
  EXPECT_NEAR (f (2, col ("log_density@0.5")), std::log (101.f), 0.02f);
  // The dimension between scales: 1 along the wire (101, 201, 401 points within 0.5,
  // 1 and 2 m), 2 on the ground, 1 up the pole until the 2 m sphere reaches the ground.
  EXPECT_NEAR (f (2, col ("dimension@1")), 1.f, 0.02f);
  EXPECT_NEAR (f (2, col ("dimension@2")), 1.f, 0.02f);
  EXPECT_NEAR (f (0, col ("dimension@1")), 2.f, 0.1f);
  EXPECT_NEAR (f (0, col ("dimension@2")), 2.f, 0.1f);
  EXPECT_NEAR (f (1, col ("dimension@1")), 1.f, 0.02f);
  // Scales not ascending are refused.
  est.setFeatureScales ({1.f, 0.5f});
  est.compute (f);
  EXPECT_EQ (f.size(), 0);
}
