/*
 * Tests of pcl_ext::AutoProfileSegmentation: the configuration chosen from the cloud on
 * analytic clouds whose answer is known.
 */
#include "profile_test_clouds.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using profile_test::addCube;
using profile_test::addRectangle;
using profile_test::evaluate;
using profile_test::LabelledCloud;
using profile_test::threeCubes;
using AutoSegmentation = pcl_ext::AutoProfileSegmentation<pcl::PointXYZ>;
using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

namespace {
/** A floor and a wall meeting at a right angle, 2 mm noise at 2 cm spacing: one
 * connected surface, two planes. */
LabelledCloud
floorAndWall ()
{
  LabelledCloud scene;
  std::mt19937 rng (5);
  addRectangle (scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.5, 1.5, 0.02, 1, rng, 0.002);
  addRectangle (scene, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.5, 1.0, 0.02, 2, rng, 0.002);
  return scene;
}
} // namespace

TEST (AutoProfileSegmentation, SeparateObjectsKeepProximityChaining)
{
  const LabelledCloud scene = threeCubes ({0.8, 0.8, 0.8}, 3);
  AutoSegmentation automatic;
  automatic.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> clusters;
  automatic.extract (clusters);
  EXPECT_FALSE (automatic.getConfiguration().curve_fitting);
  EXPECT_FALSE (automatic.getCylindersJoined());
  EXPECT_LT (automatic.getLargestProximityShare(), 0.5);
  EXPECT_NEAR (automatic.getCloudStatistics().spacing, 0.02, 0.004);
  ASSERT_EQ (clusters.size(), 3u);
  EXPECT_DOUBLE_EQ (evaluate (clusters, scene).mean_best_iou, 1.0);

  // The same segments as the paper's configuration.
  Segmentation paper;
  paper.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> expected;
  paper.extract (expected);
  ASSERT_EQ (expected.size(), clusters.size());
  for (std::size_t i = 0; i < clusters.size(); ++i)
    EXPECT_EQ (clusters[i].indices, expected[i].indices);
}

TEST (AutoProfileSegmentation, TouchingSurfacesChooseCurveFitting)
{
  // Proximity chaining gives one segment (the share is 1); curve fitting splits the
  // crease, which the paper's configuration does not do unless told.
  const LabelledCloud scene = floorAndWall();
  Segmentation paper;
  paper.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> proximity;
  paper.extract (proximity);
  ASSERT_EQ (proximity.size(), 1u);

  AutoSegmentation automatic;
  automatic.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> clusters;
  automatic.extract (clusters);
  EXPECT_DOUBLE_EQ (automatic.getLargestProximityShare(), 1.0);
  EXPECT_TRUE (automatic.getConfiguration().curve_fitting);
  EXPECT_TRUE (automatic.getConfiguration().side_frames);
  EXPECT_FALSE (automatic.getConfiguration().local_threshold);
  ASSERT_GE (clusters.size(), 2u);
  const auto m = evaluate (clusters, scene);
  EXPECT_EQ (m.correct, 2u);
  EXPECT_GE (m.mean_best_iou, 0.9);
  // The segments are reported in the coloured cloud too.
  EXPECT_EQ (automatic.getColoredCloud()->size(), scene.cloud->size());
}

TEST (AutoProfileSegmentation, CrossingSurfacesAreOneSegmentEach)
{
  // Two planes crossing at 70 degrees, and two vertical walls crossing at a right angle
  // on a floor (section 4.1.2's entangled curves: the profiles show an X, a + or a T).
  // Curve ends cut every curve at the crossing; followed across it, each plane is one
  // segment, not two halves (best IoU about 0.47 each before).
  const double a = 35.0 * M_PI / 180.0;
  const Eigen::Vector3d up (std::cos (a), 0.0, std::sin (a)),
      down (std::cos (a), 0.0, -std::sin (a)), y (0.0, 1.0, 0.0);
  LabelledCloud planes;
  std::mt19937 rng (9);
  addRectangle (planes, -0.7 * up, up, y, 1.4, 1.0, 0.02, 1, rng, 0.0015);
  addRectangle (planes, -0.7 * down, down, y, 1.4, 1.0, 0.02, 2, rng, 0.0015);
  LabelledCloud walls;
  addRectangle (walls, {-1.2, -1.2, 0}, {1, 0, 0}, y, 2.4, 2.4, 0.025, 1, rng, 0.0015);
  addRectangle (
      walls, {-1.0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 2.0, 1.2, 0.025, 2, rng, 0.0015);
  addRectangle (walls, {0, -1.0, 0}, y, {0, 0, 1}, 2.0, 1.2, 0.025, 3, rng, 0.0015);
  for (const LabelledCloud* scene : {&planes, &walls}) {
    AutoSegmentation automatic;
    automatic.setInputCloud (scene->cloud);
    std::vector<pcl::PointIndices> clusters;
    automatic.extract (clusters);
    EXPECT_TRUE (automatic.getConfiguration().curve_fitting);
    const auto m = evaluate (clusters, *scene);
    const std::size_t surfaces = scene == &planes ? 2u : 3u;
    EXPECT_EQ (m.correct, surfaces) << surfaces << " surfaces";
    EXPECT_GE (m.mean_best_iou, 0.9) << surfaces << " surfaces";
  }
}

TEST (AutoProfileSegmentation, TheCallersSettingsAreKept)
{
  const LabelledCloud scene = floorAndWall();
  AutoSegmentation automatic;
  automatic.setInputCloud (scene.cloud);
  automatic.setProfileSegmentation (Segmentation::ProfileMethod::MinimumSpanningTree);
  automatic.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  automatic.extract (clusters);
  ASSERT_TRUE (automatic.getConfiguration().curve_fitting);
  for (const auto& c : clusters)
    EXPECT_GE (c.indices.size(), 50u);
  // What extract() chose is not left in the settings.
  EXPECT_EQ (automatic.getProfileSegmentation(),
             Segmentation::ProfileMethod::MinimumSpanningTree);
  EXPECT_FALSE (automatic.getSideFrames());
  EXPECT_FALSE (automatic.getCorrectedAic());
  EXPECT_DOUBLE_EQ (automatic.getTurnSignificance(), 0.0);
  EXPECT_DOUBLE_EQ (automatic.getProfileWidthFactor(), 1.5);
}

TEST (AutoProfileSegmentation, DeterministicForAnyThreadCount)
{
  const LabelledCloud scene = floorAndWall();
  std::vector<pcl::PointIndices> one, two;
  for (const unsigned int threads : {1u, 2u}) {
    AutoSegmentation automatic;
    automatic.setInputCloud (scene.cloud);
    automatic.setNumberOfThreads (threads);
    automatic.extract (threads == 1 ? one : two);
  }
  ASSERT_EQ (one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    EXPECT_EQ (one[i].indices, two[i].indices);
}

TEST (AutoProfileSegmentation, BadInputGivesNoSegments)
{
  AutoSegmentation automatic;
  std::vector<pcl::PointIndices> clusters (1);
  automatic.extract (clusters); // no input cloud
  EXPECT_TRUE (clusters.empty());
  EXPECT_FALSE (automatic.getConfiguration().curve_fitting);

  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->push_back (pcl::PointXYZ (nan, nan, nan));
  automatic.setInputCloud (cloud);
  automatic.extract (clusters);
  EXPECT_TRUE (clusters.empty());

  automatic.setInputCloud (threeCubes().cloud);
  automatic.setNumberOfStacks (0);
  automatic.extract (clusters);
  EXPECT_TRUE (clusters.empty());
  EXPECT_FALSE (automatic.getCylindersJoined());
}
