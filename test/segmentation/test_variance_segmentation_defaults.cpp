/*
 * Belton & Lichti's segmentation with the defaults of pcl_ext_segment_variance (k = 50,
 * the classification's defaults, region growing, section 4's re-integration, new
 * segments among the points left out, segments of at least 50 points, interleaved
 * pieces of one plane merged, the points left over put where they fit) on generated
 * scenes at seeds that were not used to choose them, against pcl::RegionGrowing
 * as PCL's region-growing tutorial sets it (normals of 50 neighbours, growing over 30,
 * smoothness 3 degrees, curvature threshold 1.0, segments of at least 50 points).
 * Nothing is taken from the generator but the truth. The figures of every family and
 * seed are in docs/belton_lichti.md.
 */
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <utility>
#include <vector>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

constexpr std::uint64_t kDefaultsUnseenSeeds[] = {5, 9};
constexpr unsigned int kDefaultsMinSize = 50; // pcl_ext_segment_variance's -min_size
constexpr unsigned int kThreads = 2;

/** The segment of every point as pcl_ext_segment_variance gives it with its defaults
 * (0: none). */
std::vector<std::uint32_t>
segmentWithDefaults (const Cloud::ConstPtr& cloud)
{
  auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  nb->setInputCloud (cloud);
  nb->setKSearch (50);
  nb->setNumberOfThreads (kThreads);
  nb->setStoreSquaredDistances (false);
  EXPECT_TRUE (nb->compute());
  pcl_ext::LocalVarianceClassification<Point> classifier;
  classifier.setNumberOfThreads (kThreads);
  pcl_ext::VarianceRegionGrowing<Point> rg;
  rg.setInputCloud (cloud);
  rg.setNeighbourhoods (nb);
  rg.setMinClusterSize (kDefaultsMinSize);
  rg.setNumberOfThreads (kThreads);
  std::vector<pcl::PointIndices> clusters;
  pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
  EXPECT_FALSE (clusters.empty());
  auto labels = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  rg.getSegmentLabels (*labels);
  pcl_ext::LocalSurfaceIntersection<Point> lsi;
  lsi.setInputCloud (cloud);
  lsi.setNeighbourhoods (nb);
  lsi.setSegmentLabels (labels);
  lsi.setPointClasses (rg.getInputClasses());
  lsi.setNumberOfThreads (kThreads);
  pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
  pcl::PointCloud<pcl::Label> reintegrated;
  EXPECT_TRUE (lsi.compute (intersections, reintegrated));
  pcl_ext::LeftoverRegionGrowing<Point> leftovers;
  leftovers.setInputCloud (cloud);
  leftovers.setNeighbourhoods (nb);
  leftovers.setSegmentLabels (
      pcl::make_shared<pcl::PointCloud<pcl::Label>> (reintegrated));
  leftovers.setMinClusterSize (kDefaultsMinSize);
  leftovers.setNumberOfThreads (kThreads);
  auto grown = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  EXPECT_TRUE (leftovers.compute (*grown));
  pcl_ext::CoplanarSegmentMerging<Point> merging;
  merging.setInputCloud (cloud);
  merging.setNeighbourhoods (nb);
  merging.setSegmentLabels (grown);
  merging.setNumberOfThreads (kThreads);
  auto merged = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  EXPECT_TRUE (merging.compute (*merged));
  pcl_ext::LeftoverPlaneAssignment<Point> assignment;
  assignment.setInputCloud (cloud);
  assignment.setNeighbourhoods (nb);
  assignment.setSegmentLabels (merged);
  assignment.setNumberOfThreads (kThreads);
  pcl::PointCloud<pcl::Label> assigned;
  EXPECT_TRUE (assignment.compute (assigned));
  std::vector<std::uint32_t> ids;
  for (const auto& l : assigned)
    ids.push_back (l.label);
  return ids;
}

/** pcl::RegionGrowing as PCL's tutorial chains it. */
std::vector<pcl::PointIndices>
segmentWithPcl (const Cloud::ConstPtr& cloud)
{
  auto tree = pcl::make_shared<pcl::search::KdTree<Point>>();
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  pcl::NormalEstimationOMP<Point, pcl::Normal> ne (kThreads);
  ne.setInputCloud (cloud);
  ne.setSearchMethod (tree);
  ne.setKSearch (50);
  ne.compute (*normals);
  pcl::RegionGrowing<Point, pcl::Normal> rg;
  rg.setInputCloud (cloud);
  rg.setInputNormals (normals);
  rg.setSearchMethod (tree);
  rg.setNumberOfNeighbours (30);
  rg.setSmoothnessThreshold (3.0 * M_PI / 180.0);
  rg.setCurvatureThreshold (1.0);
  rg.setMinClusterSize (kDefaultsMinSize);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  return clusters;
}
} // namespace

/** Mean best IoU of the defaults and of pcl::RegionGrowing on generated \a family at
 * \a seed, printed. */
std::pair<double, double>
scoreBoth (const char* family, std::uint64_t seed, int superfluous_planes = 0)
{
  pcl_ext::simulation::SceneParameters parameters;
  parameters.seed = seed;
  parameters.superfluous_planes = superfluous_planes;
  pcl_ext::simulation::SyntheticScene scene;
  EXPECT_TRUE (pcl_ext::simulation::generateScene (family, parameters, scene));
  auto cloud = pcl::make_shared<Cloud>();
  std::vector<std::uint32_t> truth;
  for (const auto& p : scene.cloud) {
    cloud->push_back (Point (p.x, p.y, p.z));
    truth.push_back (p.segment);
  }
  pcl_ext::SegmentationMetrics ours, pcl;
  EXPECT_TRUE (
      pcl_ext::evaluateSegmentation (segmentWithDefaults (cloud), truth, ours));
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (segmentWithPcl (cloud), truth, pcl));
  std::printf ("%s seed %d: pcl_ext %.3f, pcl::RegionGrowing %.3f\n",
               family,
               static_cast<int> (seed),
               ours.mean_best_iou,
               pcl.mean_best_iou);
  return {ours.mean_best_iou, pcl.mean_best_iou};
}

// The goals on indoor: at least 0.70, and 0.10 ahead of pcl::RegionGrowing.
TEST (VarianceSegmentationDefaults, IndoorUnseenSeedsAheadOfPclRegionGrowing)
{
  for (const auto seed : kDefaultsUnseenSeeds) {
    const auto [ours, pcl] = scoreBoth ("indoor", seed);
    EXPECT_GE (ours, 0.70) << "seed " << seed;
    EXPECT_GE (ours, pcl + 0.10) << "seed " << seed;
  }
}

// The same lead on pipes, whose small pipes and narrow faces have no surface point to
// grow from: the new segments among the points left out are what finds them.
TEST (VarianceSegmentationDefaults, PipesUnseenSeedsAheadOfPclRegionGrowing)
{
  for (const auto seed : kDefaultsUnseenSeeds) {
    const auto [ours, pcl] = scoreBoth ("pipes", seed);
    EXPECT_GE (ours, pcl + 0.10) << "seed " << seed;
  }
}

// Building with two superfluous planes (a neighbouring building and an interior wall
// seen through the windows, sparse at 40-60 m): their scan lines and stations' grids,
// each a segment after sections 3 and 4, merged into whole planes, and the roof's
// patches seen from the ground with them, put the defaults ahead of
// pcl::RegionGrowing (0.804 against 0.815 without the merging and the assignment).
TEST (VarianceSegmentationDefaults, BuildingUnseenSeedsAheadOfPclRegionGrowing)
{
  for (const auto seed : kDefaultsUnseenSeeds) {
    const auto [ours, pcl] = scoreBoth ("building", seed, 2);
    EXPECT_GT (ours, pcl + 0.02) << "seed " << seed;
  }
}
