/*
 * pcl_ext_generate_scene: simulate a terrestrial laser scan of a synthetic scene and
 * save it with its ground truth (segment, object, class, label).
 */
#include <pcl_ext/io/footprints.h>
#include <pcl_ext/io/read_error.h>
#include <pcl_ext/simulation/scene_io.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace pcl_ext;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {
// All numbers in \a text (separated by spaces, commas, semicolons or parentheses).
bool
parseNumbers (const std::string& text, std::vector<double>& numbers)
{
  numbers.clear();
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == ',' || c == ';' || c == '(' || c == ')')
      c = ' ';
  std::istringstream in (cleaned);
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod (token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite (v))
      return false;
    numbers.push_back (v);
  }
  return true;
}

bool
parseVectors (const std::string& option,
              const std::string& text,
              std::vector<Vector3d>& out)
{
  std::vector<double> v;
  if (!parseNumbers (text, v) || v.empty() || v.size() % 3 != 0) {
    std::cerr << "Error: -" << option
              << " expects x,y,z triples of finite numbers, got '" << text << "'.\n";
    return false;
  }
  out.clear();
  for (std::size_t i = 0; i < v.size(); i += 3)
    out.emplace_back (v[i], v[i + 1], v[i + 2]);
  return true;
}

// A footprint from WKT text, or from a file in any format io::loadFootprints reads: one
// polygon without holes (the simulator walls its outer ring).
bool
parseFootprint (const std::string& value, std::vector<Vector2d>& footprint)
{
  std::vector<io::Footprint> read;
  try {
    std::string upper = value;
    std::transform (upper.begin(), upper.end(), upper.begin(), [] (unsigned char c) {
      return static_cast<char> (std::toupper (c));
    });
    if (upper.find ("POLYGON") != std::string::npos) {
      read.emplace_back();
      io::parseWkt (value, read.back(), "-footprint"); // errors name the option
    }
    else
      io::loadFootprints (value, read);
  }
  catch (const io::ReadError& e) {
    std::cerr << "Error: " << e.what() << "\n";
    return false;
  }
  if (read.size() != 1 || read[0].polygons.size() != 1 ||
      !read[0].polygons[0].holes.empty()) {
    std::cerr << "Error: -footprint: expected one polygon without holes in '" << value
              << "'.\n";
    return false;
  }
  footprint.assign (read[0].polygons[0].outer.begin(), read[0].polygons[0].outer.end());
  return true;
}
} // namespace

int
main (int argc, char** argv)
{
  std::string scene_name, output;
  unsigned int seed = 1, threads = 0;
  int points = 0, scanners = 0, superfluous = 0, missing = 0;
  double noise = 0.005, noise_per_metre = 0.0, step = 0.0, max_range = 0.0,
         edge_distance = 0.0, height = 10.0;
  std::string positions, offset, footprint, pose;
  bool identity_pose = false, ascii = false, curves_only = false,
       surface_segments = false;

  std::string names;
  for (const auto& n : simulation::sceneNames())
    names += (names.empty() ? "" : ", ") + n;
  apps::CommandLine cl (
      "pcl_ext_generate_scene",
      "Simulates terrestrial laser scans of a synthetic scene and saves the points "
      "with their "
      "ground truth: fields x y z [rgb intensity] segment object class [label]. For "
      "'building', "
      "also writes <stem>.footprint.wkt and <stem>.transform.txt (scan-to-map 4x4).");
  cl.addPositional ("scene", scene_name, "one of: " + names);
  cl.addPositional ("output.pcd", output, "where to write the cloud (.pcd or .ply)");
  cl.addOption (
      "seed",
      seed,
      "random seed (noise, vegetation; the layout of tree, street, cubes and spheres)");
  cl.addOption (
      "points",
      points,
      "target number of points (chooses the angular step); 0 = scene default");
  cl.addOption (
      "step", step, "angular step in degrees (overrides -points); 0 = scene default");
  cl.addOption (
      "noise", noise, "range noise sigma in metres (Khoshelham & Gorte used 0.2)");
  cl.addOption (
      "noise_per_metre", noise_per_metre, "extra range noise sigma per metre of range");
  cl.addOption ("scanners", scanners, "number of scan positions; 0 = scene default");
  cl.addOption ("positions",
                positions,
                "explicit scan positions 'x,y,z;x,y,z;...' (scene frame)");
  cl.addOption ("max_range", max_range, "maximum range in metres; 0 = scene default");
  cl.addOption ("edge_distance",
                edge_distance,
                "distance to a crease/border for class edge/boundary; 0 = local "
                "spacing range*step");
  cl.addSwitch ("curve_boundaries_only",
                curves_only,
                "class boundary only along the scene's borders, not along shadows, "
                "the blind cone and creases seen from one side");
  cl.addSwitch (
      "surface_segments",
      surface_segments,
      "one segment id per surface as built, not per connected visible piece of it");
  cl.addOption (
      "offset",
      offset,
      "'x,y,z' added to all coordinates (georeferenced-like); building: to the map");
  cl.addOption (
      "threads", threads, "threads; 0 = all cores (output is identical for any count)");
  cl.addOption ("footprint",
                footprint,
                "building: footprint, WKT POLYGON((x y, ..., x y)) or a footprint file "
                "(.wkt, .geojson, .txt)");
  cl.addOption ("height", height, "building: wall height in metres");
  cl.addOption ("superfluous",
                superfluous,
                "building: number of superfluous planes (neighbours, interior walls)");
  cl.addOption (
      "missing", missing, "building: number of walls hidden behind vegetation");
  cl.addOption ("pose",
                pose,
                "building: scan pose 'yaw,pitch,roll,tx,ty,tz' (degrees, metres); "
                "default random from the seed");
  cl.addSwitch ("identity_pose", identity_pose, "building: scan frame = map frame");
  cl.addSwitch ("ascii", ascii, "write an ASCII PCD");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;

  const auto known = simulation::sceneNames();
  if (std::find (known.begin(), known.end(), scene_name) == known.end()) {
    std::cerr << "Error: unknown scene '" << scene_name << "' (known: " << names
              << ").\n";
    return 1;
  }
  simulation::SceneParameters parameters;
  parameters.seed = seed;
  parameters.noise = noise;
  parameters.noise_per_metre = noise_per_metre;
  parameters.angular_step_deg = step;
  parameters.num_scanners = scanners;
  parameters.max_range = max_range;
  parameters.edge_distance = edge_distance;
  parameters.coverage_boundaries = !curves_only;
  parameters.connected_segments = !surface_segments;
  parameters.threads = threads;
  parameters.building_height = height;
  parameters.superfluous_planes = superfluous;
  parameters.missing_walls = missing;
  parameters.random_pose = !identity_pose;
  if (cl.given ("points") && points <= 0) {
    std::cerr << "Error: -points must be positive, got " << points << ".\n";
    return 1;
  }
  parameters.points = static_cast<std::size_t> (points);
  if (cl.given ("step") && !(step > 0.0)) {
    std::cerr << "Error: -step must be positive, got " << step << ".\n";
    return 1;
  }
  if (cl.given ("scanners") && scanners <= 0) {
    std::cerr << "Error: -scanners must be positive, got " << scanners << ".\n";
    return 1;
  }
  if (!positions.empty() &&
      !parseVectors ("positions", positions, parameters.scan_positions))
    return 1;
  if (!offset.empty()) {
    std::vector<Vector3d> v;
    if (!parseVectors ("offset", offset, v) || v.size() != 1) {
      if (v.size() > 1)
        std::cerr << "Error: -offset expects one x,y,z triple.\n";
      return 1;
    }
    parameters.offset = v.front();
  }
  if (!footprint.empty() && !parseFootprint (footprint, parameters.footprint))
    return 1;
  if (!pose.empty()) {
    std::vector<double> v;
    if (!parseNumbers (pose, v) || v.size() != 6) {
      std::cerr << "Error: -pose expects 'yaw,pitch,roll,tx,ty,tz', got '" << pose
                << "'.\n";
      return 1;
    }
    const double deg = 3.141592653589793 / 180.0;
    parameters.has_pose = true;
    parameters.pose.linear() = (Eigen::AngleAxisd (v[0] * deg, Vector3d::UnitZ()) *
                                Eigen::AngleAxisd (v[1] * deg, Vector3d::UnitY()) *
                                Eigen::AngleAxisd (v[2] * deg, Vector3d::UnitX()))
                                   .toRotationMatrix();
    parameters.pose.translation() = Vector3d (v[3], v[4], v[5]);
  }
  if (!simulation::checkSceneParameters (parameters))
    return 1;
  if (!io::checkWritable (output))
    return 1;

  simulation::SyntheticScene scene;
  {
    apps::StageTimer timer ("Generating scene '" + scene_name + "'");
    if (!simulation::generateScene (scene_name, parameters, scene)) {
      std::cout << std::endl;
      std::cerr << "Error: could not generate scene '" << scene_name << "'.\n";
      return 1;
    }
    timer.done (scene.cloud.size());
  }
  std::cout << "  " << scene.scan_positions.size() << " scan positions, angular step "
            << std::setprecision (4) << scene.angular_step_deg << " deg, range noise "
            << scene.noise << " m\n";
  if (scene.has_label) {
    std::cout << "  labels:";
    for (std::size_t l = 1; l < scene.label_names.size(); ++l)
      std::cout << (l > 1 ? "," : "") << ' ' << l << ' ' << scene.label_names[l];
    std::cout << '\n';
  }
  {
    apps::StageTimer timer ("Saving " + output);
    if (!simulation::saveScene (output, scene, ascii)) {
      std::cout << std::endl;
      return 1;
    }
    timer.done (scene.cloud.size());
  }
  if (!scene.footprint.empty())
    std::cout << "  footprint: " << simulation::pathStem (output)
              << ".footprint.wkt, transform: " << simulation::pathStem (output)
              << ".transform.txt\n";
  return 0;
}
