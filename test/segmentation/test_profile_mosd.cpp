/*
 * Real data (label "data"; skipped without the data folder, PCL_EXT_SHARED_DATA_DIR):
 * pcl_ext::ProfileSegmentation on the mOSD Kinect frames learn0 (boxes), learn20
 * (stacked boxes) and learn35 (cylinders), scored at the object level against their
 * labels, next to pcl::EuclideanClusterExtraction with the same distance tolerance on
 * the same points.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace {
const std::string kDir =
    std::string (PCL_EXT_SHARED_DATA_DIR) + "/mosd_object_segmentation";

struct Frame {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  std::vector<std::uint32_t> objects; ///< 0 ignored, 1 the table, 2.. the objects
};

/** The finite points of a frame. mOSD labels: 0 NaN, 1-9 parts of the table, 10 j + p
 * part p of object j (j >= 2); an object is label / 10, the table one object. */
bool
loadFrame (const std::string& name, Frame& frame)
{
  pcl::PointCloud<pcl::PointXYZRGBL> raw;
  if (pcl::io::loadPCDFile (kDir + "/" + name, raw) != 0)
    return false;
  for (const auto& p : raw) {
    if (!pcl::isFinite (p))
      continue;
    frame.cloud->emplace_back (p.x, p.y, p.z);
    frame.objects.push_back (p.label == 0 ? 0u : (p.label < 10 ? 1u : p.label / 10));
  }
  return !frame.cloud->empty();
}
} // namespace

TEST (ProfileSegmentationMosd, ObjectsNextToEuclideanClustering)
{
  if (!std::ifstream (kDir + "/learn0.pcd"))
    GTEST_SKIP() << "real data not found in " << kDir;
  for (const char* name : {"learn0.pcd", "learn20.pcd", "learn35.pcd"}) {
    Frame frame;
    ASSERT_TRUE (loadFrame (name, frame)) << name;

    pcl_ext::ProfileSegmentation<pcl::PointXYZ> profiles;
    profiles.setInputCloud (frame.cloud);
    std::vector<pcl::PointIndices> ours;
    profiles.extract (ours);
    pcl_ext::SegmentationMetrics m_ours;
    ASSERT_TRUE (pcl_ext::evaluateSegmentation (ours, frame.objects, m_ours));
    profiles.setProfileSegmentation (
        pcl_ext::ProfileSegmentation<pcl::PointXYZ>::ProfileMethod::CurveFitting);
    std::vector<pcl::PointIndices> curves;
    profiles.extract (curves);
    pcl_ext::SegmentationMetrics m_curves;
    ASSERT_TRUE (pcl_ext::evaluateSegmentation (curves, frame.objects, m_curves));
    std::printf ("%s: curve fitting %.3f (%zu segments, %zu correct)\n",
                 name,
                 m_curves.mean_best_iou,
                 curves.size(),
                 m_curves.correct);

    pcl::EuclideanClusterExtraction<pcl::PointXYZ> ece;
    ece.setInputCloud (frame.cloud);
    ece.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
        new pcl::search::KdTree<pcl::PointXYZ>));
    ece.setClusterTolerance (profiles.getUsedDistanceThreshold());
    std::vector<pcl::PointIndices> stock;
    ece.extract (stock);
    pcl_ext::SegmentationMetrics m_stock;
    ASSERT_TRUE (pcl_ext::evaluateSegmentation (stock, frame.objects, m_stock));

    std::printf (
        "%s: %zu points, %zu objects, tolerance %.4f m; mean best IoU: profiles %.3f "
        "(%zu segments, %zu correct), EuclideanClusterExtraction %.3f (%zu segments, "
        "%zu "
        "correct)\n",
        name,
        frame.cloud->size(),
        m_ours.segments.size(),
        profiles.getUsedDistanceThreshold(),
        m_ours.mean_best_iou,
        ours.size(),
        m_ours.correct,
        m_stock.mean_best_iou,
        stock.size(),
        m_stock.correct);
    // Every point lies in exactly one segment: proximity chaining drops nothing.
    std::size_t segmented = 0;
    for (const auto& s : ours)
      segmented += s.indices.size();
    EXPECT_EQ (segmented, frame.cloud->size()) << name;
  }
}
