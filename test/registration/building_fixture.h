/*
 * The simulated building scanned in a random pose (Khoshelham & Gorte 2009, section 4)
 * and registered to its footprint: shared by the registration tests and the trials
 * benchmark.
 */
#pragma once

#include "plane_fixtures.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/common/io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace pcl_ext {
namespace test {
/** A scan of the simulated building with its viewpoints. */
struct Building {
  simulation::SyntheticScene scene;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  ScanViewpoints viewpoints;
};

// The building scene on the asymmetric H (the default H is symmetric under a half turn,
// which no map registration can resolve), in a random pose drawn from the seed.
inline Building
scanBuilding (std::uint64_t seed, double noise, int superfluous, int missing)
{
  Building b;
  simulation::SceneParameters p;
  p.seed = seed;
  p.noise = noise;
  p.angular_step_deg = 0.8;
  p.footprint = asymmetricH();
  p.superfluous_planes = superfluous;
  p.missing_walls = missing;
  p.threads = 1;
  // The scene's own random pose tilts up to 10 degrees; these trials tilt up to 3.
  std::mt19937 rng (static_cast<unsigned> (seed));
  p.random_pose = false;
  p.has_pose = true;
  p.pose = Eigen::Isometry3d (randomPose (rng).inverse());
  if (!simulation::generateScene ("building", p, b.scene))
    return b;
  pcl::copyPointCloud (b.scene.cloud, *b.cloud);
  for (const auto& position : b.scene.scan_positions)
    b.viewpoints.positions.push_back (b.scene.cloud_from_scene * position);
  b.viewpoints.scanner_of_point = b.scene.scanner_of_point;
  return b;
}

inline io::Footprint
footprintOf (const simulation::SyntheticScene& scene)
{
  io::Footprint f;
  f.polygons.resize (1);
  f.polygons[0].outer = scene.footprint;
  return f;
}

inline Eigen::Vector3d
centroidOf (const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : cloud)
    c += p.getVector3fMap().cast<double>();
  return c / static_cast<double> (cloud.size());
}

struct Outcome {
  TransformationError error;
  PlaneDistanceMetrics distances;
  std::size_t scan_planes = 0, map_planes = 0, matches = 0;
  int wrong =
      0; ///< matches whose planes are not the same plane under the true transform
  bool converged = false;
  PlaneMatchingStatistics statistics;
};

inline Outcome
registerToMap (const Building& b)
{
  Outcome o;
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (b.cloud);
  reg.setSourceViewpoints (b.viewpoints);
  // The scanner positions are known: scan normals face the scanner, walls face out, the
  // floor up. Without signs a ceiling seen through the windows can take the floor's
  // place.
  reg.setOrientedNormals (true);
  if (!reg.setFootprints ({footprintOf (b.scene)}))
    return o;
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned);
  o.converged = reg.hasConverged();
  if (!o.converged)
    return o;
  Eigen::Matrix4d truth = b.scene.scan_to_map;
  truth.topRightCorner<3, 1>() -= reg.getLocalOrigin();
  o.error = computeTransformationError (
      reg.getFinalTransformationDouble(), truth, centroidOf (*b.cloud));
  reg.getPlaneDistances (o.distances);
  o.scan_planes = reg.getSourcePlanes().size();
  o.map_planes = reg.getMapPlanes().size();
  o.matches = reg.getMatchingResult().matches.size();
  o.statistics = reg.getMatchingResult().statistics;
  for (const auto& pair : reg.getMatchingResult().matches) {
    const Plane moved = transformPlane (reg.getSourcePlanes()[pair.scan], truth);
    const Plane& map = reg.getMapPlanes()[pair.map];
    if (std::abs (moved.normal.dot (map.normal)) < std::cos (2.0 * M_PI / 180.0) ||
        std::abs (map.signedDistance (moved.centroid)) > 0.5)
      ++o.wrong;
  }
  if (std::getenv ("PCL_EXT_DEBUG_PLANES"))
    for (std::size_t i = 0; i < reg.getSourcePlanes().size(); ++i) {
      const Plane moved = transformPlane (reg.getSourcePlanes()[i], truth);
      int matched = -1;
      for (const auto& pair : reg.getMatchingResult().matches)
        if (pair.scan == static_cast<int> (i))
          matched = pair.map;
      double best = 1e9;
      int best_map = -1;
      for (std::size_t j = 0; j < reg.getMapPlanes().size(); ++j) {
        const auto& m = reg.getMapPlanes()[j];
        if (std::abs (moved.normal.dot (m.normal)) > std::cos (3.0 * M_PI / 180.0) &&
            std::abs (m.signedDistance (moved.centroid)) < best) {
          best = std::abs (m.signedDistance (moved.centroid));
          best_map = static_cast<int> (j);
        }
      }
      std::printf ("  plane %zu: %zu pts rms %.2f n (%.3f %.3f %.3f) c (%.1f %.1f "
                   "%.1f) nearest map %d at %.2f m, matched %d\n",
                   i,
                   reg.getSourcePlanes()[i].size,
                   reg.getSourcePlanes()[i].rms,
                   moved.normal.x(),
                   moved.normal.y(),
                   moved.normal.z(),
                   moved.centroid.x(),
                   moved.centroid.y(),
                   moved.centroid.z(),
                   best_map,
                   best,
                   matched);
    }
  return o;
}
} // namespace test
} // namespace pcl_ext
