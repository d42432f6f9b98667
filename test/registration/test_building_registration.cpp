/*
 * Khoshelham & Gorte (2009) section 4 on the simulated building: scan, extract planes,
 * match them to the footprint's planes (Table 1 anchor) and scan to scan.
 */
#include "building_fixture.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numeric>

using namespace pcl_ext;

namespace {
using test::Building;
using test::centroidOf;
using test::Outcome;

Building
scanChecked (std::uint64_t seed, double noise, int superfluous, int missing)
{
  Building b = test::scanBuilding (seed, noise, superfluous, missing);
  EXPECT_FALSE (b.cloud->empty());
  return b;
}

Outcome
registerChecked (const Building& b)
{
  const Outcome o = test::registerToMap (b);
  EXPECT_TRUE (o.converged);
  return o;
}

void
print (const char* what, const Outcome& o)
{
  std::printf (
      "%s: %zu scan planes, %zu map planes, %zu matched, mean %.3f m, max %.3f m, "
      "rotation %.4f deg, translation %.4f m; combinations %llu / %llu / %llu / %llu\n",
      what,
      o.scan_planes,
      o.map_planes,
      o.matches,
      o.distances.mean,
      o.distances.max,
      o.error.rotation_deg,
      o.error.translation,
      (unsigned long long)o.statistics.unconstrained,
      (unsigned long long)o.statistics.vertical,
      (unsigned long long)o.statistics.orientation,
      (unsigned long long)o.statistics.residual);
}
} // namespace

// Table 1: the paper's simulation, 20 cm noise, no superfluous or missing planes.
TEST (BuildingRegistration, TwentyCentimetreNoiseMatchesTable1)
{
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const Building b = scanChecked (seed, 0.2, 0, 0);
    const Outcome o = registerChecked (b);
    print ("20 cm", o);
    EXPECT_EQ (o.wrong, 0);
    EXPECT_GE (o.matches, 8u);
    EXPECT_LE (o.error.rotation_deg, 0.5);
    EXPECT_LE (o.error.translation, 0.2);
    EXPECT_LE (o.distances.mean, 0.27); // Table 1: 0.27 m
  }
}

// 20 cm noise with superfluous planes (4 of 13, 30 %) and walls hidden by hedges (2 of
// 12). The hedges hide the two longest walls, which are parallel; the extractor fits a
// plane to the front of each hedge row, 3.8 m before the hidden wall. Only the
// courtyard walls then fix that direction, so they must be scanned (the scene's central
// positions see them); matching a hedge to its wall would cost those matches.
TEST (BuildingRegistration, TwentyCentimetreNoiseWithOutliers)
{
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const Building b = scanChecked (seed, 0.2, 4, 2);
    const Outcome o = registerChecked (b);
    print ("20 cm, outliers", o);
    EXPECT_EQ (o.wrong, 0);
    EXPECT_LE (o.error.rotation_deg, 0.5);
    EXPECT_LE (o.error.translation, 0.2);
    EXPECT_LE (o.distances.mean, 0.27);
  }
}

TEST (BuildingRegistration, TwoCentimetreNoise)
{
  const Building b = scanChecked (5, 0.02, 4, 2);
  const Outcome o = registerChecked (b);
  print ("2 cm", o);
  EXPECT_EQ (o.wrong, 0);
  EXPECT_LE (o.error.rotation_deg, 0.1);
  EXPECT_LE (o.error.translation, 0.03);
}

// Scan to scan (the paper's future work): the scans of every other position, moved by a
// known transform, against the scans of all positions; the target's planes play the
// map's part.
TEST (BuildingRegistration, ScanToScan)
{
  const Building b = scanChecked (7, 0.02, 0, 0);
  const std::size_t scanners = b.viewpoints.positions.size();
  ASSERT_GE (scanners, 4u);
  std::mt19937 rng (7);
  const Eigen::Matrix4d truth = test::randomPose (rng, 3.0, 20.0); // source to target
  pcl::PointCloud<pcl::PointXYZ>::Ptr source (new pcl::PointCloud<pcl::PointXYZ>),
      target (new pcl::PointCloud<pcl::PointXYZ>);
  ScanViewpoints source_views, target_views;
  source_views.positions = target_views.positions = b.viewpoints.positions;
  for (auto& position : source_views.positions)
    position = (truth.inverse() * position.homogeneous()).head<3>();
  for (std::size_t i = 0; i < b.cloud->size(); ++i) {
    const std::uint16_t s = b.viewpoints.scanner_of_point[i];
    if (s % 2 == 0) {
      const Eigen::Vector4d q =
          truth.inverse() * (*b.cloud)[i].getVector4fMap().cast<double>();
      source->emplace_back (float (q.x()), float (q.y()), float (q.z()));
      source_views.scanner_of_point.push_back (s);
    }
    target->push_back ((*b.cloud)[i]);
    target_views.scanner_of_point.push_back (s);
  }
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (source);
  reg.setInputTarget (target);
  reg.setSourceViewpoints (source_views);
  reg.setTargetViewpoints (target_views);
  reg.setOrientedNormals (true);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned);
  ASSERT_TRUE (reg.hasConverged());
  const auto error = computeTransformationError (
      reg.getFinalTransformationDouble(), truth, centroidOf (*source));
  PlaneDistanceMetrics distances;
  reg.getPlaneDistances (distances);
  std::printf ("scan to scan: %zu source planes, %zu target planes, %zu matched, "
               "rotation %.4f deg, "
               "translation %.4f m, mean plane distance %.3f m\n",
               reg.getSourcePlanes().size(),
               reg.getTargetPlanes().size(),
               reg.getMatchingResult().matches.size(),
               error.rotation_deg,
               error.translation,
               distances.mean);
  EXPECT_GE (reg.getMatchingResult().matches.size(), 5u);
  EXPECT_LE (error.rotation_deg, 0.1);
  EXPECT_LE (error.translation, 0.03);
}

TEST (BuildingRegistration, BadInputDoesNotConverge)
{
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  pcl::PointCloud<pcl::PointXYZ>::Ptr empty (new pcl::PointCloud<pcl::PointXYZ>);
  io::Footprint footprint;
  footprint.polygons.resize (1);
  footprint.polygons[0].outer = test::asymmetricH();
  ASSERT_TRUE (reg.setFootprints ({footprint}));
  pcl::PointCloud<pcl::PointXYZ> out;
  reg.setInputSource (empty);
  reg.align (out);
  EXPECT_FALSE (reg.hasConverged());
  // A cloud of NaN points and one without planes (a random blob).
  pcl::PointCloud<pcl::PointXYZ>::Ptr nan (new pcl::PointCloud<pcl::PointXYZ>);
  nan->resize (500, pcl::PointXYZ (NAN, NAN, NAN));
  reg.setInputSource (nan);
  reg.align (out);
  EXPECT_FALSE (reg.hasConverged());
  pcl::PointCloud<pcl::PointXYZ>::Ptr blob (new pcl::PointCloud<pcl::PointXYZ>);
  std::mt19937 rng (1);
  std::normal_distribution<float> g (0.f, 5.f);
  for (int i = 0; i < 2000; ++i)
    blob->emplace_back (g (rng), g (rng), g (rng));
  reg.setInputSource (blob);
  reg.align (out);
  EXPECT_FALSE (reg.hasConverged());
  // Bad footprints: empty, self-intersecting.
  EXPECT_FALSE (reg.setFootprints ({}));
  footprint.polygons[0].outer = {{0, 0}, {4, 4}, {4, 0}, {0, 4}};
  EXPECT_FALSE (reg.setFootprints ({footprint}));
  reg.setInputSource (blob);
  reg.align (out); // no map and no target: pcl::Registration refuses
  EXPECT_FALSE (reg.hasConverged());
}

// setIndices: the scan planes come from the indexed points only. The scan is followed
// by a second copy of itself 300 m away; indexing the first copy gives the result of
// the first copy alone, bit for bit, and inlier indices that index the whole cloud.
TEST (BuildingRegistration, IndicesRestrictTheScanPlanes)
{
  const Building b = scanChecked (1, 0.02, 0, 0);
  const Outcome alone = registerChecked (b);
  ASSERT_TRUE (alone.converged);

  Building doubled = b;
  doubled.cloud.reset (new pcl::PointCloud<pcl::PointXYZ> (*b.cloud));
  for (const auto& p : *b.cloud)
    doubled.cloud->emplace_back (p.x + 300.f, p.y, p.z);
  doubled.viewpoints.scanner_of_point.insert (doubled.viewpoints.scanner_of_point.end(),
                                              b.viewpoints.scanner_of_point.begin(),
                                              b.viewpoints.scanner_of_point.end());
  pcl::IndicesPtr first (new pcl::Indices (b.cloud->size()));
  std::iota (first->begin(), first->end(), 0);

  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (doubled.cloud);
  reg.setIndices (first);
  reg.setSourceViewpoints (doubled.viewpoints);
  reg.setOrientedNormals (true);
  ASSERT_TRUE (reg.setFootprints ({test::footprintOf (b.scene)}));
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned);
  ASSERT_TRUE (reg.hasConverged());
  EXPECT_EQ (aligned.size(), b.cloud->size());
  EXPECT_EQ (reg.getSourcePlanes().size(), alone.scan_planes);
  EXPECT_EQ (reg.getMatchingResult().matches.size(), alone.matches);
  Eigen::Matrix4d truth = b.scene.scan_to_map;
  truth.topRightCorner<3, 1>() -= reg.getLocalOrigin();
  const auto error = computeTransformationError (
      reg.getFinalTransformationDouble(), truth, test::centroidOf (*b.cloud));
  EXPECT_EQ (error.rotation_deg, alone.error.rotation_deg);
  EXPECT_EQ (error.translation, alone.error.translation);
  for (const auto& plane : reg.getSourcePlanes())
    for (const auto i : plane.inliers.indices)
      ASSERT_LT (static_cast<std::size_t> (i), b.cloud->size());

  // An index past the end: refused before any point is read.
  first->push_back (static_cast<pcl::index_t> (doubled.cloud->size()));
  reg.setIndices (first);
  reg.align (aligned);
  EXPECT_FALSE (reg.hasConverged());
  EXPECT_TRUE (aligned.empty());
}
