/*
 * Tests of pcl_ext::ProfileSegmentation on analytic shapes sampled finely: nested
 * spheres with every profile method, touching coaxial surfaces with curve fitting.
 * Labelled `quality`: the sanitized quick run leaves them out (curve fitting runs many
 * times slower there), and the determinism tests of test_profile_segmentation cover the
 * same code on coarser pipes.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include "profile_test_clouds.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>

using namespace profile_test;
using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

namespace {
/** Prints the figures the bounds below check. */
void
report (const std::string& name, const pcl_ext::SegmentationMetrics& m)
{
  std::cout << std::fixed << std::setprecision (3) << "  [ " << name
            << " ] mean best IoU " << m.mean_best_iou << ", " << m.correct
            << " correct, " << m.under_segmented << " under\n";
}
} // namespace

TEST (ProfileSegmentationShapes, NestedSpheresAreSeparate)
{
  LabelledCloud scene;
  addSphere (scene, {0, 0, 0}, 1.0, 0.02, 1);
  addSphere (scene, {0.05, 0, 0}, 0.6, 0.02, 2);
  addSphere (scene, {0.1, 0.05, 0}, 0.25, 0.02, 3);
  for (const auto method : {Segmentation::ProfileMethod::Proximity,
                            Segmentation::ProfileMethod::MinimumSpanningTree,
                            Segmentation::ProfileMethod::CurveFitting}) {
    Segmentation seg;
    seg.setInputCloud (scene.cloud);
    seg.setProfileSegmentation (method);
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    const auto m = evaluate (clusters, scene);
    report ("nested spheres, method " + std::to_string (static_cast<int> (method)), m);
    EXPECT_GE (m.mean_best_iou, 0.99) << static_cast<int> (method);
    EXPECT_EQ (m.correct, 3u) << static_cast<int> (method);
  }
}

TEST (ProfileSegmentationShapes, CurveFittingSeparatesTouchingCoaxialSurfaces)
{
  const LabelledCloud scene = coaxialPipes();
  Segmentation seg;
  seg.setInputCloud (scene.cloud);
  std::vector<pcl::PointIndices> clusters;
  // Proximity links across the creases: the three surfaces are one segment.
  seg.extract (clusters);
  const auto proximity = evaluate (clusters, scene);
  report ("coaxial pipes, proximity", proximity);
  EXPECT_EQ (clusters.size(), 1u);
  EXPECT_EQ (proximity.under_segmented, 3u);
  // Curve fitting ends the curves at the creases.
  seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
  seg.extract (clusters);
  const auto curve = evaluate (clusters, scene);
  report ("coaxial pipes, curve fitting", curve);
  EXPECT_GE (curve.mean_best_iou, 0.90);
  EXPECT_EQ (curve.correct, 3u);
  EXPECT_FALSE (seg.getBreakpoints().empty());
}
