/*
 * LocalVarianceClassification's presets: the paper's settings and the settings derived
 * from the cloud (the noise estimated and removed, the curvature threshold at the
 * median).
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

TEST (LocalVarianceClassificationPresets, PaperSettingsAreTheDefaults)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.002);
  Classifier defaults, paper;
  for (Classifier* c : {&defaults, &paper}) {
    c->setInputCloud (cube.cloud);
    c->setKSearch (50);
  }
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
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_EQ (a[i].label, b[i].label) << i;
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
