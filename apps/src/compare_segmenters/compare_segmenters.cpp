/*
 * pcl_ext_compare_segmenters: pcl_ext's segmenters and the stock PCL ones on the same
 * cloud, scored against its ground truth: one table, optionally a CSV file, the labels
 * and a montage.
 */
#include "comparison.h"
#include "comparison_report.h"
#include "segmenter_methods.h"

#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/picture_options.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/io/file_output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/montage.h>
#endif

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

namespace {
using namespace pcl_ext::compare;

/** The methods named in \a list (comma-separated, "all" for every one), in table order.
 */
bool
selectMethods (const std::string& list,
               const std::vector<SegmenterMethod>& all,
               std::vector<SegmenterMethod>& selected)
{
  std::set<std::string> wanted;
  std::stringstream in (list);
  std::string name;
  while (std::getline (in, name, ',')) {
    if (name.empty())
      continue;
    if (name == "all") {
      for (const auto& m : all)
        wanted.insert (m.name);
      continue;
    }
    bool known = false;
    for (const auto& m : all)
      known = known || m.name == name;
    if (!known) {
      std::cerr << "Error: unknown method '" << name << "' in -methods; known:";
      for (const auto& m : all)
        std::cerr << " " << m.name;
      std::cerr << ".\n";
      return false;
    }
    wanted.insert (name);
  }
  for (const auto& m : all)
    if (wanted.count (m.name))
      selected.push_back (m);
  if (selected.empty()) {
    std::cerr << "Error: -methods names no method.\n";
    return false;
  }
  return true;
}

#ifdef PCL_EXT_HAVE_VISUALIZATION
/** Every method's result from the same camera, the ground truth first. Organised clouds
 * (depth cameras) are seen from the sensor, others from above and the side; points
 * above \a max_z (a ceiling) are left out of the picture. */
bool
renderMontage (const std::string& path,
               const Comparison& c,
               const std::vector<MethodResult>& results,
               int tile_width,
               int tile_height,
               const pcl_ext::apps::PictureOptions& picture)
{
  namespace vis = pcl_ext::visualization;
  pcl_ext::apps::StageTimer timer ("Rendering " + path);
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *c.input.cloud;
  // With a truth, every result's segments take the colour of the truth segment they
  // overlap most, so that the tiles compare at a glance.
  const auto pick = [&c] (const std::vector<std::uint32_t>& labels) {
    return c.truth.empty()
               ? labels
               : pcl_ext::visualization::matchLabelsToReference (labels, c.truth);
  };
  std::vector<vis::View> views;
  const bool with_truth = !c.truth.empty();
  if (with_truth) {
    std::set<std::uint32_t> distinct (c.truth.begin(), c.truth.end());
    distinct.erase (0);
    views.push_back (vis::makeLabelView (
        "ground truth: " + std::to_string (distinct.size()) + " segments",
        cloud,
        c.truth));
  }
  for (const auto& r : results)
    if (r.ok)
      views.push_back (
          vis::makeLabelView (tileTitle (r, with_truth), cloud, pick (r.labels)));
  vis::RenderOptions options = picture.renderOptions (cloud);
  const vis::RenderOptions montage =
      vis::makeMontageOptions (views.size(), tile_width, tile_height);
  options.width = montage.width;
  options.height = montage.height;
  options.columns = montage.columns;
  if (c.organised) { // a depth camera's image (before its NaN were dropped)
    options.up = -Eigen::Vector3d::UnitY();
    options.sensor = Eigen::Vector3d::Zero();
  }
  if (!vis::renderToPng (views, path, options))
    return false;
  timer.done (cloud.size());
  return true;
}
#endif
} // namespace

int
main (int argc, char** argv)
{
  const std::vector<SegmenterMethod> all = allMethods();
  std::string input_path, truth_field, methods_list = "all", csv_path, png_path,
                                       labels_path;
  SegmenterSettings s;
  double spacing = 0.0, timeout = 0.0;
  int tile_width = 520, tile_height = 400;
  pcl_ext::apps::PictureOptions picture;
  std::string description = "Runs pcl_ext's segmenters and stock PCL segmenters on the "
                            "same cloud (finite points) and "
                            "prints one table: segments, mean and point-weighted best "
                            "IoU, Hoover correct / over / "
                            "under / missed (tolerance 0.8), unsegmented fraction, "
                            "time, peak memory. Without "
                            "-truth_field only counts and times. Every length "
                            "parameter is a multiple of the mean "
                            "point spacing s (estimated as sqrt(pi r6^2 / 6), r6 the "
                            "6th-neighbour distance, or "
                            "-spacing). Each method runs in its own child process: "
                            "time is its wall time (plus the "
                            "normals' for those marked 'normals'), peak memory its "
                            "resident set above the loaded "
                            "input at its peak.\n\nMethods:";
  for (const auto& m : all)
    description += "\n  " + m.name +
                   std::string (m.name.size() < 15 ? 15 - m.name.size() : 1, ' ') +
                   m.description;
  pcl_ext::apps::CommandLine cl ("pcl_ext_compare_segmenters", description);
  cl.addPositional ("input",
                    input_path,
                    std::string ("input cloud: ") + pcl_ext::apps::kInputFormats);
  cl.addOption (
      "truth_field",
      truth_field,
      "field holding the ground-truth segments (e.g. segment, object, label; 0 = "
      "ignored); none: counts and times only");
  cl.addOption ("methods", methods_list, "comma-separated methods, or 'all'");
  cl.addOption ("k", s.k, "neighbours of the normals and of region_growing");
  cl.addOption ("normal_k",
                s.normal_k,
                "neighbours of the normals alone (0: -k); PCL's region growing "
                "tutorial takes 50 for the normals and 30 for the growing");
  cl.addOption ("threads",
                s.threads,
                "threads of the parallel methods and the normals (0: all cores)");
  cl.addOption ("spacing", spacing, "mean point spacing s in m (0: estimated)");
  cl.addOption (
      "min_size", s.min_size, "smallest segment kept (methods with a minimum size)");
  cl.addOption (
      "tolerance",
      s.tolerance,
      "connection distance / s: euclidean, cec, profile threshold, plane split");
  cl.addOption (
      "angle", s.angle, "normal angle in degrees: region_growing smoothness, cec");
  cl.addOption ("curvature", s.curvature, "region_growing curvature threshold");
  cl.addOption ("plane_distance",
                s.plane_distance,
                "sac_planes and cgal_planes: distance to the plane / s");
  cl.addOption ("max_planes", s.max_planes, "sac_planes: most planes");
  cl.addOption ("voxel", s.voxel, "lccp supervoxel voxel resolution / s");
  cl.addOption ("seed", s.seed, "lccp supervoxel seed resolution / s");
  cl.addOption ("concavity", s.concavity, "lccp concavity tolerance in degrees");
  cl.addSwitch (
      "aicc",
      s.profile_aicc,
      "profile curve fitting: polynomials chosen by AICc, not the paper's AIC");
  cl.addOption (
      "turn_significance",
      s.profile_turn_significance,
      "profile curve fitting: a sharp turn must also exceed this many standard errors "
      "(0: the paper's angle alone)");
  cl.addSwitch (
      "side_frames",
      s.profile_side_frames,
      "profile curve fitting: each side of a point fitted along its own axis");
  cl.addSwitch ("local_threshold",
                s.profile_local_threshold,
                "profile segmenters: thresholds that follow the local point density");
  cl.addOption (
      "timeout", timeout, "seconds after which a method is stopped (0: none)");
  cl.addOption ("csv", csv_path, "also write the table to this CSV file");
  cl.addOption ("labels",
                labels_path,
                std::string ("also write the input with one label field per method (0: "
                             "no segment), in its frame: ") +
                    pcl_ext::apps::kOutputFormats);
  cl.addOption (
      "png", png_path, "also render a montage of every result; needs an X display");
  cl.addOption ("tile_width", tile_width, "montage tile width in pixels");
  cl.addOption ("tile_height", tile_height, "montage tile height in pixels");
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;

  std::vector<SegmenterMethod> methods;
  if (!selectMethods (methods_list, all, methods))
    return 1;
  const auto positive = [] (double v) { return std::isfinite (v) && v > 0.0; };
  std::string bad;
  if (s.k < 3)
    bad = "-k must be at least 3";
  else if (s.normal_k != 0 && s.normal_k < 3)
    bad = "-normal_k must be 0 (-k) or at least 3";
  else if (s.min_size < 1)
    bad = "-min_size must be at least 1";
  else if (!(std::isfinite (spacing) && spacing >= 0.0))
    bad = "-spacing must be 0 or positive";
  else if (!positive (s.tolerance) || !positive (s.plane_distance) ||
           !positive (s.voxel) || !positive (s.seed))
    bad = "-tolerance, -plane_distance, -voxel and -seed must be positive";
  else if (!positive (s.angle) || !(s.angle < 90.0) || !positive (s.concavity) ||
           !(s.concavity < 180.0))
    bad = "-angle must be in (0, 90) and -concavity in (0, 180) degrees";
  else if (!positive (s.curvature))
    bad = "-curvature must be positive";
  else if (!(std::isfinite (s.profile_turn_significance) &&
             s.profile_turn_significance >= 0.0))
    bad = "-turn_significance must be 0 or positive";
  else if (s.max_planes < 1)
    bad = "-max_planes must be at least 1";
  else if (!(std::isfinite (timeout) && timeout >= 0.0))
    bad = "-timeout must be 0 or positive";
  else if (tile_width < 64 || tile_height < 64 || tile_width > 4096 ||
           tile_height > 4096)
    bad = "-tile_width and -tile_height must be in [64, 4096]";
  if (!bad.empty()) {
    std::cerr << "Error: " << bad << ".\n";
    return 1;
  }
#ifndef PCL_EXT_HAVE_VISUALIZATION
  if (!png_path.empty()) {
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
  }
#endif
  std::string reason;
  if (!labels_path.empty() && !pcl_ext::io::canWritePointFile (labels_path, &reason)) {
    std::cerr << "Error: -labels " << reason << ".\n";
    return 1;
  }
  for (const auto* path : {&csv_path, &labels_path, &png_path})
    if (!path->empty() && !pcl_ext::io::checkWritable (*path))
      return 1;

  pcl_ext::io::PointFile input;
  Comparison c;
  if (!loadInput (input_path, truth_field, input, c))
    return 1;
  if (spacing > 0.0)
    s.spacing = spacing;
  else {
    std::vector<Eigen::Vector3f> xyz;
    xyz.reserve (c.input.cloud->size());
    for (const auto& p : *c.input.cloud)
      xyz.push_back (p.getVector3fMap());
    s.spacing = pcl_ext::profiles::estimatePointSpacing (xyz);
    if (!(s.spacing > 0.0)) {
      std::cerr
          << "Error: cannot estimate the point spacing (too few distinct points); give "
             "-spacing.\n";
      return 1;
    }
  }
  {
    const auto length = [] (double metres) {
      char text[32];
      std::snprintf (text, sizeof (text), "%.3g m", metres);
      return std::string (text);
    };
    std::cout << "Point spacing s = " << length (s.spacing) << ": tolerance "
              << length (s.tolerance * s.spacing) << ", plane distance "
              << length (s.plane_distance * s.spacing) << ", voxel "
              << length (s.voxel * s.spacing) << ", seed "
              << length (s.seed * s.spacing) << "\n";
  }

  MethodResult normals_cost;
  bool need_normals = false;
  for (const auto& m : methods)
    need_normals = need_normals || m.needs_normals;
  if (need_normals &&
      !computeNormals (
          c, s.normal_k > 0 ? s.normal_k : s.k, s.threads, timeout, normals_cost))
    return 1;

  std::vector<MethodResult> results;
  for (const auto& m : methods)
    results.push_back (runMethod (m, c, s, normals_cost, timeout));
  const bool with_truth = !c.truth.empty();
  if (with_truth)
    std::cout << "\nScores against '" << truth_field << "' over " << c.truth.size()
              << " points (label 0 ignored), Hoover tolerance 0.8:";
  printTable (results, with_truth);

  bool ok = true;
  for (const auto& r : results)
    ok = ok && r.ok;
  if (!csv_path.empty()) {
    if (!pcl_ext::io::writeTextFile (csv_path, makeCsv (results, with_truth)))
      return 1;
    std::cout << "Wrote " << csv_path << "\n";
  }
  if (!labels_path.empty() && !writeLabels (labels_path, input, c, results))
    return 1;
#ifdef PCL_EXT_HAVE_VISUALIZATION
  if (!png_path.empty() &&
      !renderMontage (png_path, c, results, tile_width, tile_height, picture))
    return 1;
#endif
  if (!ok) {
    std::cerr << "Error: some methods failed (see the table).\n";
    return 1;
  }
  return 0;
}
