/*
 * pcl_ext: scene registry and scanning of described scenes.
 */
#include "scene_parts.h"

#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/simulation/tls_scanner.h>

#include <pcl/console/print.h>

#include <cmath>
#include <functional>
#include <map>

namespace pcl_ext {
namespace simulation {
namespace {
using Builder = std::function<void (const SceneParameters&, SceneDescription&)>;

const std::vector<std::pair<std::string, Builder>>&
registry ()
{
  static const std::vector<std::pair<std::string, Builder>> scenes{
      {"indoor", describeIndoorScene},
      {"cubes", describeCubesScene},
      {"spheres", describeSpheresScene},
      {"coaxial", describeCoaxialScene},
      {"pipes", describePipesScene},
      {"tree", describeTreeScene},
      {"building", describeBuildingScene},
      {"street", describeStreetScene}};
  return scenes;
}

// 100 million simulated points take about 5 GB: more is certainly a typing error.
constexpr std::size_t kMaxPoints = 100000000;

bool
finiteNonNegative (double v)
{
  return std::isfinite (v) && v >= 0.0;
}
} // namespace

std::vector<std::string>
sceneNames ()
{
  std::vector<std::string> names;
  for (const auto& entry : registry())
    names.push_back (entry.first);
  return names;
}

bool
checkSceneParameters (const SceneParameters& p)
{
  const char* fn = "[pcl_ext::simulation::generateScene]";
  if (!finiteNonNegative (p.noise) || !finiteNonNegative (p.noise_per_metre)) {
    PCL_ERROR ("%s Noise must be finite and >= 0 (got %g, %g per metre).\n",
               fn,
               p.noise,
               p.noise_per_metre);
    return false;
  }
  if (!finiteNonNegative (p.angular_step_deg) || p.angular_step_deg > 10.0 ||
      (p.angular_step_deg > 0.0 && p.angular_step_deg < 1e-3)) {
    PCL_ERROR (
        "%s Angular step must be in [0.001, 10] degrees (0 = default), got %g.\n",
        fn,
        p.angular_step_deg);
    return false;
  }
  if (p.points > kMaxPoints) {
    PCL_ERROR (
        "%s At most %zu points can be asked for, got %zu.\n", fn, kMaxPoints, p.points);
    return false;
  }
  if (!finiteNonNegative (p.edge_distance) || !finiteNonNegative (p.max_range)) {
    PCL_ERROR ("%s Edge distance and maximum range must be finite and >= 0.\n", fn);
    return false;
  }
  if (p.num_scanners < 0 || p.num_scanners > 1000) {
    PCL_ERROR (
        "%s Number of scanners must be in [0, 1000], got %d.\n", fn, p.num_scanners);
    return false;
  }
  for (const auto& q : p.scan_positions)
    if (!q.allFinite()) {
      PCL_ERROR ("%s Scan positions must be finite.\n", fn);
      return false;
    }
  if (!p.offset.allFinite()) {
    PCL_ERROR ("%s Offset must be finite.\n", fn);
    return false;
  }
  if (!(std::isfinite (p.building_height) && p.building_height > 0.5)) {
    PCL_ERROR ("%s Building height must be > 0.5 m, got %g.\n", fn, p.building_height);
    return false;
  }
  if (p.superfluous_planes < 0 || p.missing_walls < 0 || p.superfluous_planes > 100) {
    PCL_ERROR ("%s Superfluous planes (<= 100) and missing walls must be >= 0.\n", fn);
    return false;
  }
  if (!p.footprint.empty()) {
    bool finite = p.footprint.size() >= 3;
    for (const auto& q : p.footprint)
      finite = finite && q.allFinite();
    if (!finite || std::abs (detail::signedArea (p.footprint)) < 1.0) {
      PCL_ERROR (
          "%s Footprint must be a polygon of >= 3 finite vertices and area >= 1 m^2.\n",
          fn);
      return false;
    }
  }
  if (p.has_pose && !p.pose.matrix().allFinite()) {
    PCL_ERROR ("%s Pose must be finite.\n", fn);
    return false;
  }
  return true;
}

bool
describeScene (const std::string& name,
               const SceneParameters& parameters,
               SceneDescription& description)
{
  description = SceneDescription();
  if (!checkSceneParameters (parameters))
    return false;
  for (const auto& entry : registry())
    if (entry.first == name) {
      description.name = name;
      entry.second (parameters, description);
      if (!parameters.scan_positions.empty())
        description.scan_positions = parameters.scan_positions;
      if (parameters.max_range > 0.0)
        description.max_range = parameters.max_range;
      description.geometry.build();
      return true;
    }
  std::string names;
  for (const auto& n : sceneNames())
    names += (names.empty() ? "" : ", ") + n;
  PCL_ERROR ("[pcl_ext::simulation::describeScene] Unknown scene '%s' (known: %s).\n",
             name.c_str(),
             names.c_str());
  return false;
}

bool
scanScene (const std::shared_ptr<const SceneDescription>& description,
           const SceneParameters& parameters,
           SyntheticScene& scene)
{
  scene = SyntheticScene();
  if (!description || !checkSceneParameters (parameters))
    return false;
  const SceneDescription& d = *description;

  TlsScanSimulation scanner;
  scanner.setScanPositions (d.scan_positions);
  scanner.setMaximumRange (d.max_range);
  scanner.setRangeNoise (parameters.noise, parameters.noise_per_metre);
  scanner.setEdgeDistance (parameters.edge_distance);
  scanner.setCoverageBoundaries (parameters.coverage_boundaries);
  scanner.setConnectedSegments (parameters.connected_segments);
  scanner.setSeed (parameters.seed);
  scanner.setNumberOfThreads (parameters.threads);
  if (!scanner.checkParameters())
    return false;

  double step = d.angular_step_deg;
  const std::size_t target =
      parameters.points > 0 ? parameters.points : d.default_points;
  if (parameters.angular_step_deg > 0.0)
    step = parameters.angular_step_deg;
  else if (target > 0) {
    step = scanner.stepForPointCount (d.geometry, target);
    if (!(step > 0.0)) {
      PCL_ERROR ("[pcl_ext::simulation::scanScene] Scene '%s' returns no points.\n",
                 d.name.c_str());
      return false;
    }
    if (step < 1e-3) {
      PCL_ERROR (
          "[pcl_ext::simulation::scanScene] %zu points would need an angular step of "
          "%g degrees (< 0.001).\n",
          target,
          step);
      return false;
    }
    step = std::min (step, 10.0);
  }
  scanner.setAngularStep (step);

  // The scan frame: a large offset (georeferenced-looking coordinates) or, for the
  // building, an arbitrary pose of the scanner's frame with respect to the map.
  Eigen::Isometry3d cloud_from_scene = Eigen::Isometry3d::Identity();
  const bool is_building = !d.footprint.empty();
  if (is_building) {
    if (parameters.has_pose)
      cloud_from_scene = parameters.pose;
    else if (parameters.random_pose) {
      RandomStream rng = detail::layoutStream (parameters.seed, 0x9053ULL);
      const double yaw = 6.283185307179586 * rng.uniform();
      const double ten_degrees = 0.17453292519943295;
      const double pitch = (2.0 * rng.uniform() - 1.0) * ten_degrees;
      const double roll = (2.0 * rng.uniform() - 1.0) * ten_degrees;
      cloud_from_scene.linear() = detail::rotationYpr (yaw, pitch, roll);
      cloud_from_scene.translation() = Vec3 ((rng.uniform() - 0.5) * 200.0,
                                             (rng.uniform() - 0.5) * 200.0,
                                             (rng.uniform() - 0.5) * 20.0);
    }
  }
  else
    cloud_from_scene.translation() = parameters.offset;
  scanner.setOutputTransform (cloud_from_scene);

  if (!scanner.scan (d.geometry,
                     scene.cloud,
                     &scene.scanner_of_point,
                     &scene.surface_of_segment)) {
    scene = SyntheticScene();
    return false;
  }
  scene.name = d.name;
  scene.scan_positions = d.scan_positions;
  scene.angular_step_deg = step;
  scene.noise = parameters.noise;
  scene.noise_per_metre = parameters.noise_per_metre;
  scene.edge_distance = parameters.edge_distance;
  scene.has_rgb = d.has_rgb;
  scene.has_intensity = d.has_intensity;
  scene.has_label = d.has_label;
  scene.label_names = d.label_names;
  scene.cloud_from_scene = cloud_from_scene;
  scene.description = description;
  if (is_building) {
    for (const auto& q : d.footprint)
      scene.footprint.push_back (q + parameters.offset.head<2>());
    Eigen::Isometry3d map_from_scene = Eigen::Isometry3d::Identity();
    map_from_scene.translation() = parameters.offset;
    scene.scan_to_map = (map_from_scene * cloud_from_scene.inverse()).matrix();
  }
  return true;
}

bool
generateScene (const std::string& name,
               const SceneParameters& parameters,
               SyntheticScene& scene)
{
  scene = SyntheticScene();
  auto description = std::make_shared<SceneDescription>();
  if (!describeScene (name, parameters, *description))
    return false;
  return scanScene (description, parameters, scene);
}
} // namespace simulation
} // namespace pcl_ext
