/*
 * pcl_ext_demo step: Khoshelham & Gorte plane matching of the `building` scan to its 2D
 * footprint, checked against the scene's true scan-to-map transform.
 */
#include "demo_context.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/footprint_view.h>

#include <pcl/common/io.h>
#include <pcl/common/transforms.h>

namespace pcl_ext {
namespace demo {
bool
runRegistrationStep (DemoContext& context)
{
  // A levelled scanner (as TLS are) in an unknown heading and position: the scene's own
  // random pose also tilts the scan, which plane matching with the vertical constraint
  // refuses.
  simulation::SceneParameters parameters;
  parameters.seed = context.seed;
  parameters.threads = context.threads;
  parameters.random_pose = false;
  parameters.has_pose = true;
  parameters.pose = Eigen::Translation3d (14.0, -9.0, 0.0) *
                    Eigen::AngleAxisd (0.65, Eigen::Vector3d::UnitZ());
  auto owned = std::make_unique<simulation::SyntheticScene>();
  if (!simulation::generateScene ("building", parameters, *owned) ||
      owned->footprint.size() < 3)
    return false;
  const auto* scene = owned.get();
  pcl::PointCloud<pcl::PointXYZ>::Ptr scan (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (scene->cloud, *scan);

  io::Footprint footprint;
  footprint.id = "building";
  footprint.polygons.resize (1);
  footprint.polygons[0].outer = scene->footprint;

  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  if (!reg.setFootprints ({footprint}, MapPlaneParameters()))
    return false;
  SACPlaneExtraction<pcl::PointXYZ> extraction;
  reg.setPlaneExtractor (extraction.asExtractor());
  reg.setNumberOfThreads (context.threads);
  reg.setInputSource (scan);
  // The scanner positions are known, so plane normals can be turned towards them.
  ScanViewpoints viewpoints;
  for (const auto& position : scene->scan_positions)
    viewpoints.positions.push_back (scene->cloud_from_scene * position);
  viewpoints.scanner_of_point = scene->scanner_of_point;
  reg.setSourceViewpoints (viewpoints);
  reg.setOrientedNormals (true);
  pcl::PointCloud<pcl::PointXYZ> registered;
  apps::StageTimer timer ("Registering 'building' to its footprint (plane matching)");
  reg.align (registered);
  const double ms = timer.done (reg.getMatchingResult().matches.size());
  if (!reg.hasConverged()) {
    context.summary << "  building: registration did not converge\n";
    return false;
  }
  // The class works in map coordinates minus a local origin; put it back to compare.
  Eigen::Matrix4d scan_to_map = reg.getFinalTransformationDouble();
  scan_to_map.block<3, 1> (0, 3) += reg.getLocalOrigin();
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid (*scan, centroid);
  const auto error = computeTransformationError (
      scan_to_map, scene->scan_to_map, centroid.head<3>().cast<double>());
  PlaneDistanceMetrics d;
  reg.getPlaneDistances (d);
  context.summary << "  building: " << scan->size() << " points, "
                  << reg.getSourcePlanes().size() << " scan planes, "
                  << reg.getMapPlanes().size() << " map planes, "
                  << reg.getMatchingResult().matches.size() << " matched in " << ms
                  << " ms; rotation error " << error.rotation_deg
                  << " deg, translation error " << error.translation
                  << " m; plane distances mean " << d.mean << " m, max " << d.max
                  << " m\n";

  // Top view: the registered scan's wall points (inliers of its vertical planes),
  // coloured by their distance to the footprint drawn over them.
  std::vector<Eigen::Vector3d> walls;
  for (const auto& plane : reg.getSourcePlanes()) {
    const Eigen::Vector3d n = scan_to_map.topLeftCorner<3, 3>() * plane.normal;
    if (!(std::abs (n.z()) < 0.3))
      continue;
    for (const auto i : plane.inliers.indices)
      walls.push_back ((scan_to_map *
                        Eigen::Vector4d ((*scan)[i].x, (*scan)[i].y, (*scan)[i].z, 1.0))
                           .head<3>());
  }
  visualization::FootprintSegments outline;
  const auto& ring = scene->footprint;
  for (std::size_t i = 0; i < ring.size(); ++i)
    outline.emplace_back (ring[i], ring[(i + 1) % ring.size()]);
  visualization::RenderOptions options;
  options.width = 1000;
  options.height = 900;
  options.view = visualization::ViewKind::Top;
  return context.render (
      {visualization::makeFootprintView (
          "building: wall points registered to the footprint", walls, outline)},
      "registration_building.png",
      options);
}
} // namespace demo
} // namespace pcl_ext
