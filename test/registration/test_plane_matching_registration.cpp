/*
 * Tests of PlaneMatchingRegistration as a pcl::Registration (Khoshelham & Gorte 2009):
 * used through a pcl::Registration pointer, its bad input, and its fitness score, the
 * mean distance between the matched planes. The scan is the asymmetric H building
 * sampled with known noise, its planes handed over by a plane extractor that knows
 * them.
 */
#include "plane_fixtures.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <pcl/point_types.h>
#include <pcl/registration/registration.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

using namespace pcl_ext;

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Registration = PlaneMatchingRegistration<Point, Point>;
using RegistrationBase = pcl::Registration<Point, Point, float>;

const double kNoise =
    0.05; // standard deviation of the points along the plane normals (m)

// Outside the footprint of the asymmetric H: its 40 x 30 m block minus the two
// courtyards.
bool
outsideAsymmetricH (double x, double y)
{
  if (x < 0.0 || x > 40.0 || y < 0.0 || y > 30.0)
    return true;
  return x > 12.0 && x < 28.0 && (y < 10.0 || y > 22.0);
}

// The asymmetric H as a scanner in a random pose would see it: each wall every 0.5 m up
// to 8 m, the ground around the building every metre, Gaussian noise of kNoise along
// the normals; one inlier set per wall and one for the ground.
struct SampledScan {
  std::vector<MapPlane> map;
  Cloud::Ptr cloud{new Cloud};
  std::vector<pcl::PointIndices> planes;
  Eigen::Matrix4d truth = Eigen::Matrix4d::Identity(); // scan to map
};

// The points of a wall every 0.5 m along it and up to 8 m.
std::vector<Eigen::Vector3d>
wallSamples (const MapPlane& wall)
{
  std::vector<Eigen::Vector3d> points;
  const double length = wall.length();
  for (double u = 0.25; u < length; u += 0.5)
    for (double z = 0.25; z < 8.0; z += 0.5) {
      const Eigen::Vector2d p = wall.start + (wall.end - wall.start) * (u / length);
      points.emplace_back (p.x(), p.y(), z);
    }
  return points;
}

SampledScan
sampleScan (unsigned int seed)
{
  SampledScan s;
  EXPECT_TRUE (computeMapPlanes (test::asymmetricH(), MapPlaneParameters(), s.map));
  std::mt19937 rng (seed);
  s.truth = test::randomPose (rng);
  const Eigen::Matrix4d to_scan = s.truth.inverse();
  std::normal_distribution<double> noise (0.0, kNoise);
  auto add = [&] (const Eigen::Vector3d& x,
                  const Eigen::Vector3d& normal,
                  pcl::PointIndices& set) {
    const Eigen::Vector3d q =
        to_scan.topLeftCorner<3, 3>() * (x + noise (rng) * normal) +
        to_scan.topRightCorner<3, 1>();
    set.indices.push_back (static_cast<pcl::index_t> (s.cloud->size()));
    s.cloud->emplace_back (float (q.x()), float (q.y()), float (q.z()));
  };
  pcl::PointIndices ground;
  for (double x = -6.0; x <= 46.0; x += 1.0)
    for (double y = -6.0; y <= 36.0; y += 1.0)
      if (outsideAsymmetricH (x, y))
        add (Eigen::Vector3d (x, y, 0.0), Eigen::Vector3d::UnitZ(), ground);
  s.planes.push_back (ground);
  for (const auto& plane : s.map) {
    if (plane.isFloor())
      continue;
    pcl::PointIndices wall;
    for (const auto& x : wallSamples (plane))
      add (x, plane.normal, wall);
    s.planes.push_back (wall);
  }
  return s;
}

// The map planes, and an extractor that answers with the sampled inlier sets.
void
configure (Registration& reg, const SampledScan& s)
{
  reg.setMapPlanes (s.map);
  const std::vector<pcl::PointIndices> planes = s.planes;
  reg.setPlaneExtractor (
      [planes] (const Cloud::ConstPtr&,
                const pcl::IndicesConstPtr&,
                std::vector<pcl::PointIndices>& out) { out = planes; });
}

Eigen::Vector3d
centroidOf (const Cloud& cloud)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : cloud)
    c += p.getVector3fMap().cast<double>();
  return c / static_cast<double> (cloud.size());
}

void
expectSameClouds (const Cloud& a, const Cloud& b)
{
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_TRUE (a[i].getVector3fMap() == b[i].getVector3fMap()) << "point " << i;
}
} // namespace

// The class used through a pcl::Registration pointer gives what it gives used directly:
// the same convergence, transform and registered cloud, without and with a guess.
TEST (PlaneMatchingRegistration, AlignThroughARegistrationPointerIsTheClassAlign)
{
  const SampledScan s = sampleScan (1);
  Registration direct;
  configure (direct, s);
  direct.setInputSource (s.cloud);
  Cloud direct_out;
  direct.align (direct_out);
  ASSERT_TRUE (direct.hasConverged());
  const TransformationError error = computeTransformationError (
      direct.getFinalTransformationDouble(), s.truth, centroidOf (*s.cloud));
  EXPECT_LT (error.rotation_deg, 0.1);
  EXPECT_LT (error.translation, 0.05);

  const Registration::Ptr concrete (new Registration);
  configure (*concrete, s);
  const RegistrationBase::Ptr reg = concrete;
  reg->setInputSource (s.cloud);
  Cloud out;
  reg->align (out);
  EXPECT_EQ (reg->hasConverged(), direct.hasConverged());
  EXPECT_TRUE (reg->getFinalTransformation() == direct.getFinalTransformation());
  EXPECT_TRUE (concrete->getFinalTransformationDouble() ==
               direct.getFinalTransformationDouble());
  EXPECT_EQ (concrete->getMatchingResult().matches.size(),
             direct.getMatchingResult().matches.size());
  expectSameClouds (out, direct_out);

  // A guess with bounds around it: the bounds apply through the pointer too.
  Eigen::Matrix4f guess = s.truth.cast<float>();
  guess (0, 3) += 1.f;
  for (Registration* r : {&direct, concrete.get()}) {
    r->setMaxRotationFromGuess (5.0);
    r->setMaxTranslationFromGuess (3.0);
  }
  direct.align (direct_out, guess);
  reg->align (out, guess);
  ASSERT_TRUE (direct.hasConverged());
  EXPECT_TRUE (reg->hasConverged());
  EXPECT_TRUE (reg->getFinalTransformation() == direct.getFinalTransformation());
  expectSameClouds (out, direct_out);
}

// Bad input through the pointer: a PCL_ERROR naming the class, not converged, no crash.
TEST (PlaneMatchingRegistration, BadInputThroughARegistrationPointerDoesNotConverge)
{
  const SampledScan s = sampleScan (2);
  const Cloud::Ptr empty (new Cloud);
  Cloud out;
  auto expectRefused =
      [&] (const RegistrationBase::Ptr& reg, const std::string& log, const char* what) {
        EXPECT_FALSE (reg->hasConverged()) << what;
        EXPECT_NE (log.find ("PlaneMatchingRegistration"), std::string::npos)
            << what << ": " << log;
      };

  {
    // No map and no target cloud: pcl::Registration refuses.
    const Registration::Ptr concrete (new Registration);
    const RegistrationBase::Ptr reg = concrete;
    testing::internal::CaptureStderr();
    reg->setInputSource (s.cloud);
    reg->align (out);
    expectRefused (reg, testing::internal::GetCapturedStderr(), "no map");
  }
  {
    // An empty cloud, on a fresh registration and after a converged one.
    const Registration::Ptr concrete (new Registration);
    configure (*concrete, s);
    const RegistrationBase::Ptr reg = concrete;
    testing::internal::CaptureStderr();
    reg->setInputSource (empty);
    reg->align (out);
    expectRefused (reg, testing::internal::GetCapturedStderr(), "empty cloud");
    EXPECT_TRUE (out.empty());

    reg->setInputSource (s.cloud);
    reg->align (out);
    ASSERT_TRUE (reg->hasConverged());
    testing::internal::CaptureStderr();
    reg->setInputSource (empty);
    reg->align (out);
    expectRefused (
        reg, testing::internal::GetCapturedStderr(), "empty cloud after a run");
    EXPECT_TRUE (out.empty());
    EXPECT_EQ (concrete->getFitnessScore(), std::numeric_limits<double>::max());
  }
  {
    // A map without planes.
    const Registration::Ptr concrete (new Registration);
    configure (*concrete, s);
    concrete->setMapPlanes ({});
    const RegistrationBase::Ptr reg = concrete;
    testing::internal::CaptureStderr();
    reg->setInputSource (s.cloud);
    reg->align (out);
    expectRefused (reg, testing::internal::GetCapturedStderr(), "no map planes");
    EXPECT_EQ (concrete->getFitnessScore(), std::numeric_limits<double>::max());
  }
  {
    // An index past the end of the cloud: refused before pcl::Registration reads the
    // points.
    const Registration::Ptr concrete (new Registration);
    configure (*concrete, s);
    const RegistrationBase::Ptr reg = concrete;
    const pcl::IndicesPtr indices (
        new pcl::Indices{0, 1, static_cast<pcl::index_t> (s.cloud->size())});
    testing::internal::CaptureStderr();
    reg->setInputSource (s.cloud);
    reg->setIndices (indices);
    reg->align (out);
    expectRefused (reg, testing::internal::GetCapturedStderr(), "index out of range");
    EXPECT_TRUE (out.empty());
    // The same indices fit a larger cloud: they are taken again.
    Cloud::Ptr larger (new Cloud (*s.cloud));
    larger->push_back (Point (0.f, 0.f, 0.f));
    reg->setInputSource (larger);
    ASSERT_TRUE (reg->getIndices());
    EXPECT_EQ (reg->getIndices()->size(), indices->size());
  }
}

// getFitnessScore is the mean over the matched planes of the RMS distance of the scan
// plane's inliers to its map plane after the transform: about the noise for the right
// pose, the misalignment for a wrong one; not pcl::Registration's nearest-neighbour
// score.
TEST (PlaneMatchingRegistration, FitnessIsTheMeanDistanceOfTheMatchedPlanes)
{
  const SampledScan s = sampleScan (3);
  Registration reg;
  configure (reg, s);
  reg.setInputSource (s.cloud);
  Cloud out;
  reg.align (out);
  ASSERT_TRUE (reg.hasConverged());
  const double fitness = reg.getFitnessScore();
  EXPECT_GT (fitness, 0.5 * kNoise);
  EXPECT_LT (fitness, 1.5 * kNoise);
  // The same figure as the per-plane RMS distances of Tables 1-2, averaged.
  PlaneDistanceMetrics distances;
  ASSERT_TRUE (reg.getPlaneDistances (distances));
  ASSERT_EQ (distances.pairs.size(), reg.getMatchingResult().matches.size());
  double mean_rms = 0.0;
  for (const auto& pair : distances.pairs)
    mean_rms += pair.rms / static_cast<double> (distances.pairs.size());
  EXPECT_NEAR (fitness, mean_rms, 1e-9);
  // max_range leaves out the points farther from their plane: the tails of the noise.
  const double clipped = reg.getFitnessScore (2.0 * kNoise);
  EXPECT_GT (clipped, 0.0);
  EXPECT_LT (clipped, fitness);
  // pcl::Registration's score is the mean squared distance to the nearest target point
  // (the map's wall corners): metres squared, and nothing to do with the planes.
  const double nearest_neighbour = reg.RegistrationBase::getFitnessScore();
  EXPECT_GT (nearest_neighbour, 1.0);

  // A wrong pose: scan planes that describe the scan moved by (0.6, 0.45, 0.3) m give a
  // transform that misplaces its points by that much.
  Cloud::Ptr moved (new Cloud (*s.cloud));
  for (auto& p : *moved) {
    p.x += 0.6f;
    p.y += 0.45f;
    p.z += 0.3f;
  }
  std::vector<ScanPlane> planes;
  ASSERT_TRUE (fitScanPlanes (*moved, s.planes, ScanViewpoints(), planes));
  Registration wrong;
  configure (wrong, s);
  wrong.setSourcePlanes (planes);
  wrong.setInputSource (s.cloud);
  wrong.align (out);
  ASSERT_TRUE (wrong.hasConverged());
  const double wrong_fitness = wrong.getFitnessScore();
  EXPECT_GT (wrong_fitness, 0.25);
  EXPECT_GT (wrong_fitness, 4.0 * fitness);
}

namespace {
// Inside the symmetric H (test::hShape): its 40 x 30 m block minus the two courtyards.
bool
insideH (double x, double y)
{
  return x > 0.0 && x < 40.0 && y > 0.0 && y < 30.0 &&
         !(x > 12.0 && x < 28.0 && (y < 10.0 || y > 20.0));
}
} // namespace

// An airborne-like scan of the symmetric H (a half turn about (20, 15) maps it onto
// itself) and, north of it, a 10 x 10 m annex whose walls the scan does not hold: the
// H's walls and the ground pair both ways, so without the roofs the two poses are
// candidates alike. The roofs (every metre over both footprints, 8 m and 3 m high) lie
// over the footprints in the true pose; turned, the annex's roof falls on open ground:
// with the roof points as coverage indices the true pose is the one result (indices
// that do not fit the cloud, and a NaN point, left out).
TEST (PlaneMatchingRegistration, CoverageIndicesChooseThePoseThatPutsTheRoofsOverTheMap)
{
  const io::Ring2d annex{{15, 40}, {25, 40}, {25, 50}, {15, 50}};
  std::vector<io::Footprint> footprints (2);
  footprints[0].polygons.resize (1);
  footprints[0].polygons[0].outer = test::hShape();
  footprints[1].polygons.resize (1);
  footprints[1].polygons[0].outer = annex;
  std::vector<MapPlane> h_walls;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), h_walls));
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const Eigen::Matrix4d to_scan = truth.inverse();
    std::normal_distribution<double> noise (0.0, kNoise);
    Cloud::Ptr cloud (new Cloud);
    pcl::IndicesPtr roofs (new pcl::Indices);
    std::vector<pcl::PointIndices> planes (1);
    auto add = [&] (const Eigen::Vector3d& x, const Eigen::Vector3d& normal) {
      const Eigen::Vector3d q =
          to_scan.topLeftCorner<3, 3>() * (x + noise (rng) * normal) +
          to_scan.topRightCorner<3, 1>();
      cloud->emplace_back (float (q.x()), float (q.y()), float (q.z()));
      return static_cast<pcl::index_t> (cloud->size() - 1);
    };
    for (double x = -9.5; x < 50.0; x += 1.0)
      for (double y = -9.5; y < 60.0; y += 1.0) {
        if (insideH (x, y))
          roofs->push_back (add ({x, y, 8.0}, Eigen::Vector3d::UnitZ()));
        else if (x > 15.0 && x < 25.0 && y > 40.0 && y < 50.0) // the annex
          roofs->push_back (add ({x, y, 3.0}, Eigen::Vector3d::UnitZ()));
        else
          planes[0].indices.push_back (add ({x, y, 0.0}, Eigen::Vector3d::UnitZ()));
      }
    for (const auto& plane : h_walls) {
      if (plane.isFloor())
        continue;
      pcl::PointIndices wall;
      for (const auto& x : wallSamples (plane))
        wall.indices.push_back (add (x, plane.normal));
      planes.push_back (wall);
    }
    // Coverage indices that do not fit are left out: past the cloud's end, negative,
    // and a NaN point.
    const Eigen::Vector3d centre = centroidOf (*cloud);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    cloud->emplace_back (nan, nan, nan);
    roofs->push_back (static_cast<pcl::index_t> (cloud->size() - 1));
    roofs->push_back (static_cast<pcl::index_t> (cloud->size() + 5));
    roofs->push_back (-1);
    auto registerScan = [&] (Registration& reg, bool with_roofs) {
      EXPECT_TRUE (reg.setFootprints (footprints));
      reg.setPlaneExtractor (
          [planes] (const Cloud::ConstPtr&,
                    const pcl::IndicesConstPtr&,
                    std::vector<pcl::PointIndices>& out) { out = planes; });
      if (with_roofs)
        reg.setCoverageIndices (roofs);
      reg.setInputSource (cloud);
      Cloud out;
      reg.align (out);
    };
    Registration plain, covered;
    registerScan (plain, false);
    ASSERT_TRUE (plain.hasConverged());
    EXPECT_EQ (plain.getMatchingResult().candidates.size(), 2u) << "seed " << seed;
    registerScan (covered, true);
    ASSERT_TRUE (covered.hasConverged());
    EXPECT_EQ (covered.getMatchingResult().candidates.size(), 1u) << "seed " << seed;
    // The truth in the map's local frame.
    Eigen::Matrix4d local_truth = truth;
    local_truth.topRightCorner<3, 1>() -= covered.getLocalOrigin();
    const TransformationError error = computeTransformationError (
        covered.getFinalTransformationDouble(), local_truth, centre);
    // The true pose, not its half turn (180 degrees and tens of metres away).
    EXPECT_LT (error.rotation_deg, 0.5) << "seed " << seed;
    EXPECT_LT (error.translation, 0.2) << "seed " << seed;
  }
}
