/*
 * Quality of pcl_ext::ProfileSegmentation on the generated scenes of Sithole & Mapurisa's
 * section 5 (simulated TLS scans with exact ground truth).
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

namespace
{
/** Scan \a name at its defaults; the truth is the object id (or the surface id). */
void
loadScene (const std::string& name, bool surfaces, pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
           std::vector<std::uint32_t>& truth)
{
  pcl_ext::simulation::SyntheticScene scene;
  ASSERT_TRUE (pcl_ext::simulation::generateScene (name, {}, scene));
  cloud.reset (new pcl::PointCloud<pcl::PointXYZ>);
  truth.clear ();
  for (const auto& p : scene.cloud)
  {
    cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    truth.push_back (surfaces ? p.segment : p.object);
  }
}

pcl_ext::SegmentationMetrics
segment (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, const std::vector<std::uint32_t>& truth,
         Segmentation::ProfileMethod method = Segmentation::ProfileMethod::Proximity)
{
  Segmentation seg;
  seg.setInputCloud (cloud);
  seg.setProfileSegmentation (method);
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  pcl_ext::SegmentationMetrics metrics;
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth, metrics));
  return metrics;
}
}  // namespace

TEST (ProfileSegmentationScenes, CubesAreOneSegmentEach)
{
  // Figure 10: 41,500 points, eight disjoint cubes.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("cubes", false, cloud, truth);
  const auto m = segment (cloud, truth);
  EXPECT_EQ (m.num_truth_segments, 8u);
  EXPECT_GE (m.mean_best_iou, 0.98);
  EXPECT_EQ (m.correct, 8u);
}

TEST (ProfileSegmentationScenes, NestedSpheresAreOneSegmentEach)
{
  // Figure 11: 155,000 points, spheres inside spheres.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("spheres", false, cloud, truth);
  const auto m = segment (cloud, truth);
  EXPECT_GE (m.mean_best_iou, 0.95);
  EXPECT_EQ (m.correct, m.num_truth_segments);
}
