/*
 * pcl_ext_register_to_map: register a building scan to its 2D footprint by plane
 * matching (Khoshelham & Gorte 2009).
 */
#include "register_to_map_defaults.h"
#include "register_to_map_output.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/footprints.h>
#include <pcl_ext/io/transform_file.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/picture_options.h>
#include <pcl_ext/io/file_output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/footprint_view.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

namespace {
using Point = pcl::PointXYZ;

#ifdef PCL_EXT_HAVE_VISUALIZATION
// Top view (figures 3 and 5): the scan's wall points (inliers of its vertical planes)
// moved by \a transform, coloured by their distance to the footprint drawn over them.
pcl_ext::visualization::View
renderTopView (const pcl::PointCloud<Point>& scan,
               const std::vector<pcl_ext::ScanPlane>& planes,
               const Eigen::Matrix4d& transform,
               const std::vector<pcl_ext::MapPlane>& map,
               const std::string& title)
{
  pcl_ext::visualization::FootprintSegments footprint;
  for (const auto& wall : map)
    if (!wall.isFloor())
      footprint.emplace_back (wall.start, wall.end);
  std::vector<Eigen::Vector3d> walls;
  for (const auto& plane : planes) {
    // Walls are vertical in the scan as in the map (the registration is about z only
    // up to a small tilt).
    const Eigen::Vector3d n = transform.topLeftCorner<3, 3>() * plane.normal;
    if (!(std::abs (n.z()) < 0.3))
      continue;
    for (const auto i : plane.inliers.indices)
      walls.push_back (
          (transform * Eigen::Vector4d (scan[i].x, scan[i].y, scan[i].z, 1.0))
              .head<3>());
  }
  return pcl_ext::visualization::makeFootprintView (title, walls, footprint);
}
#endif

// Refuses footprints that no footprint vertex puts within 1 km of the scan's points
// (local frame: the scan's origin is subtracted from both): a wrong file or a wrong
// coordinate system, which no registration can bridge.
bool
footprintNearScan (const std::vector<pcl_ext::io::Footprint>& footprints,
                   const Eigen::Vector3d& origin,
                   const pcl::PointCloud<Point>& scan)
{
  Eigen::AlignedBox2d box;
  for (const auto& p : scan)
    if (pcl::isXYZFinite (p))
      box.extend (Eigen::Vector2d (p.x, p.y));
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& f : footprints)
    for (const auto& polygon : f.polygons)
      for (const auto& q : polygon.outer)
        nearest = std::min (nearest, box.exteriorDistance (q - origin.head<2>()));
  if (box.isEmpty() || nearest <= 1000.0)
    return true;
  std::cerr << "Error: the footprint is " << nearest
            << " m from the scan's points (more than 1 km): not the same place or not "
               "the same coordinate system.\n";
  return false;
}

} // namespace
using pcl_ext::apps::candidatePath;
using pcl_ext::apps::poseDistance;
using pcl_ext::apps::transformXyz;
using pcl_ext::apps::writeTransform;

int
main (int argc, char** argv)
{
  std::string input, footprint_path, output, png, png_before, no_constraint, id,
      guess_path, transform_out;
  std::string walls = "auto", label_field;
  int k = 4, m = 0, n = 0, max_planes = 30, min_inliers = 200;
  unsigned int threads = 0, ground_label = 2, building_label = 6;
  double threshold = 0.4, angle = 3.0, distance = 0.5, floor_height = 0.0;
  double max_rotation = std::numeric_limits<double>::infinity();
  double max_translation = std::numeric_limits<double>::infinity();
  bool similarity = false, oriented = false, levelled = false;
  std::string initial = "walls";
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_register_to_map",
      "Registers a building scan to its 2D footprint by plane matching "
      "(Khoshelham & Gorte 2009). The output cloud and -transform_out are in map "
      "coordinates.");
  cl.addPositional ("scan",
                    input,
                    std::string ("the building scan: ") + pcl_ext::apps::kInputFormats);
  cl.addPositional ("footprint.(wkt|geojson|csv|txt)",
                    footprint_path,
                    "footprint polygons: WKT, GeoJSON, CSV with a geometry column "
                    "(.csv) or text (told by content)");
  cl.addPositional ("output",
                    output,
                    "the registered scan in map coordinates, every input field kept: "
                    ".las, .pcd or .ply");
  cl.addOption ("transform_out",
                transform_out,
                "write the scan-to-map 4x4 transform (map coordinates, row by row) "
                "to this file");
  cl.addOption ("k", k, "initial pairs per combination (paper: k)");
  cl.addOption ("m",
                m,
                "scan planes used to initiate (paper: m); 0: from the data, every scan "
                "plane (at most 64)");
  cl.addOption ("n",
                n,
                "map planes used to initiate (paper: n); 0: from the data, every map "
                "plane of the footprints near the scan (at most 64)");
  cl.addSwitch ("similarity",
                similarity,
                "estimate a similarity (with scale) instead of a rigid transform");
  cl.addOption (
      "no_constraint",
      no_constraint,
      "switch a constraint off: vertical, orientation or residual (comma separated)");
  cl.addOption (
      "angle", angle, "residual and extension tolerance on normals (degrees)");
  cl.addOption (
      "distance", distance, "residual and extension tolerance on plane offsets (m)");
  cl.addSwitch ("levelled",
                levelled,
                "take the scan as levelled (the paper's assumption) instead of finding "
                "its vertical from its planes");
  cl.addOption ("initial",
                initial,
                "initial planes: walls (the ground, then the walls longest in plan) or "
                "largest (the paper's choice, by size)");
  cl.addSwitch ("oriented",
                oriented,
                "use plane signs (scan normals to the scanner, walls outward)");
  cl.addOption (
      "guess",
      guess_path,
      "initial guess: a scan-to-map 4x4 transform file in map coordinates (e.g. the "
      ".transform.txt of pcl_ext_generate_scene); none: the identity (a georeferenced "
      "scan)");
  cl.addOption ("max_rotation_from_guess",
                max_rotation,
                "search only within this rotation of the guess (degrees, > 0; "
                "unbounded when left out: the paper's global search)");
  cl.addOption ("max_translation_from_guess",
                max_translation,
                "search only within this translation of the guess (m, > 0; unbounded "
                "when left out)");
  cl.addOption (
      "walls",
      walls,
      "plane extraction: sac (sequential RANSAC, for terrestrial scans), "
      "roof_outline (a classified airborne cloud: ground plane and walls along the "
      "building outlines) or auto (sac, and roof_outline when sac finds fewer than 3 "
      "walls and the cloud has building-class points)");
  cl.addOption (
      "label_field",
      label_field,
      "roof_outline: the field holding the point classes (default: 'label', or the LAS "
      "'classification' when there is no 'label')");
  cl.addOption (
      "ground_label", ground_label, "roof_outline: class of ground points (LAS: 2)");
  cl.addOption ("building_label",
                building_label,
                "roof_outline: class of building points (LAS: 6)");
  cl.addOption (
      "threshold",
      threshold,
      "sac: RANSAC inlier distance (m); left out: 3 noise sigmas of the scan, "
      "at least half its spacing (0.4 when they cannot be estimated)");
  cl.addOption (
      "min_inliers",
      min_inliers,
      "sac: least points of a plane; left out: those of 1.25 m^2 at the scan's "
      "spacing, at least 50 (200 when it cannot be estimated)");
  cl.addOption ("max_planes", max_planes, "sac: most planes");
  cl.addOption ("floor",
                floor_height,
                "floor height in map coordinates (m); when left out: 0, or with roof "
                "outlines and footprints in a projected system (beyond 1 km of its "
                "zero) the median height of the ground-class points under the guess");
  cl.addOption ("id", id, "use only the footprint with this id (default: all)");
  cl.addOption ("threads", threads, "threads of the search (0 = all cores)");
  cl.addOption ("png", png, "top view of the registered scan over the footprint");
  cl.addOption ("png_before", png_before, "top view before registration");
  pcl_ext::apps::PictureOptions picture;
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;

  // Bad values are refused before anything is read or written.
  if (!(max_rotation > 0.0)) {
    std::cerr << "Error: -max_rotation_from_guess must be > 0 degrees (leave it out "
                 "for no bound).\n";
    return 1;
  }
  if (!(max_translation > 0.0)) {
    std::cerr << "Error: -max_translation_from_guess must be > 0 m (leave it out for "
                 "no bound).\n";
    return 1;
  }
  if (initial != "walls" && initial != "largest") {
    std::cerr << "Error: unknown -initial '" << initial << "' (walls, largest).\n";
    return 1;
  }
  bool roof_outline = walls == "roof_outline";
  if (!roof_outline && walls != "sac" && walls != "auto") {
    std::cerr << "Error: unknown -walls '" << walls << "' (auto, sac, roof_outline).\n";
    return 1;
  }
  for (const char* option : {"label_field", "ground_label", "building_label"})
    if (walls == "sac" && cl.given (option)) {
      std::cerr << "Error: -" << option
                << " applies to -walls roof_outline or auto, not sac.\n";
      return 1;
    }
  if ((m != 0 && m < k) || (n != 0 && n < k) || m < 0 || n < 0 || m > 64 || n > 64) {
    std::cerr << "Error: -m and -n must be 0 (from the data) or in [k, 64].\n";
    return 1;
  }
  if (roof_outline && ground_label == building_label) {
    std::cerr << "Error: -ground_label and -building_label must differ.\n";
    return 1;
  }
  if (!pcl_ext::io::checkOutputsWritable (output, {png, png_before, transform_out}))
    return 1;
  Eigen::Matrix4d guess = Eigen::Matrix4d::Identity();
  if (!guess_path.empty()) {
    try {
      pcl_ext::io::loadTransform (guess_path, guess);
    }
    catch (const pcl_ext::io::ReadError& e) {
      std::cerr << "Error: " << e.what() << "\n";
      return 1;
    }
  }

  pcl_ext::PlaneMatchingRegistration<Point, Point> reg;
  for (std::stringstream list (no_constraint); list.good();) {
    std::string name;
    std::getline (list, name, ',');
    if (name == "vertical")
      reg.setVerticalConstraint (false);
    else if (name == "orientation")
      reg.setOrientationConstraint (false);
    else if (name == "residual")
      reg.setResidualConstraint (false);
    else if (!name.empty()) {
      std::cerr << "Error: unknown constraint '" << name
                << "' (vertical, orientation, residual).\n";
      return 1;
    }
  }

  pcl::PointCloud<Point>::Ptr scan (new pcl::PointCloud<Point>);
  pcl::PointCloud<pcl::Label>::Ptr labels (new pcl::PointCloud<pcl::Label>);
  pcl_ext::io::PointFile point_file;
  if (!pcl_ext::apps::loadInput (input, point_file, *scan))
    return 1;
  if (walls != "sac") {
    std::vector<std::uint32_t> values;
    std::string error;
    if (label_field.empty())
      label_field = pcl::getFieldIndex (point_file.cloud, "label") >= 0
                        ? "label"
                        : "classification";
    if (pcl_ext::io::getLabelField (point_file.cloud, label_field, values, &error))
      for (const auto v : values)
        labels->push_back (pcl::Label{v});
    else if (roof_outline || cl.given ("label_field")) {
      std::cerr << "Error: " << input << ": " << error << " (-label_field).\n";
      return 1;
    }
  }
  std::vector<pcl_ext::io::Footprint> footprints;
  try {
    pcl_ext::io::loadFootprints (footprint_path, footprints);
  }
  catch (const pcl_ext::io::ReadError& e) {
    std::cerr << "Error: " << e.what() << "\n";
    return 1;
  }
  if (!id.empty()) {
    std::vector<pcl_ext::io::Footprint> chosen;
    for (const auto& f : footprints)
      if (f.id == id)
        chosen.push_back (f);
    if (chosen.empty()) {
      std::cerr << "Error: no footprint with id '" << id << "' in " << footprint_path
                << ".\n";
      return 1;
    }
    footprints.swap (chosen);
  }
  pcl_ext::MapPlaneParameters map_parameters;
  // A georeferenced scan is loaded relative to its origin: the footprints are shifted
  // by the same origin, so that both are in one local frame.
  map_parameters.origin = point_file.origin;
  if (!footprintNearScan (footprints, point_file.origin, *scan))
    return 1;
  // The scan in map coordinates, as the guess puts it.
  auto toMapFrame = [&] (const Point& p) {
    return (guess *
            (p.getVector3fMap().cast<double>() + point_file.origin).homogeneous())
        .head<3>()
        .eval();
  };
  Eigen::AlignedBox3d scan_box;
  for (const auto& p : *scan)
    if (pcl::isXYZFinite (p))
      scan_box.extend (toMapFrame (p));
  // Footprints within a tenth of the scan's extent of it; all when none is.
  if (id.empty() && !scan_box.isEmpty()) {
    std::vector<pcl_ext::io::Footprint> near;
    const double margin = 0.1 * scan_box.sizes().head<2>().maxCoeff();
    if (pcl_ext::selectFootprintsNearScan (footprints, scan_box, margin, near) &&
        near.size() < footprints.size()) {
      std::printf (
          "Footprints near the scan: %zu of %zu\n", near.size(), footprints.size());
      footprints.swap (near);
    }
  }

  // Walls from the data: sequential RANSAC, and the roof outlines of a classified
  // airborne cloud when RANSAC finds fewer than 3 walls.
  pcl::IndicesPtr roofs (new pcl::Indices); // the building-class points
  for (std::size_t i = 0; labels->size() == scan->size() && i < labels->size(); ++i)
    if ((*labels)[i].label == building_label)
      roofs->push_back (static_cast<pcl::index_t> (i));
  const bool has_buildings = !roofs->empty();
  if (!roof_outline) {
    const auto settings =
        pcl_ext::apps::wallExtractionSettings (*scan,
                                               threads,
                                               {threshold, min_inliers},
                                               !cl.given ("threshold"),
                                               !cl.given ("min_inliers"));
    pcl_ext::SACPlaneExtraction<Point> extraction;
    extraction.setDistanceThreshold (settings.inlier_distance);
    extraction.setMinInliers (settings.min_inliers);
    extraction.setMaxPlanes (max_planes);
    if (walls == "auto" && has_buildings) {
      std::vector<pcl::PointIndices> sets;
      extraction.setInputCloud (scan);
      extraction.extract (sets);
      std::vector<pcl_ext::ScanPlane> planes;
      roof_outline = pcl_ext::countVerticalPlanes (*scan, sets) < 3;
      if (!roof_outline &&
          pcl_ext::fitScanPlanes (*scan, sets, pcl_ext::ScanViewpoints(), planes))
        reg.setSourcePlanes (planes);
      if (roof_outline)
        std::printf ("Walls: fewer than 3 from RANSAC, taken from the roof outlines\n");
    }
    if (!roof_outline)
      reg.setPlaneExtractor (extraction.asExtractor());
  }
  if (roof_outline) {
    pcl_ext::RoofOutlinePlaneExtraction<Point> extraction;
    extraction.setInputLabels (labels);
    extraction.setGroundLabel (ground_label);
    extraction.setBuildingLabel (building_label);
    reg.setPlaneExtractor (extraction.asExtractor());
    // The roofs lie over the footprints: a pose that puts fewer there is not chosen.
    reg.setCoverageIndices (roofs);
  }
  // The map has no heights: with footprints in a projected system (beyond 1 km of its
  // zero), heights are absolute, and a classified airborne cloud gives its ground's.
  map_parameters.floor_height = floor_height;
  Eigen::Vector3d map_centre = Eigen::Vector3d::Zero();
  if (roof_outline && !cl.given ("floor") &&
      pcl_ext::chooseLocalOrigin (footprints, map_centre) &&
      map_centre.norm() > 1000.0) {
    std::vector<double> ground;
    for (std::size_t i = 0; i < scan->size(); ++i)
      if ((*labels)[i].label == ground_label && pcl::isXYZFinite ((*scan)[i]))
        ground.push_back (toMapFrame ((*scan)[i]).z());
    if (!ground.empty()) {
      std::nth_element (
          ground.begin(), ground.begin() + ground.size() / 2, ground.end());
      map_parameters.floor_height = ground[ground.size() / 2];
      std::printf ("Floor: %.3f m, the ground's median height\n",
                   map_parameters.floor_height);
    }
  }
  if (!reg.setFootprints (footprints, map_parameters))
    return 1;
  // m and n from the data: every plane (at most 64).
  if (m == 0)
    m = 64;
  if (n == 0)
    n = 64;
  reg.setMaxRotationFromGuess (max_rotation);
  reg.setMaxTranslationFromGuess (max_translation);
  reg.setInitialPairs (k);
  reg.setInitialScanPlanes (m);
  reg.setInitialMapPlanes (n);
  reg.setSimilarity (similarity);
  reg.setTolerances (angle, distance);
  reg.setOrientedNormals (oriented);
  reg.setEstimateVertical (!levelled);
  {
    pcl_ext::PlaneMatchingParameters p = reg.getMatchingParameters();
    p.walls_first = initial == "walls";
    reg.setMatchingParameters (p);
  }
  reg.setNumberOfThreads (threads);
  reg.setInputSource (scan);

  // The guess is in map coordinates; the registration works in the map's local frame.
  Eigen::Matrix4d local_guess = guess;
  local_guess.topRightCorner<3, 1>() +=
      guess.topLeftCorner<3, 3>() * point_file.origin - reg.getLocalOrigin();
  if (!guess_path.empty() || std::isfinite (max_rotation) ||
      std::isfinite (max_translation))
    std::printf ("Search within %g deg and %g m of the guess%s\n",
                 max_rotation,
                 max_translation,
                 guess_path.empty() ? " (the identity)"
                                    : (" in " + guess_path).c_str());

  pcl::PointCloud<Point> registered;
  {
    pcl_ext::apps::StageTimer timer ("Extracting and matching planes");
    reg.align (registered, local_guess.cast<float>());
    timer.done (reg.getMatchingResult().matches.size());
  }
  const auto& result = reg.getMatchingResult();
  const auto& s = result.statistics;
  std::printf ("Planes: %zu scan, %zu map; local origin (%.3f, %.3f, %.3f)\n",
               reg.getSourcePlanes().size(),
               reg.getMapPlanes().size(),
               reg.getLocalOrigin().x(),
               reg.getLocalOrigin().y(),
               reg.getLocalOrigin().z());
  std::printf ("Initial combinations (m = %d, n = %d, k = %d): %llu without "
               "constraints, %llu vertical, "
               "%llu + orientation (%llu degenerate), %llu + residual; search %.3f s\n",
               s.m,
               s.n,
               s.k,
               (unsigned long long)s.unconstrained,
               (unsigned long long)s.vertical,
               (unsigned long long)s.orientation,
               (unsigned long long)s.degenerate,
               (unsigned long long)s.residual,
               s.seconds);
  if (!reg.hasConverged()) {
    std::cerr << "Error: the registration did not converge (see the messages above).\n";
    return 1;
  }
  // Scan file to map coordinates: file - scan origin, the local transform, + map
  // origin.
  auto toMap = [&] (const Eigen::Matrix4d& local) {
    Eigen::Matrix4d to_map = local;
    to_map.topRightCorner<3, 1>() +=
        reg.getLocalOrigin() - local.topLeftCorner<3, 3>() * point_file.origin;
    return to_map;
  };
  // A symmetric footprint: every pose supported as well as the best, ranked; the guess
  // picks among them when given.
  const auto& candidates = result.candidates;
  std::size_t chosen = 0;
  if (!guess_path.empty())
    for (std::size_t c = 1; c < candidates.size(); ++c)
      if (poseDistance (candidates[c].estimate.transformation, local_guess) <
          poseDistance (candidates[chosen].estimate.transformation, local_guess))
        chosen = c;
  if (candidates.size() > 1) {
    std::cerr << "Warning: " << candidates.size()
              << " poses fit the footprint equally well (a symmetric footprint); "
              << (guess_path.empty() ? "the first is written"
                                     : "the one nearest the guess is written")
              << (transform_out.empty() ? "" : ", all of them next to -transform_out")
              << ".\n";
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const Eigen::Matrix4d m = toMap (candidates[c].estimate.transformation);
      std::printf ("Candidate %zu (%zu pairs)%s:\n",
                   c + 1,
                   candidates[c].matches.size(),
                   c == chosen ? ", chosen" : "");
      for (int r = 0; r < 3; ++r)
        std::printf (
            "  %12.6f %12.6f %12.6f %14.4f\n", m (r, 0), m (r, 1), m (r, 2), m (r, 3));
      if (!transform_out.empty() &&
          !writeTransform (candidatePath (transform_out, c + 1), m))
        return 1;
    }
  }
  const pcl_ext::PlaneMatchingCandidate fallback{0, result.matches, result.estimate};
  const pcl_ext::PlaneMatchingCandidate& pick =
      candidates.empty() ? fallback : candidates[chosen];
  const Eigen::Matrix4d t = pick.estimate.transformation;
  std::printf ("Transformation (scan to map - origin):\n");
  for (int r = 0; r < 4; ++r)
    std::printf (
        "  %12.6f %12.6f %12.6f %12.4f\n", t (r, 0), t (r, 1), t (r, 2), t (r, 3));
  std::printf (
      "Match set (%zu pairs): scan plane -> map plane [angle deg, distance m]\n",
      pick.matches.size());
  const auto& residuals = pick.estimate;
  for (std::size_t i = 0; i < pick.matches.size(); ++i) {
    const auto& pair = pick.matches[i];
    const auto& map = reg.getMapPlanes()[pair.map];
    const bool known =
        i < residuals.angle_residuals.size() && i < residuals.distance_residuals.size();
    std::printf ("  %3d (%6zu pts) -> %3d (%s) [%.2f, %.3f]\n",
                 pair.scan,
                 reg.getSourcePlanes()[pair.scan].size,
                 pair.map,
                 map.isFloor() ? "floor"
                               : ("wall, edge " + std::to_string (map.edge)).c_str(),
                 known ? residuals.angle_residuals[i] * 180.0 / M_PI : NAN,
                 known ? residuals.distance_residuals[i] : NAN);
  }
  // Tables 1-2: the distances of the matched scan planes' inliers to their map planes.
  pcl_ext::PlaneDistanceMetrics d;
  pcl_ext::computePlaneDistances (*scan,
                                  reg.getSourcePlanes(),
                                  reg.getTargetPlanes(),
                                  pick.matches,
                                  pick.estimate.transformation,
                                  d);
  std::printf ("Plane distances (Tables 1-2): mean %.3f m, max %.3f m, rms %.3f m over "
               "%zu points\n",
               d.mean,
               d.max,
               d.rms,
               d.points);
  // Scan file to map coordinates: file - scan origin, the local transform, + map
  // origin.
  Eigen::Matrix4d to_map = t;
  to_map.topRightCorner<3, 1>() +=
      reg.getLocalOrigin() - t.topLeftCorner<3, 3>() * point_file.origin;
  if (!transform_out.empty() && !writeTransform (transform_out, to_map))
    return 1;
  transformXyz (t, point_file.cloud);
  if (!pcl_ext::io::savePointFile (
          output, point_file.cloud, reg.getLocalOrigin(), &point_file)) {
    std::cerr << "Error: could not write " << output << ".\n";
    return 1;
  }
#ifdef PCL_EXT_HAVE_VISUALIZATION
  pcl_ext::visualization::RenderOptions options;
  options.view = pcl_ext::visualization::ViewKind::Top; // -view auto: the top view
  pcl_ext::visualization::parseViewKind (picture.view, options.view);
  if (options.view == pcl_ext::visualization::ViewKind::Auto)
    options.view = pcl_ext::visualization::ViewKind::Top;
  picture.maxHeight (options.max_height);
  options.width = 1000;
  options.height = 900;
  for (const auto& [path, before] :
       {std::make_pair (png, false), std::make_pair (png_before, true)}) {
    if (path.empty())
      continue;
    const pcl_ext::visualization::View view =
        renderTopView (*scan,
                       reg.getSourcePlanes(),
                       before ? Eigen::Matrix4d::Identity() : t,
                       reg.getMapPlanes(),
                       before ? "wall points before registration, over the footprint"
                              : "wall points registered to the footprint");
    if (!pcl_ext::visualization::renderToPng ({view}, path, options))
      return 1;
  }
#else
  if (!png.empty() || !png_before.empty())
    std::cerr << "Warning: built without visualization, no PNG written.\n";
#endif
  return 0;
}
