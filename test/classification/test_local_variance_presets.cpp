/*
 * LocalVarianceClassification's presets: the paper's settings, the settings derived
 * from the cloud (the noise estimated and removed, the curvature threshold at the
 * median), and the defaults, which choose the curvature factor from the cloud's noise.
 */
#include "../features/analytic_clouds.h"

#include <pcl_ext/classification/local_variance_classification.h>

#include <gtest/gtest.h>

#include <cmath>

using Classifier = pcl_ext::LocalVarianceClassification<pcl::PointXYZ>;
using Labels = pcl::PointCloud<pcl::Label>;

TEST (LocalVarianceClassificationPresets, DerivedSettingsEstimateTheNoiseAndSpacing)
{
  // A cube of 2 cm spacing with 2 mm of noise along the face normals.
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.002);
  Classifier c;
  c.setInputCloud (cube.cloud);
  c.setKSearch (50);
  c.setDerivedSettings();
  EXPECT_TRUE (c.getNoiseEstimation());
  EXPECT_EQ (c.getCurvatureThresholdFactor(), 1.0);
  Labels labels;
  c.classify (labels);
  ASSERT_EQ (labels.size(), cube.cloud->size());
  const auto& e = c.getNoiseEstimate();
  ASSERT_TRUE (e.valid) << e.reason;
  EXPECT_NEAR (e.sigma, 0.002, 0.0004);
  EXPECT_NEAR (e.spacing, 0.02, 0.004);
  EXPECT_EQ (c.getNoiseStandardDeviationUsed(), e.sigma);

  // A value set by hand overrides the estimate.
  c.setNoiseStandardDeviation (0.001);
  EXPECT_FALSE (c.getNoiseEstimation());
  c.classify (labels);
  EXPECT_EQ (c.getNoiseStandardDeviationUsed(), 0.001);
  EXPECT_FALSE (c.getNoiseEstimate().valid);
}

TEST (LocalVarianceClassificationPresets, DefaultsAreThePapersOnAScannersCloud)
{
  // 2 mm of noise at 2 cm spacing: a scanner's share; the factor chosen is the
  // paper's 3.
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.002);
  Classifier defaults, paper;
  for (Classifier* c : {&defaults, &paper}) {
    c->setInputCloud (cube.cloud);
    c->setKSearch (50);
  }
  EXPECT_EQ (defaults.getCurvatureThresholdFactor(), 0.0); // from the cloud
  paper.setDerivedSettings();
  paper.setPaperSettings();
  EXPECT_FALSE (paper.getNoiseEstimation());
  EXPECT_EQ (paper.getNoiseStandardDeviation(), 0.0);
  EXPECT_EQ (paper.getCurvatureThresholdFactor(), 3.0);
  EXPECT_EQ (paper.getVarianceThreshold(), 1e-4);
  EXPECT_EQ (paper.getConfidence(), 0.95);
  Labels a, b;
  defaults.classify (a);
  paper.classify (b);
  EXPECT_EQ (defaults.getCurvatureThresholdFactorUsed(), 3.0);
  EXPECT_EQ (defaults.getNoiseStandardDeviationUsed(), 0.0); // estimated, not removed
  EXPECT_TRUE (defaults.getNoiseEstimate().valid);
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_EQ (a[i].label, b[i].label) << i;
}

TEST (LocalVarianceClassificationPresets, RangeCameraNoiseTakesTheMedianAsThreshold)
{
  // 7 mm of noise at 2 cm spacing: above 0.2 spacings, as a range camera's frames; the
  // threshold is the median curvature itself, as -preset derived sets it.
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.007);
  Classifier defaults, factor_one;
  for (Classifier* c : {&defaults, &factor_one}) {
    c->setInputCloud (cube.cloud);
    c->setKSearch (50);
  }
  factor_one.setCurvatureThresholdFactor (1.0);
  Labels a, b;
  defaults.classify (a);
  factor_one.classify (b);
  const auto& e = defaults.getNoiseEstimate();
  ASSERT_TRUE (e.valid) << e.reason;
  EXPECT_GT (e.sigma, Classifier::kMaxNoiseToSpacing * e.spacing);
  EXPECT_EQ (defaults.getCurvatureThresholdFactorUsed(), 1.0);
  EXPECT_EQ (defaults.getCurvatureThresholdUsed(),
             factor_one.getCurvatureThresholdUsed());
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_EQ (a[i].label, b[i].label) << i;
  // A threshold given by hand: no factor, no estimate.
  defaults.setCurvatureThreshold (0.01);
  defaults.classify (a);
  EXPECT_EQ (defaults.getCurvatureThresholdFactorUsed(), 0.0);
  EXPECT_FALSE (defaults.getNoiseEstimate().valid);
  defaults.setCurvatureThresholdFactor (-1.0);
  defaults.setCurvatureThreshold (0.0);
  defaults.classify (a);
  EXPECT_TRUE (a.empty());
}

TEST (LocalVarianceClassificationPresets, TheNoiseSampleDoesNotDependOnThePointOrder)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.002);
  auto reversed = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (auto it = cube.cloud->rbegin(); it != cube.cloud->rend(); ++it)
    reversed->push_back (*it);
  Classifier a, b;
  a.setInputCloud (cube.cloud);
  b.setInputCloud (reversed);
  Labels la, lb;
  for (Classifier* c : {&a, &b}) {
    c->setKSearch (50);
    c->setDerivedSettings();
  }
  a.classify (la);
  b.classify (lb);
  ASSERT_TRUE (a.getNoiseEstimate().valid);
  // The same points are sampled; on this grid, neighbours at equal distances may be
  // taken in another order or another of them as the k-th, which moves the values in
  // their last digits (before the sample was every n-th row: another sample).
  EXPECT_EQ (a.getNoiseEstimate().used, b.getNoiseEstimate().used);
  EXPECT_NEAR (a.getNoiseEstimate().sigma, b.getNoiseEstimate().sigma, 1e-4 * 0.002);
  EXPECT_NEAR (a.getNoiseEstimate().spacing, b.getNoiseEstimate().spacing, 1e-4 * 0.02);
}

TEST (LocalVarianceClassificationPresets, UnestimableNoiseFallsBackToThePaper)
{
  // 64 points: fewer neighbourhoods than the estimate needs.
  const auto plane = pcl_ext::test::makePlane (0.08, 0.01, 0.0, 0.001);
  ASSERT_LT (plane.cloud->size(), pcl_ext::kMinNoiseNeighbourhoods);
  Classifier c;
  c.setInputCloud (plane.cloud);
  c.setKSearch (20);
  c.setDerivedSettings();
  Labels labels;
  c.classify (labels);
  ASSERT_EQ (labels.size(), plane.cloud->size());
  EXPECT_FALSE (c.getNoiseEstimate().valid);
  EXPECT_FALSE (c.getNoiseEstimate().reason.empty());
  EXPECT_EQ (c.getNoiseStandardDeviationUsed(), 0.0);
}
