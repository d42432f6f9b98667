/*
 * VarianceRegionGrowing (Belton & Lichti 2006, section 3): the walk rules on hand-made
 * neighbourhoods, segments of analytic shapes, plane fits, determinism and bad input.
 */
#include "../features/analytic_clouds.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <set>

namespace
{
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Growing = pcl_ext::VarianceRegionGrowing<Point>;
using Labels = pcl::PointCloud<pcl::Label>;
constexpr std::int8_t S = 1, E = 2, B = 3;  // PointClass values
const float kNoLimit = std::numeric_limits<float>::infinity ();

/** Rows as the kernel takes them, written as lists of (neighbour, distance). */
struct Rows
{
  std::vector<std::size_t> offsets {0};
  pcl::Indices neighbours;
  std::vector<float> sqr_distances;
  pcl::Indices points;

  void
  add (pcl::index_t point, const std::vector<std::pair<pcl::index_t, float>>& row)
  {
    points.push_back (point);
    for (const auto& [j, d] : row)
    {
      neighbours.push_back (j);
      sqr_distances.push_back (d * d);
    }
    offsets.push_back (neighbours.size ());
  }

  std::vector<std::int32_t>
  grow (const std::vector<std::int8_t>& classes, float max_sqr = kNoLimit) const
  {
    std::vector<std::int32_t> root;
    pcl_ext::growSurfaceSegments (offsets, neighbours, sqr_distances, points, classes, max_sqr,
                                  1, root);
    return root;
  }
};

/** Which face of the cube [0, size]^3 a point lies on (1..6); points on an edge of the cube
  * get the face of the coordinate closest to a face plane. */
std::vector<std::uint32_t>
cubeFaces (const Cloud& cloud, double size)
{
  std::vector<std::uint32_t> faces;
  for (const auto& p : cloud)
  {
    const double c[3] = {p.x, p.y, p.z};
    int best = 0;
    double best_d = 1e30;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        const double d = std::abs (c[axis] - side * size);
        if (d < best_d)
        {
          best_d = d;
          best = 2 * axis + side + 1;
        }
      }
    faces.push_back (static_cast<std::uint32_t> (best));
  }
  return faces;
}

Labels::Ptr
uniformClasses (std::size_t n, std::uint32_t c)
{
  Labels::Ptr labels (new Labels);
  labels->resize (n);
  for (auto& l : *labels)
    l.label = c;
  return labels;
}

/** Two unit squares side by side in z = 0 with a gap between them (spacing 0.05). */
Cloud::Ptr
twoPatches (double gap)
{
  Cloud::Ptr cloud (new Cloud);
  for (int patch = 0; patch < 2; ++patch)
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j)
        cloud->push_back (Point (static_cast<float> (patch * (1.0 + gap) + 0.05 * i),
                                 static_cast<float> (0.05 * j), 0.f));
  return cloud;
}
}  // namespace

// ---------------------------------------------------------------------------------------------
// The walk (section 3 and the corrected figure 4), on hand-made rows.

TEST (GrowSurfaceSegments, UnlabelledSurfaceNeighboursJoin)
{
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (1, {{1, 0.f}});
  rows.add (2, {{2, 0.f}});
  const auto root = rows.grow ({S, S, S});
  EXPECT_EQ (root, (std::vector<std::int32_t> {0, 0, 0}));
}

TEST (GrowSurfaceSegments, NonSurfaceNeighbourStopsTheWalk)
{
  // Point 0's list: itself, the edge point 1, then surface point 2: 2 is beyond the stop.
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (1, {{1, 0.f}, {0, 1.f}, {2, 1.f}});
  rows.add (2, {{2, 0.f}, {1, 1.f}, {0, 2.f}});
  for (const std::int8_t stop : {E, B, std::int8_t (0)})
  {
    const auto root = rows.grow ({S, stop, S});
    EXPECT_EQ (root, (std::vector<std::int32_t> {0, -1, 2})) << "class " << int (stop);
  }
  // Without the stop, 0 and 2 link.
  EXPECT_EQ (rows.grow ({S, S, S}), (std::vector<std::int32_t> {0, 0, 0}));
}

TEST (GrowSurfaceSegments, SurfaceNeighbourOfAnotherSegmentMerges)
{
  // 3 - 2 and 1 - 0 grow apart (in row order 3, 1 first); then 2's walk reaches 1: one
  // segment, whose root is its smallest index whatever the order of the rows.
  Rows rows;
  rows.add (3, {{3, 0.f}, {2, 1.f}});
  rows.add (1, {{1, 0.f}, {0, 1.f}});
  rows.add (2, {{2, 0.f}, {1, 1.f}, {4, 1.5f}});
  rows.add (0, {{0, 0.f}});
  rows.add (4, {{4, 0.f}});
  const auto root = rows.grow ({S, S, S, S, E});
  EXPECT_EQ (root, (std::vector<std::int32_t> {0, 0, 0, 0, -1}));
}

TEST (GrowSurfaceSegments, MaximumDistanceFromTheSeedStopsTheWalk)
{
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 0.5f}, {2, 2.0f}});
  rows.add (1, {{1, 0.f}});
  rows.add (2, {{2, 0.f}});
  EXPECT_EQ (rows.grow ({S, S, S}, 1.0f), (std::vector<std::int32_t> {0, 0, 2}));
  EXPECT_EQ (rows.grow ({S, S, S}, 4.0f), (std::vector<std::int32_t> {0, 0, 0}));
}

TEST (GrowSurfaceSegments, PointsOutsideTheIndicesAreSkipped)
{
  // Point 1 is not segmented (-1): the walk passes over it to 2.
  Rows rows;
  rows.add (0, {{0, 0.f}, {1, 1.f}, {2, 2.f}});
  rows.add (2, {{2, 0.f}});
  EXPECT_EQ (rows.grow ({S, -1, S}), (std::vector<std::int32_t> {0, -1, 0}));
}

// ---------------------------------------------------------------------------------------------
// Segments of analytic shapes, with the classification computed inside.

TEST (VarianceRegionGrowing, CubeFacesAreSegmentsAndEdgesStopTheGrowth)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 6u);
  const auto faces = cubeFaces (*cube.cloud, 1.0);
  pcl_ext::SegmentationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, faces, m));
  // Each segment lies on one face (edges cut the faces apart), a different one each ...
  std::set<std::uint32_t> found;
  for (const auto& c : clusters)
  {
    std::size_t same = 0;
    for (const auto i : c.indices)
      same += faces[i] == faces[c.indices.front ()];
    EXPECT_EQ (same, c.indices.size ());
    found.insert (faces[c.indices.front ()]);
  }
  EXPECT_EQ (found.size (), 6u);
  // ... less a band along its four creases where the neighbourhoods reach across: radius
  // r = sqrt(50 / pi) * 0.02 = 0.080 for 50 neighbours at spacing 0.02, IoU (1 - 2 r)^2.
  const double r = std::sqrt (50.0 / M_PI) * 0.02;
  for (const auto& s : m.segments)
    EXPECT_NEAR (s.iou, (1 - 2 * r) * (1 - 2 * r), 0.05) << "face " << s.truth_label;
  // ... and what is left out lies near a crease: within the k = 50 neighbourhood radius,
  // about 4 spacings for a 50-point disc at spacing 0.02.
  Labels labels;
  rg.getSegmentLabels (labels);
  ASSERT_EQ (labels.size (), cube.cloud->size ());
  for (std::size_t i = 0; i < labels.size (); ++i)
    if (labels[i].label == 0)
      EXPECT_LT (cube.crease_distance[i], 0.1) << "point " << i;
  // Largest first, indices sorted.
  for (std::size_t c = 1; c < clusters.size (); ++c)
    EXPECT_GE (clusters[c - 1].indices.size (), clusters[c].indices.size ());
  for (const auto& c : clusters)
    EXPECT_TRUE (std::is_sorted (c.indices.begin (), c.indices.end ()));
}

TEST (VarianceRegionGrowing, OnePlaneIsOneSegment)
{
  const auto plane = pcl_ext::test::makePlane (2.0, 0.02, 0.3, 0.001);
  Growing rg;
  rg.setInputCloud (plane.cloud);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_GE (clusters.size (), 1u);
  // Every surface point of the plane is in the first segment; only boundary points (and
  // perhaps a few isolated surface points among them) are left.
  const auto& classes = rg.getClassification ();
  std::size_t surface = 0;
  for (const auto& c : classes)
    surface += c.label == static_cast<std::uint32_t> (pcl_ext::PointClass::Surface);
  EXPECT_GE (clusters[0].indices.size (), surface - surface / 100);
  EXPECT_GT (clusters[0].indices.size (), plane.cloud->size () * 8 / 10);
}

TEST (VarianceRegionGrowing, DeterministicForAnyThreadCountAndRun)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.003);
  std::vector<pcl::PointIndices> reference;
  for (const unsigned threads : {1u, 2u, 3u, 4u, 1u})
  {
    Growing rg;
    rg.setInputCloud (cube.cloud);
    rg.setNumberOfThreads (threads);
    std::vector<pcl::PointIndices> clusters;
    rg.extract (clusters);
    ASSERT_FALSE (clusters.empty ());
    if (reference.empty ())
    {
      reference = clusters;
      continue;
    }
    ASSERT_EQ (clusters.size (), reference.size ()) << threads << " threads";
    for (std::size_t c = 0; c < clusters.size (); ++c)
      EXPECT_EQ (clusters[c].indices, reference[c].indices) << threads << " threads";
  }
}

TEST (VarianceRegionGrowing, MaximumDistanceSeparatesPatches)
{
  // Two patches 0.2 apart, every point called surface: with k = 50 the neighbourhoods of the
  // facing rows reach across the gap, so without a limit the patches are one segment.
  const auto cloud = twoPatches (0.2);
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setClassification (uniformClasses (cloud->size (), 1));
  rg.setMaxDistanceFactor (0.0);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 1u);
  EXPECT_EQ (clusters[0].indices.size (), cloud->size ());
  rg.setMaxDistance (0.15);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 2u);
  EXPECT_EQ (clusters[0].indices.size (), 441u);
  EXPECT_EQ (clusters[1].indices.size (), 441u);
  EXPECT_EQ (clusters[1].indices.front (), 441);  // ties: smallest index first
}

TEST (VarianceRegionGrowing, MaximumDistanceFactorFollowsTheSpacing)
{
  // The same two patches at two scales: spacing 0.05 with a 0.2 gap, and both doubled. A
  // limit of twice the local spacing (s = r_m sqrt(pi / m), m = 24 of k = 50: about 0.05
  // inside a patch, more on its border, where the m-th neighbour is farther) separates them at
  // both scales, as the limit scales with the sampling. Without a limit both are one segment.
  for (const double scale : {1.0, 2.0})
  {
    const auto base = twoPatches (0.2);
    Cloud::Ptr cloud (new Cloud);
    for (const auto& p : *base)
      cloud->push_back (
          Point (static_cast<float> (scale * p.x), static_cast<float> (scale * p.y), 0.f));
    Growing rg;
    rg.setInputCloud (cloud);
    rg.setClassification (uniformClasses (cloud->size (), 1));
    std::vector<pcl::PointIndices> clusters;
    rg.setMaxDistanceFactor (0.0);
    rg.extract (clusters);
    EXPECT_EQ (clusters.size (), 1u) << scale;
    rg.setMaxDistanceFactor (2.0);
    rg.extract (clusters);
    ASSERT_EQ (clusters.size (), 2u) << scale;
    EXPECT_EQ (clusters[0].indices.size (), 441u);
    EXPECT_EQ (clusters[1].indices.size (), 441u);
  }
  EXPECT_DOUBLE_EQ (Growing ().getMaxDistanceFactor (), 3.0);  // the default
}

TEST (VarianceRegionGrowing, SizeLimitsDropSegments)
{
  // Patch 0: 441 points; patch 1 cut to 10 x 21 = 210 points by calling a column edge.
  const auto cloud = twoPatches (1.0);
  Labels::Ptr classes = uniformClasses (cloud->size (), 1);
  for (std::size_t i = 441; i < cloud->size (); ++i)
    if ((i - 441) / 21 == 10)
      (*classes)[i].label = 2;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setClassification (classes);
  rg.setKSearch (9);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 3u);
  EXPECT_EQ (clusters[0].indices.size (), 441u);
  EXPECT_EQ (clusters[1].indices.size (), 210u);
  EXPECT_EQ (clusters[2].indices.size (), 210u);
  rg.setMinClusterSize (300);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 1u);
  EXPECT_EQ (clusters[0].indices.size (), 441u);
  rg.setMinClusterSize (1);
  rg.setMaxClusterSize (300);
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 2u);
  EXPECT_EQ (clusters[0].indices.size (), 210u);
}

TEST (VarianceRegionGrowing, IndicesRestrictTheSegmentation)
{
  // Only the second patch is segmented; the first is neither segmented nor a stop.
  const auto cloud = twoPatches (0.05);
  pcl::IndicesPtr second (new pcl::Indices);
  for (pcl::index_t i = 441; i < static_cast<pcl::index_t> (cloud->size ()); ++i)
    second->push_back (i);
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setIndices (second);
  rg.setClassification (uniformClasses (second->size (), 1));
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 1u);
  EXPECT_EQ (clusters[0].indices, *second);
  Labels labels;
  rg.getSegmentLabels (labels);
  ASSERT_EQ (labels.size (), cloud->size ());
  EXPECT_EQ (labels[0].label, 0u);
  EXPECT_EQ (labels[441].label, 1u);
}

TEST (VarianceRegionGrowing, SharedNeighbourhoodsGiveTheSameSegments)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.025, 0.001);
  pcl_ext::Neighbourhoods<Point>::Ptr nb (new pcl_ext::Neighbourhoods<Point>);
  nb->setInputCloud (cube.cloud);
  nb->setKSearch (50);
  ASSERT_TRUE (nb->compute ());
  Growing own, shared;
  own.setInputCloud (cube.cloud);
  shared.setInputCloud (cube.cloud);
  shared.setNeighbourhoods (nb);
  std::vector<pcl::PointIndices> a, b;
  own.extract (a);
  shared.extract (b);
  ASSERT_EQ (a.size (), b.size ());
  for (std::size_t c = 0; c < a.size (); ++c)
    EXPECT_EQ (a[c].indices, b[c].indices);
  // Neighbourhoods of another cloud are not used (a warning, then a search of its own).
  const auto other = pcl_ext::test::makePlane (1.0, 0.05);
  Growing mismatched;
  mismatched.setInputCloud (cube.cloud);
  mismatched.setNeighbourhoods (pcl_ext::Neighbourhoods<Point>::Ptr (new pcl_ext::Neighbourhoods<Point>));
  mismatched.extract (b);
  ASSERT_EQ (a.size (), b.size ());
}

TEST (VarianceRegionGrowing, ClassifierOptionsPassThrough)
{
  // The options beyond the paper reach the classification: the segmenter's classes are those
  // of LocalVarianceClassification with the same options, with its own search (k = 50 capped
  // at a radius) or with shared neighbourhoods, for 1 and 2 threads.
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.003);
  pcl_ext::LocalVarianceClassification<Point> lvc;
  lvc.setInputCloud (cube.cloud);
  lvc.setNoiseStandardDeviation (0.003);
  lvc.setBoundaryBand (true);
  lvc.setMaxRadius (0.06);
  pcl::PointCloud<pcl::Label> expected;
  lvc.classify (expected);
  ASSERT_EQ (expected.size (), cube.cloud->size ());
  auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<Point>> ();
  nb->setInputCloud (cube.cloud);
  nb->setKSearch (50);
  nb->setMaxRadius (0.06);
  ASSERT_TRUE (nb->compute ());
  std::vector<pcl::PointIndices> reference;
  for (const unsigned threads : {1u, 2u})
    for (const bool shared : {false, true})
    {
      Growing rg;
      rg.setInputCloud (cube.cloud);
      rg.setNoiseStandardDeviation (0.003);
      rg.setBoundaryBand (true);
      rg.setMaxRadius (0.06);
      rg.setNumberOfThreads (threads);
      rg.setMinClusterSize (100);
      if (shared)
        rg.setNeighbourhoods (nb);
      std::vector<pcl::PointIndices> clusters;
      rg.extract (clusters);
      EXPECT_EQ (clusters.size (), 6u);  // the faces
      const auto& classes = rg.getClassification ();
      ASSERT_EQ (classes.size (), expected.size ());
      std::size_t differ = 0;
      for (std::size_t i = 0; i < classes.size (); ++i)
        differ += classes[i].label != expected[i].label;
      EXPECT_EQ (differ, 0u) << threads << " threads, shared " << shared;
      if (reference.empty ())
        reference = clusters;
      ASSERT_EQ (clusters.size (), reference.size ());
      for (std::size_t c = 0; c < clusters.size (); ++c)
        EXPECT_EQ (clusters[c].indices, reference[c].indices);
    }
}

TEST (VarianceRegionGrowing, OutputsLabelsAndColours)
{
  // An organised 2-row cloud: the labels keep its layout.
  const auto cloud = twoPatches (1.0);
  cloud->width = static_cast<std::uint32_t> (cloud->size () / 2);
  cloud->height = 2;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setClassification (uniformClasses (cloud->size (), 1));
  Labels labels;
  rg.getSegmentLabels (labels);
  EXPECT_TRUE (labels.empty ());                    // before extract()
  EXPECT_TRUE (rg.getColoredCloud ()->empty ());
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 2u);
  rg.getSegmentLabels (labels);
  EXPECT_EQ (labels.width, cloud->width);
  EXPECT_EQ (labels.height, 2u);
  EXPECT_EQ (labels[0].label, 1u);
  EXPECT_EQ (labels[441].label, 2u);
  const auto coloured = rg.getColoredCloud ();
  ASSERT_EQ (coloured->size (), cloud->size ());
  EXPECT_EQ (coloured->height, 2u);
  const auto& a = (*coloured)[0];
  const auto& b = (*coloured)[441];
  EXPECT_FALSE (a.r == b.r && a.g == b.g && a.b == b.b);
  EXPECT_FALSE (a.r == 255 && a.g == 255 && a.b == 255);
}

// ---------------------------------------------------------------------------------------------
// Plane fits.

TEST (FitSegmentPlane, RecoversATiltedPlaneFarFromTheOrigin)
{
  // z = 0.1 (x - x0) - 0.2 (y - y0) + 3 with 2 mm noise in z, over 40 m x 2.5 m at
  // x0 = 6,000,000 m, y0 = 500,000 m. Floats there are 0.5 m (x) and 1/32 m (y) apart, so the
  // grid is made of representable coordinates: the fit must lose nothing beyond the noise.
  const Eigen::Vector3d n_true = Eigen::Vector3d (-0.1, 0.2, 1.0).normalized ();
  std::mt19937 rng (3);
  std::normal_distribution<double> noise (0.0, 0.002);
  Cloud cloud;
  pcl::Indices indices;
  const double x0 = 6000000.0, y0 = 500000.0;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j)
    {
      const double x = x0 + 0.5 * i, y = y0 + 0.03125 * j;
      const double z = 0.1 * (x - x0) - 0.2 * (y - y0) + 3.0 + noise (rng);
      cloud.push_back (Point (static_cast<float> (x), static_cast<float> (y),
                              static_cast<float> (z)));
      indices.push_back (static_cast<pcl::index_t> (cloud.size () - 1));
    }
  const auto plane = pcl_ext::fitSegmentPlane (cloud, indices, Eigen::Vector3d (x0, y0, 100.0));
  ASSERT_TRUE (plane.valid);
  EXPECT_EQ (plane.size, cloud.size ());
  EXPECT_GT (plane.normal.dot (n_true), 1.0 - 1e-6);  // and turned up, towards the viewpoint
  EXPECT_NEAR (plane.normal.dot (plane.centroid) + plane.d, 0.0, 1e-6);
  // A z offset dz is a distance dz * n_z from the plane.
  EXPECT_NEAR (plane.rms_residual, 0.002 * n_true.z (), 0.0003);
  EXPECT_GT (plane.max_residual, 2.5 * plane.rms_residual);
  EXPECT_LT (plane.max_residual, 6.0 * plane.rms_residual);
  // The same fit seen from below is turned down.
  const auto below = pcl_ext::fitSegmentPlane (cloud, indices, Eigen::Vector3d (x0, y0, -100.0));
  EXPECT_LT (below.normal.dot (n_true), -1.0 + 1e-6);
  EXPECT_NEAR (below.d, -plane.d, 1e-6 * std::abs (plane.d));
}

TEST (FitSegmentPlane, ThroughTheSegmenter)
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  EXPECT_TRUE (rg.getSegmentPlanes ().empty ());  // off by default
  rg.setFitPlanes (true);
  rg.extract (clusters);
  const auto& planes = rg.getSegmentPlanes ();
  ASSERT_EQ (planes.size (), clusters.size ());
  ASSERT_EQ (planes.size (), 6u);
  for (const auto& plane : planes)
  {
    ASSERT_TRUE (plane.valid);
    // Each face is axis-aligned at 0 or 1, the noise is 1 mm along its normal.
    EXPECT_GT (plane.normal.cwiseAbs ().maxCoeff (), 0.9999);
    EXPECT_NEAR (std::abs (plane.d), std::abs (plane.d) < 0.5 ? 0.0 : 1.0, 1e-3);
    EXPECT_LT (plane.rms_residual, 0.0015);
  }
}

TEST (FitSegmentPlane, OneOrTwoPointsOrALineHaveNoPlane)
{
  Cloud cloud;
  for (int i = 0; i < 5; ++i)
    cloud.push_back (Point (0.1f * i, 0.2f * i, 0.f));  // collinear
  const Eigen::Vector3d view (0, 0, 1);
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices {0}, view).valid);
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices {0, 1}, view).valid);
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices {0, 1, 2, 3, 4}, view).valid);
  EXPECT_FALSE (pcl_ext::fitSegmentPlane (cloud, pcl::Indices {}, view).valid);
  EXPECT_TRUE (std::isnan (pcl_ext::fitSegmentPlane (cloud, pcl::Indices {0}, view).normal.x ()));
}

// ---------------------------------------------------------------------------------------------
// Bad input: a PCL_ERROR and no segment, never a crash.

TEST (VarianceRegionGrowingBadInput, NoCloudEmptyCloudEmptyIndices)
{
  std::vector<pcl::PointIndices> clusters {pcl::PointIndices ()};
  Growing rg;
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
  rg.setInputCloud (Cloud::Ptr (new Cloud));
  clusters.resize (1);
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
  const auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  rg.setInputCloud (plane.cloud);
  rg.setIndices (pcl::IndicesPtr (new pcl::Indices));
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
  Labels labels;
  rg.getSegmentLabels (labels);
  EXPECT_TRUE (labels.empty ());
}

TEST (VarianceRegionGrowingBadInput, NoSurfacePoint)
{
  const auto plane = pcl_ext::test::makePlane (1.0, 0.05);
  Growing rg;
  rg.setInputCloud (plane.cloud);
  rg.setClassification (uniformClasses (plane.cloud->size (), 2));
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
  // Points that are all collinear have no tangent plane: all unknown, so no surface either.
  Cloud::Ptr line (new Cloud);
  for (int i = 0; i < 200; ++i)
    line->push_back (Point (0.01f * i, 0.f, 0.f));
  Growing on_line;
  on_line.setInputCloud (line);
  on_line.setKSearch (10);
  on_line.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
  for (const auto& c : on_line.getClassification ())
    EXPECT_EQ (c.label, 0u);
}

TEST (VarianceRegionGrowingBadInput, NaNPointsAreNeverSegmented)
{
  // The cube with every 7th point replaced by NaN (is_dense false): same faces, and no NaN
  // point in a segment.
  auto cube = pcl_ext::test::makeCube (1.0, 0.02, 0.001);
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (std::size_t i = 0; i < cube.cloud->size (); i += 7)
    (*cube.cloud)[i].x = nan;
  cube.cloud->is_dense = false;
  Growing rg;
  rg.setInputCloud (cube.cloud);
  rg.setMinClusterSize (50);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 6u);
  for (const auto& c : clusters)
    for (const auto i : c.indices)
      EXPECT_NE (i % 7, 0) << "NaN point " << i << " segmented";
  // A cloud claiming to be dense while holding NaN points is treated the same.
  cube.cloud->is_dense = true;
  std::vector<pcl::PointIndices> dense_claim;
  rg.extract (dense_claim);
  ASSERT_EQ (dense_claim.size (), clusters.size ());
  for (std::size_t c = 0; c < clusters.size (); ++c)
    EXPECT_EQ (dense_claim[c].indices, clusters[c].indices);
}

TEST (VarianceRegionGrowingBadInput, SegmentsOfOnePoint)
{
  // Surface points each surrounded by edges: every one is a segment of its own.
  const auto cloud = twoPatches (1.0);
  Labels::Ptr classes = uniformClasses (cloud->size (), 2);
  for (const std::size_t i : {22u, 100u, 300u})
    (*classes)[i].label = 1;
  Growing rg;
  rg.setInputCloud (cloud);
  rg.setClassification (classes);
  rg.setKSearch (9);
  rg.setFitPlanes (true);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  ASSERT_EQ (clusters.size (), 3u);
  EXPECT_EQ (clusters[0].indices, pcl::Indices {22});  // equal sizes: smallest index first
  EXPECT_EQ (clusters[2].indices, pcl::Indices {300});
  ASSERT_EQ (rg.getSegmentPlanes ().size (), 3u);
  for (const auto& p : rg.getSegmentPlanes ())
  {
    EXPECT_FALSE (p.valid);
    EXPECT_EQ (p.size, 1u);
  }
  // With the usual minimum size nothing is left, and that is no error.
  rg.setMinClusterSize (2);
  rg.extract (clusters);
  EXPECT_TRUE (clusters.empty ());
}

TEST (VarianceRegionGrowingBadInput, NonsenseParameters)
{
  const auto cloud = twoPatches (1.0);
  std::vector<pcl::PointIndices> clusters;
  const auto fails = [&] (const std::function<void (Growing&)>& set) {
    Growing rg;
    rg.setInputCloud (cloud);
    set (rg);
    clusters.resize (1);
    rg.extract (clusters);
    return clusters.empty ();
  };
  EXPECT_FALSE (fails ([] (Growing&) {}));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMinClusterSize (0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMinClusterSize (10); rg.setMaxClusterSize (9); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistance (INFINITY); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxDistanceFactor (INFINITY); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxRadius (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setMaxRadius (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setNoiseStandardDeviation (-0.001); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setNoiseStandardDeviation (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (2); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (-5); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (100000); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setRadiusSearch (-0.1); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setRadiusSearch (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setKSearch (0); }));  // neither k nor radius
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setVarianceThreshold (-1.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setCurvatureThreshold (std::nan ("")); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setCurvatureThresholdFactor (0.0); }));
  EXPECT_TRUE (fails ([] (Growing& rg) { rg.setConfidence (1.0); }));
  EXPECT_TRUE (fails ([&] (Growing& rg) {
    rg.setClassification (uniformClasses (cloud->size () - 1, 1));
  }));
}
