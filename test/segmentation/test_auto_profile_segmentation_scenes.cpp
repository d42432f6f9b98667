/*
 * pcl_ext::AutoProfileSegmentation with its defaults on the generated scenes of Sithole
 * & Mapurisa's section 5, at two seeds that were not used to choose the defaults (seeds
 * 1-3 were). The goals are those of the method's issue; the figures of every seed are
 * in docs/sithole_mapurisa.md. (`coaxial` at the same seeds is tested through the tool:
 * SegmentProfilesApp.DefaultsSeparateTheCoaxialSurfacesOfUnseenSeeds.) On `indoor` the
 * peer is pcl::EuclideanClusterExtraction with the distance the segmentation linked
 * points at.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {
constexpr std::uint64_t kUnseenSeeds[] = {5, 9};

/** A generated scene segmented with the defaults, and its truth. */
struct Segmented {
  pcl_ext::simulation::SyntheticScene scene;
  std::vector<std::uint32_t> truth;
  pcl_ext::SegmentationMetrics metrics;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  double link_distance = 0.0; ///< the distance threshold the last extract() used
};

void
segmentScene (const std::string& name,
              std::uint64_t seed,
              bool surfaces,
              Segmented& out)
{
  pcl_ext::simulation::SceneParameters parameters;
  parameters.seed = seed;
  ASSERT_TRUE (pcl_ext::simulation::generateScene (name, parameters, out.scene));
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  out.truth.clear();
  for (const auto& p : out.scene.cloud) {
    cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    out.truth.push_back (surfaces ? p.segment : p.object);
  }
  pcl_ext::AutoProfileSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setNumberOfThreads (2);
  std::vector<pcl::PointIndices> segments;
  seg.extract (segments);
  ASSERT_FALSE (segments.empty());
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (segments, out.truth, out.metrics));
  out.cloud = cloud;
  out.link_distance = seg.getUsedDistanceThreshold();
}

/** Mean best IoU over the truth segments of which most points carry \a label. */
double
meanIoUOfLabel (const Segmented& s, std::uint32_t label)
{
  std::map<std::uint32_t, std::size_t> of_label, total;
  for (std::size_t i = 0; i < s.truth.size(); ++i) {
    ++total[s.truth[i]];
    of_label[s.truth[i]] += s.scene.cloud[i].label == label;
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& match : s.metrics.segments)
    if (2 * of_label[match.truth_label] > total[match.truth_label]) {
      sum += match.iou;
      ++count;
    }
  return count ? sum / static_cast<double> (count) : 0.0;
}

/** Best IoU of the truth segment holding most of the points of \a label below \a z. */
double
iouOfDominantSegment (const Segmented& s, std::uint32_t label, float z)
{
  std::map<std::uint32_t, std::size_t> below;
  for (std::size_t i = 0; i < s.truth.size(); ++i)
    if (s.scene.cloud[i].label == label && s.scene.cloud[i].z < z)
      ++below[s.truth[i]];
  std::uint32_t dominant = 0;
  std::size_t most = 0;
  for (const auto& [segment, count] : below)
    if (count > most) {
      most = count;
      dominant = segment;
    }
  for (const auto& match : s.metrics.segments)
    if (match.truth_label == dominant)
      return match.iou;
  return 0.0;
}
} // namespace

TEST (AutoProfileSegmentationScenes, CubesAreOneObjectEach)
{
  for (const auto seed : kUnseenSeeds) {
    Segmented s;
    segmentScene ("cubes", seed, false, s);
    std::printf ("cubes seed %d: objects %.3f\n", int (seed), s.metrics.mean_best_iou);
    EXPECT_GE (s.metrics.mean_best_iou, 0.98) << "seed " << seed;
  }
}

TEST (AutoProfileSegmentationScenes, NestedSpheresAreOneObjectEach)
{
  for (const auto seed : kUnseenSeeds) {
    Segmented s;
    segmentScene ("spheres", seed, false, s);
    std::printf (
        "spheres seed %d: objects %.3f\n", int (seed), s.metrics.mean_best_iou);
    EXPECT_GE (s.metrics.mean_best_iou, 0.95) << "seed " << seed;
  }
}

TEST (AutoProfileSegmentationScenes, PipesAreOneSegmentEach)
{
  constexpr std::uint32_t kPipe = 3; // the scene's pipe label
  for (const auto seed : kUnseenSeeds) {
    Segmented s;
    segmentScene ("pipes", seed, false, s);
    const double pipes = meanIoUOfLabel (s, kPipe);
    std::printf ("pipes seed %d: the pipes %.3f\n", int (seed), pipes);
    EXPECT_GE (pipes, 0.85) << "seed " << seed;
  }
}

TEST (AutoProfileSegmentationScenes, TreeTrunkIsOneSegment)
{
  const auto trunk_label =
      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Trunk);
  for (const auto seed : kUnseenSeeds) {
    Segmented s;
    segmentScene ("tree", seed, true, s);
    const double trunk = iouOfDominantSegment (s, trunk_label, 3.0f);
    std::printf ("tree seed %d: the trunk %.3f\n", int (seed), trunk);
    EXPECT_GE (trunk, 0.85) << "seed " << seed;
  }
}

TEST (AutoProfileSegmentationScenes, IndoorObjectsAtLeastAsGoodAsEuclideanClustering)
{
  for (const auto seed : kUnseenSeeds) {
    Segmented s;
    segmentScene ("indoor", seed, false, s);
    ASSERT_GT (s.link_distance, 0.0);
    pcl::EuclideanClusterExtraction<pcl::PointXYZ> euclidean;
    euclidean.setInputCloud (s.cloud);
    euclidean.setSearchMethod (pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
    euclidean.setClusterTolerance (s.link_distance);
    euclidean.setMinClusterSize (1);
    std::vector<pcl::PointIndices> clusters;
    euclidean.extract (clusters);
    pcl_ext::SegmentationMetrics peer;
    ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, s.truth, peer));
    std::printf (
        "indoor seed %d: objects %.3f, EuclideanClusterExtraction (%.3f m) %.3f\n",
        int (seed),
        s.metrics.mean_best_iou,
        s.link_distance,
        peer.mean_best_iou);
    EXPECT_GE (s.metrics.mean_best_iou, peer.mean_best_iou) << "seed " << seed;
  }
}
