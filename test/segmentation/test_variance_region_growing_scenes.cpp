/*
 * VarianceRegionGrowing on the generated `indoor` scene against its ground-truth surfaces (the
 * `segment` field: one id per true surface), next to pcl::RegionGrowing (k = 30, smoothness
 * 3 degrees, curvature threshold 1.0) on the normals and curvatures of the same k = 50
 * neighbourhoods, computed in the same run. Both keep segments of at least 50 points.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>
#include <map>

namespace
{
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

constexpr pcl::uindex_t kMinSize = 50;

struct Indoor
{
  pcl_ext::simulation::SyntheticScene scene;
  Cloud::Ptr cloud {new Cloud};
  pcl_ext::Neighbourhoods<Point>::Ptr nb {new pcl_ext::Neighbourhoods<Point>};
  std::vector<std::uint32_t> truth;  ///< the true surface of every point
  std::vector<pcl::PointIndices> ours, stock;
  pcl_ext::SegmentationMetrics m_ours, m_stock;
};

/** Share of the segmented points that lie on their segment's main true surface. */
double
purity (const std::vector<pcl::PointIndices>& clusters, const std::vector<std::uint32_t>& truth)
{
  std::size_t total = 0, main = 0;
  for (const auto& c : clusters)
  {
    std::map<std::uint32_t, std::size_t> count;
    std::size_t best = 0;
    for (const auto i : c.indices)
      best = std::max (best, ++count[truth[i]]);
    main += best;
    total += c.indices.size ();
  }
  return total ? static_cast<double> (main) / total : 0.0;
}

void
print (const std::string& name, const pcl_ext::SegmentationMetrics& m, double purity)
{
  std::cout << std::fixed << std::setprecision (3) << "  " << std::left << std::setw (22) << name
            << std::right << " mean best IoU " << m.mean_best_iou << " (weighted "
            << m.weighted_mean_best_iou << "), " << m.num_predicted_segments << " segments, "
            << m.correct << " correct, " << m.over_segmented << " over, " << m.under_segmented
            << " under, " << m.missed << " missed; unsegmented " << m.unsegmented_fraction
            << ", purity " << purity << "\n";
}

/** The scene (about 300,000 points, 2 scanners) and both segmentations, made once. */
const Indoor&
indoor ()
{
  static std::unique_ptr<Indoor> s;
  if (s)
    return *s;
  s.reset (new Indoor);
  pcl_ext::simulation::SceneParameters parameters;
  parameters.points = 300000;
  EXPECT_TRUE (pcl_ext::simulation::generateScene ("indoor", parameters, s->scene));
  for (const auto& p : s->scene.cloud)
  {
    s->cloud->push_back (Point (p.x, p.y, p.z));
    s->truth.push_back (p.segment);
  }
  s->nb->setInputCloud (s->cloud);
  s->nb->setKSearch (50);
  EXPECT_TRUE (s->nb->compute ());

  // Ours, with the paper's parameters (k = 50, variance tolerance 1e-4).
  pcl_ext::VarianceRegionGrowing<Point> rg;
  rg.setInputCloud (s->cloud);
  rg.setNeighbourhoods (s->nb);
  rg.setMinClusterSize (kMinSize);
  rg.extract (s->ours);

  // Stock PCL on the normals and curvatures (l0 / (l0 + l1 + l2), PCL's definition) of the
  // same neighbourhoods.
  pcl::PointCloud<pcl_ext::CovarianceFeatures> features;
  pcl_ext::CovarianceFeatureEstimation<Point> fe;
  fe.setInputCloud (s->cloud);
  fe.setNeighbourhoods (s->nb);
  fe.compute (features);
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  for (const auto& f : features)
    normals->push_back (pcl::Normal (f.normal_x, f.normal_y, f.normal_z, f.surface_variance));
  pcl::RegionGrowing<Point, pcl::Normal> stock;
  stock.setInputCloud (s->cloud);
  stock.setInputNormals (normals);
  stock.setSearchMethod (pcl::search::KdTree<Point>::Ptr (new pcl::search::KdTree<Point>));
  stock.setNumberOfNeighbours (30);
  stock.setSmoothnessThreshold (3.0 * M_PI / 180.0);
  stock.setCurvatureThreshold (1.0);
  stock.setMinClusterSize (kMinSize);
  stock.extract (s->stock);

  EXPECT_TRUE (pcl_ext::evaluateSegmentation (s->ours, s->truth, s->m_ours));
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (s->stock, s->truth, s->m_stock));
  std::cout << "[ indoor ] " << s->cloud->size () << " points, " << s->m_ours.num_truth_segments
            << " true surfaces\n";
  print ("VarianceRegionGrowing", s->m_ours, purity (s->ours, s->truth));
  print ("pcl::RegionGrowing", s->m_stock, purity (s->stock, s->truth));
  return *s;
}
}  // namespace

TEST (VarianceRegionGrowingScenes, IndoorSegmentsStopAtCreases)
{
  // Section 3: edge points are a cut line, so a segment does not run from one surface onto
  // another. Measured: 0.990 of the segmented points lie on their segment's main surface
  // (pcl::RegionGrowing: 0.996). The rest: a pipe's straight parts and elbow, which meet
  // tangentially with no crease, and the two faces of the 0.2 m interior wall, where the
  // k = 50 neighbourhoods of the sparser face reach the other (links of 0.19 m, which
  // setMaxDistance would cut).
  const Indoor& s = indoor ();
  ASSERT_GT (s.cloud->size (), 250000u);
  ASSERT_FALSE (s.ours.empty ());
  EXPECT_GE (purity (s.ours, s.truth), 0.98);
  // The floor, the largest surface seen whole from both rooms through the door, is one
  // segment less its crease bands (measured IoU 0.923).
  ASSERT_FALSE (s.m_ours.segments.empty ());
  EXPECT_EQ (s.m_ours.segments[0].truth_label, 1u);
  EXPECT_GE (s.m_ours.segments[0].iou, 0.9);
}

// Goal not met (300,000 points, paper parameters): mean best IoU 0.384 against 0.532 for
// pcl::RegionGrowing. Three reasons, measured on this scene:
// - 16 % of the points are left unsegmented (pcl::RegionGrowing: 5 %): the edge and boundary
//   points the classifier finds are cut lines and belong to no segment until section 4's
//   re-integration. On small surfaces (box faces, pipes) that is a large share: a box face of
//   1,443 points scores 0.73, a 139-point face 0 (all its points are edges).
// - the classifier's false edges near the scanners (5 mm noise over neighbourhoods a few cm
//   wide) and false boundaries along the silhouettes of the pipes and the column fragment
//   those surfaces (a 4,643-point wall: 56 % edges, IoU 0.14).
// - the ground truth gives one id to surfaces the interior wall cuts into two disconnected
//   parts (the ceiling and two long walls), which caps their best IoU near 0.5 for any region
//   growing, and counts six surfaces of fewer than 140 points that neither method segments.
// Variations measured: boundary points as surface 0.434, k = 30 0.452, variance tolerance
// 3e-4 0.386, 1,000,000 points 0.513 (pcl::RegionGrowing 0.633). The paper's whole workflow,
// with section 4's re-integration of edge and boundary points (LocalSurfaceIntersection,
// defaults), leaves 5 % unsegmented and scores 0.509 (0.647 at 1,000,000 points). Run with
// --gtest_also_run_disabled_tests.
TEST (VarianceRegionGrowingScenes, DISABLED_IndoorMeanBestIoUBeatsPclRegionGrowing)
{
  const Indoor& s = indoor ();
  EXPECT_GE (s.m_ours.mean_best_iou, 0.85);
  EXPECT_GE (s.m_ours.mean_best_iou, s.m_stock.mean_best_iou + 0.10);
}
