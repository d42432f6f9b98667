/*
 * Belton & Lichti's classification and region growing together (2006, sections 2 and
 * 3): segments of analytic shapes, the classifier's options, shared neighbourhoods,
 * plane fits, determinism and bad input.
 */
#include "../features/analytic_clouds.h"
#include "../segmentation/variance_test_clouds.h"

#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/evaluation/segmentation_metrics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Growing = pcl_ext::VarianceRegionGrowing<Point>;
using Labels = pcl::PointCloud<pcl::Label>;

/** Classify with the classifier's defaults (the growing's thread count), then grow. */
void
segment (Growing& rg, std::vector<pcl::PointIndices>& clusters)
{
  pcl_ext::LocalVarianceClassification<Point> classifier;
  classifier.setNumberOfThreads (rg.getNumberOfThreads());
  pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
}
} // namespace

TEST (SegmentByLocalVariance, CubeFacesAreSegmentsAndEdgesStopTheGrowth)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  segment (rg, clusters);
  ASSERT_EQ (clusters.size(), 6u);
  const auto faces = pcl_ext::test::cubeFaces (*cube.cloud, 1.0);
  pcl_ext::SegmentationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, faces, m));
  // Each segment lies on one face (edges cut the faces apart), a different one each ...
  std::set<std::uint32_t> found;
  for (const auto& c : clusters) {
    std::size_t same = 0;
    for (const auto i : c.indices)
      same += faces[i] == faces[c.indices.front()];
    EXPECT_EQ (same, c.indices.size());
    found.insert (faces[c.indices.front()]);
  }
  EXPECT_EQ (found.size(), 6u);
  // ... less a band along its four creases where the neighbourhoods reach across:
  // radius r = sqrt(50 / pi) * 0.02 = 0.080 for 50 neighbours at spacing 0.02, IoU (1 -
  // 2 r)^2.
  const double r = std::sqrt (50.0 / M_PI) * 0.02;
  for (const auto& s : m.segments)
    EXPECT_NEAR (s.iou, (1 - 2 * r) * (1 - 2 * r), 0.05) << "face " << s.truth_label;
  // ... and what is left out lies near a crease: within the k = 50 neighbourhood
  // radius, about 4 spacings for a 50-point disc at spacing 0.02.
  Labels labels;
  rg.getSegmentLabels (labels);
  ASSERT_EQ (labels.size(), cube.cloud->size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i].label == 0)
      EXPECT_LT (cube.crease_distance[i], 0.1) << "point " << i;
  // Largest first, indices sorted.
  for (std::size_t c = 1; c < clusters.size(); ++c)
    EXPECT_GE (clusters[c - 1].indices.size(), clusters[c].indices.size());
  for (const auto& c : clusters)
    EXPECT_TRUE (std::is_sorted (c.indices.begin(), c.indices.end()));
}

TEST (SegmentByLocalVariance, OnePlaneIsOneSegment)
{
  const auto plane = pcl_ext::test::makePlane (2.0, 0.02, 0.3, 0.001);
  Growing rg;
  rg.setInputCloud (plane.cloud);
  std::vector<pcl::PointIndices> clusters;
  segment (rg, clusters);
  ASSERT_GE (clusters.size(), 1u);
  // Every surface point of the plane is in the first segment; only boundary points (and
  // perhaps a few isolated surface points among them) are left.
  const auto& classes = *rg.getInputClasses();
  std::size_t surface = 0;
  for (const auto& c : classes)
    surface += c.label == static_cast<std::uint32_t> (pcl_ext::PointClass::Surface);
  EXPECT_GE (clusters[0].indices.size(), surface - surface / 100);
  EXPECT_GT (clusters[0].indices.size(), plane.cloud->size() * 8 / 10);
}

TEST (SegmentByLocalVariance, DeterministicForAnyThreadCountAndRun)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.003);
  std::vector<pcl::PointIndices> reference;
  for (const unsigned threads : {1u, 2u, 3u, 4u, 1u}) {
    Growing rg;
    rg.setInputCloud (cube.cloud);
    rg.setNumberOfThreads (threads);
    std::vector<pcl::PointIndices> clusters;
    segment (rg, clusters);
    ASSERT_FALSE (clusters.empty());
    if (reference.empty()) {
      reference = clusters;
      continue;
    }
    ASSERT_EQ (clusters.size(), reference.size()) << threads << " threads";
    for (std::size_t c = 0; c < clusters.size(); ++c)
      EXPECT_EQ (clusters[c].indices, reference[c].indices) << threads << " threads";
  }
}

TEST (SegmentByLocalVariance, SharedNeighbourhoodsGiveTheSameSegments)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.025, 0.001);
  pcl_ext::Neighbourhoods<Point>::Ptr nb (new pcl_ext::Neighbourhoods<Point>);
  nb->setInputCloud (cube.cloud);
  nb->setKSearch (50);
  ASSERT_TRUE (nb->compute());
  Growing own, shared;
  own.setInputCloud (cube.cloud);
  shared.setInputCloud (cube.cloud);
  shared.setNeighbourhoods (nb);
  std::vector<pcl::PointIndices> a, b;
  segment (own, a);
  segment (shared, b);
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t c = 0; c < a.size(); ++c)
    EXPECT_EQ (a[c].indices, b[c].indices);
  // Neighbourhoods of another cloud are not used (a warning, then a search of its own).
  const auto other = pcl_ext::test::makePlane (1.0, 0.05);
  Growing mismatched;
  mismatched.setInputCloud (cube.cloud);
  mismatched.setNeighbourhoods (
      pcl_ext::Neighbourhoods<Point>::Ptr (new pcl_ext::Neighbourhoods<Point>));
  segment (mismatched, b);
  ASSERT_EQ (a.size(), b.size());
}

TEST (SegmentByLocalVariance, GrowsOnTheClassesOfTheClassifierWithItsOptions)
{
  // The classifier's options beyond the paper shape the classes grown on: they are
  // those of LocalVarianceClassification with the same options, whether the growing
  // searches itself (k = 50 capped at a radius) or is given shared neighbourhoods, for
  // 1 and 2 threads.
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.003);
  pcl_ext::LocalVarianceClassification<Point> lvc;
  lvc.setInputCloud (cube.cloud);
  lvc.setNoiseStandardDeviation (0.003);
  lvc.setBoundaryBand (true);
  lvc.setMaxRadius (0.06);
  pcl::PointCloud<pcl::Label> expected;
  lvc.classify (expected);
  ASSERT_EQ (expected.size(), cube.cloud->size());
  auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
  nb->setInputCloud (cube.cloud);
  nb->setKSearch (50);
  nb->setMaxRadius (0.06);
  ASSERT_TRUE (nb->compute());
  std::vector<pcl::PointIndices> reference;
  for (const unsigned threads : {1u, 2u})
    for (const bool shared : {false, true}) {
      pcl_ext::LocalVarianceClassification<Point> classifier;
      classifier.setNoiseStandardDeviation (0.003);
      classifier.setBoundaryBand (true);
      classifier.setNumberOfThreads (threads);
      Growing rg;
      rg.setInputCloud (cube.cloud);
      rg.setMaxRadius (0.06);
      rg.setNumberOfThreads (threads);
      rg.setMinClusterSize (100);
      if (shared)
        rg.setNeighbourhoods (nb);
      std::vector<pcl::PointIndices> clusters;
      pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
      EXPECT_EQ (clusters.size(), 6u); // the faces
      ASSERT_TRUE (rg.getInputClasses());
      const auto& classes = *rg.getInputClasses();
      ASSERT_EQ (classes.size(), expected.size());
      std::size_t differ = 0;
      for (std::size_t i = 0; i < classes.size(); ++i)
        differ += classes[i].label != expected[i].label;
      EXPECT_EQ (differ, 0u) << threads << " threads, shared " << shared;
      if (reference.empty())
        reference = clusters;
      ASSERT_EQ (clusters.size(), reference.size());
      for (std::size_t c = 0; c < clusters.size(); ++c)
        EXPECT_EQ (clusters[c].indices, reference[c].indices);
    }
  // The same classes given by hand to the growing give the same segments.
  Growing given;
  given.setInputCloud (cube.cloud);
  given.setNeighbourhoods (nb);
  given.setInputClasses (pcl::make_shared<pcl::PointCloud<pcl::Label>> (expected));
  given.setMinClusterSize (100);
  std::vector<pcl::PointIndices> clusters;
  given.extract (clusters);
  ASSERT_EQ (clusters.size(), reference.size());
  for (std::size_t c = 0; c < clusters.size(); ++c)
    EXPECT_EQ (clusters[c].indices, reference[c].indices);
}

TEST (SegmentByLocalVariance, FitsPlanesToTheSegments)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  segment (rg, clusters);
  EXPECT_TRUE (rg.getSegmentPlanes().empty()); // off by default
  rg.setFitPlanes (true);
  segment (rg, clusters);
  const auto& planes = rg.getSegmentPlanes();
  ASSERT_EQ (planes.size(), clusters.size());
  ASSERT_EQ (planes.size(), 6u);
  for (const auto& plane : planes) {
    ASSERT_TRUE (plane.isValid());
    // Each face is axis-aligned at 0 or 1, the noise is 1 mm along its normal.
    EXPECT_GT (plane.normal.cwiseAbs().maxCoeff(), 0.9999);
    EXPECT_NEAR (std::abs (plane.d), std::abs (plane.d) < 0.5 ? 0.0 : 1.0, 1e-3);
    EXPECT_LT (plane.rms, 0.0015);
  }
}

TEST (SegmentByLocalVariance, NaNPointsAreNeverSegmented)
{
  // The cube with every 7th point replaced by NaN (is_dense false): same faces, and no
  // NaN point in a segment.
  auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < cube.cloud->size(); i += 7)
    (*cube.cloud)[i].x = nan;
  cube.cloud->is_dense = false;
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  segment (rg, clusters);
  ASSERT_EQ (clusters.size(), 6u);
  for (const auto& c : clusters)
    for (const auto i : c.indices)
      EXPECT_NE (i % 7, 0) << "NaN point " << i << " segmented";
  // A cloud claiming to be dense while holding NaN points is treated the same.
  cube.cloud->is_dense = true;
  std::vector<pcl::PointIndices> dense_claim;
  segment (rg, dense_claim);
  ASSERT_EQ (dense_claim.size(), clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c)
    EXPECT_EQ (dense_claim[c].indices, clusters[c].indices);
}

TEST (SegmentByLocalVariance, CollinearPointsHaveNoSurfaceToGrowFrom)
{
  // Points that are all collinear have no tangent plane: all unknown, so no segment.
  Cloud::Ptr line (new Cloud);
  for (int i = 0; i < 200; ++i)
    line->push_back (Point (0.01f * i, 0.f, 0.f));
  Growing on_line;
  on_line.setInputCloud (line);
  on_line.setKSearch (10);
  std::vector<pcl::PointIndices> clusters{pcl::PointIndices()};
  segment (on_line, clusters);
  EXPECT_TRUE (clusters.empty());
  ASSERT_TRUE (on_line.getInputClasses());
  for (const auto& c : *on_line.getInputClasses())
    EXPECT_EQ (c.label, 0u);
}

TEST (SegmentByLocalVariance, NoCloudAndNonsenseParameters)
{
  std::vector<pcl::PointIndices> clusters{pcl::PointIndices()};
  Growing none;
  segment (none, clusters);
  EXPECT_TRUE (clusters.empty());
  const auto cloud = pcl_ext::test::twoPatches (1.0);
  using Classifier = pcl_ext::LocalVarianceClassification<Point>;
  const auto fails = [&] (const std::function<void (Classifier&, Growing&)>& set) {
    Classifier classifier;
    Growing rg;
    rg.setInputCloud (cloud);
    set (classifier, rg);
    clusters.resize (1);
    pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
    return clusters.empty();
  };
  EXPECT_FALSE (fails ([] (Classifier&, Growing&) {}));
  EXPECT_TRUE (
      fails ([] (Classifier& c, Growing&) { c.setNoiseStandardDeviation (-0.001); }));
  EXPECT_TRUE (
      fails ([] (Classifier& c, Growing&) { c.setNoiseStandardDeviation (NAN); }));
  EXPECT_TRUE (fails ([] (Classifier& c, Growing&) { c.setVarianceThreshold (-1.0); }));
  EXPECT_TRUE (fails ([] (Classifier& c, Growing&) { c.setCurvatureThreshold (NAN); }));
  EXPECT_TRUE (
      fails ([] (Classifier& c, Growing&) { c.setCurvatureThresholdFactor (-1.0); }));
  EXPECT_TRUE (fails ([] (Classifier& c, Growing&) { c.setConfidence (1.0); }));
  EXPECT_TRUE (fails ([] (Classifier&, Growing& rg) { rg.setKSearch (2); }));
  EXPECT_TRUE (fails ([] (Classifier&, Growing& rg) { rg.setKSearch (100000); }));
  EXPECT_TRUE (fails ([] (Classifier&, Growing& rg) { rg.setMaxRadius (-1.0); }));
  EXPECT_TRUE (fails ([] (Classifier&, Growing& rg) { rg.setMinClusterSize (0); }));
}
