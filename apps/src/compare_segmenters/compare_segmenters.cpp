/*
 * pcl_ext_compare_segmenters: pcl_ext's segmenters and the stock PCL ones on the same cloud,
 * scored against its ground truth: one table, optionally a CSV file, the labels and a montage.
 */
#include "comparison_report.h"
#include "isolated_run.h"
#include "segmenter_methods.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/tools/cloud_io.h>
#include <pcl_ext/tools/command_line.h>
#include <pcl_ext/tools/file_output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/montage.h>
#endif

#include <pcl/common/point_tests.h>
#include <pcl/conversions.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

namespace
{
using namespace pcl_ext::compare;

/** The methods named in \a list (comma-separated, "all" for every one), in table order. */
bool
selectMethods (const std::string& list, const std::vector<SegmenterMethod>& all,
               std::vector<SegmenterMethod>& selected)
{
  std::set<std::string> wanted;
  std::stringstream in (list);
  std::string name;
  while (std::getline (in, name, ','))
  {
    if (name.empty ())
      continue;
    if (name == "all")
    {
      for (const auto& m : all)
        wanted.insert (m.name);
      continue;
    }
    bool known = false;
    for (const auto& m : all)
      known = known || m.name == name;
    if (!known)
    {
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
  if (selected.empty ())
  {
    std::cerr << "Error: -methods names no method.\n";
    return false;
  }
  return true;
}

/** Everything the methods share, and the ground truth of the same points. */
struct Comparison
{
  SegmenterInput input;
  std::vector<std::size_t> source_index;  ///< input-file index of each finite point
  std::size_t file_points = 0;
  bool organised = false;
  std::vector<std::uint32_t> truth;       ///< per finite point; empty without ground truth
};

bool
loadInput (const std::string& path, const std::string& truth_field, pcl::PCLPointCloud2& blob,
           Comparison& c)
{
  pcl_ext::tools::StageTimer timer ("Loading " + path);
  if (!pcl_ext::tools::loadCloud (path, blob))
    return false;
  std::vector<std::uint32_t> truth;
  if (!truth_field.empty ())
  {
    std::string error;
    if (!pcl_ext::io::getLabelField (blob, truth_field, truth, &error))
    {
      std::cout << std::endl;
      std::cerr << "Error: " << path << ": " << error << ".\n";
      return false;
    }
  }
  pcl::PointCloud<pcl::PointXYZ> all;
  pcl::fromPCLPointCloud2 (blob, all);
  const bool colour = pcl_ext::tools::findField (blob, "rgb") >= 0 ||
                      pcl_ext::tools::findField (blob, "rgba") >= 0;
  pcl::PointCloud<pcl::PointXYZRGBA> all_coloured;
  if (colour)
    pcl::fromPCLPointCloud2 (blob, all_coloured);
  c.file_points = all.size ();
  c.organised = all.isOrganized ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::PointXYZRGBA>::Ptr coloured (new pcl::PointCloud<pcl::PointXYZRGBA>);
  for (std::size_t i = 0; i < all.size (); ++i)
    if (pcl::isFinite (all[i]))
    {
      cloud->push_back (all[i]);
      if (colour)
        coloured->push_back (all_coloured[i]);
      if (!truth.empty ())
        c.truth.push_back (truth[i]);
      c.source_index.push_back (i);
    }
  if (cloud->empty ())
  {
    std::cout << std::endl;
    std::cerr << "Error: " << path << " has no point with finite coordinates.\n";
    return false;
  }
  c.input.cloud = cloud;
  if (colour)
    c.input.coloured = coloured;
  timer.done (cloud->size ());
  if (cloud->size () < all.size ())
    std::cout << "  " << all.size () - cloud->size ()
              << " points with non-finite coordinates left out (no method can segment them)\n";
  return true;
}

/** Normals for the methods that need them, in a child process (OpenMP stays out of this one). */
bool
computeNormals (Comparison& c, int k, unsigned int threads, double timeout, MethodResult& cost)
{
  pcl_ext::tools::StageTimer timer ("Estimating normals (pcl::NormalEstimationOMP, k = " +
                                    std::to_string (k) + ")");
  pcl::PointCloud<pcl::Normal> normals;
  const auto run = runIsolated (
      [&] {
        pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne (threads);
        ne.setInputCloud (c.input.cloud);
        ne.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
            new pcl::search::KdTree<pcl::PointXYZ>));
        ne.setKSearch (k);
        ne.compute (normals);
        return normals.size () == c.input.cloud->size ();
      },
      [&] {
        std::vector<char> bytes;
        appendBytes (std::vector<pcl::Normal> (normals.begin (), normals.end ()), bytes);
        return bytes;
      },
      timeout);
  std::vector<pcl::Normal> values;
  std::size_t offset = 0;
  if (!run.ok || !readBytes (run.result, offset, c.input.cloud->size (), values))
  {
    std::cout << std::endl;
    std::cerr << "Error: normal estimation " << (run.ok ? "sent a short result" : run.error)
              << ".\n";
    return false;
  }
  pcl::PointCloud<pcl::Normal>::Ptr cloud (new pcl::PointCloud<pcl::Normal>);
  cloud->assign (values.begin (), values.end (), static_cast<pcl::index_t> (values.size ()));
  c.input.normals = cloud;
  cost.seconds = run.seconds;
  cost.peak_bytes = run.peak_bytes;
  timer.done (values.size ());
  std::cout << "  " << run.seconds << " s, peak " << run.peak_bytes / (1024 * 1024)
            << " MB (counted in the methods that use them)\n";
  return true;
}

MethodResult
runMethod (const SegmenterMethod& method, const Comparison& c, const SegmenterSettings& settings,
           const MethodResult& normals_cost, double timeout)
{
  MethodResult r;
  r.name = method.name;
  r.library = method.library;
  r.needs_normals = method.needs_normals;
  const std::size_t n = c.input.cloud->size ();
  pcl_ext::tools::StageTimer timer ("Running " + method.name);
  std::vector<pcl::PointIndices> clusters;
  const auto run = runIsolated (
      [&] { return method.run (c.input, settings, clusters); },
      [&] {
        // Overlapping clusters (super-voxels) keep their points in the first cluster that
        // holds them; the segments counted are those left with a point.
        std::vector<std::uint32_t> labels;
        pcl_ext::labelsFromIndices (clusters, n, labels);
        std::vector<char> used (clusters.size () + 1, 0);
        for (const auto l : labels)
          used[l] = 1;
        const std::uint64_t segments =
            static_cast<std::uint64_t> (std::count (used.begin () + 1, used.end (), 1));
        std::vector<char> bytes;
        appendBytes (std::vector<std::uint64_t> {segments}, bytes);
        appendBytes (labels, bytes);
        return bytes;
      },
      timeout);
  std::vector<std::uint64_t> count;
  std::size_t offset = 0;
  if (!run.ok || !readBytes (run.result, offset, 1, count) ||
      !readBytes (run.result, offset, n, r.labels))
  {
    r.error = run.ok ? "short result" : run.error;
    std::cout << "[failed: " << r.error << "]" << std::endl;
    return r;
  }
  r.ok = true;
  r.segments = static_cast<std::size_t> (count[0]);
  r.seconds = run.seconds;
  r.peak_bytes = run.peak_bytes;
  if (method.needs_normals)
  {
    // As if the method had estimated them itself: their time, and the larger of their
    // estimation's peak and their storage plus the method's own peak.
    r.seconds += normals_cost.seconds;
    r.peak_bytes = std::max (normals_cost.peak_bytes,
                             run.peak_bytes + n * sizeof (pcl::Normal));
  }
  for (const auto l : r.labels)
    r.unsegmented += l == 0;
  timer.done (n);
  if (!c.truth.empty ())
    r.evaluated = pcl_ext::evaluateSegmentation (r.labels, c.truth, r.metrics);
  return r;
}

/** The input file with one uint32 field per method (its labels; 0 for non-finite points). */
bool
writeLabels (const std::string& path, pcl::PCLPointCloud2& blob, const Comparison& c,
             const std::vector<MethodResult>& results)
{
  pcl_ext::tools::StageTimer timer ("Saving " + path);
  for (const auto& r : results)
  {
    if (!r.ok)
      continue;
    std::vector<std::uint32_t> labels (c.file_points, 0);
    for (std::size_t i = 0; i < r.labels.size (); ++i)
      labels[c.source_index[i]] = r.labels[i];
    if (!pcl_ext::io::setLabelField (blob, r.name, labels))
      return false;
  }
  if (!pcl_ext::tools::saveCloud (path, blob))
    return false;
  timer.done (c.file_points);
  return true;
}

#ifdef PCL_EXT_HAVE_VISUALIZATION
/** Every method's result from the same camera, the ground truth first. Organised clouds (depth
  * cameras) are seen from the sensor, others from above and the side; points above \a max_z
  * (a ceiling) are left out of the picture. */
bool
renderMontage (const std::string& path, const Comparison& c,
               const std::vector<MethodResult>& results, int tile_width, int tile_height,
               double max_z)
{
  namespace vis = pcl_ext::visualization;
  pcl_ext::tools::StageTimer timer ("Rendering " + path);
  std::vector<std::size_t> shown;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (std::size_t i = 0; i < c.input.cloud->size (); ++i)
    if ((*c.input.cloud)[i].z <= max_z)
    {
      shown.push_back (i);
      cloud.push_back ((*c.input.cloud)[i]);
    }
  const auto pick = [&shown] (const std::vector<std::uint32_t>& labels) {
    std::vector<std::uint32_t> picked (shown.size ());
    for (std::size_t j = 0; j < shown.size (); ++j)
      picked[j] = labels[shown[j]];
    return picked;
  };
  std::vector<vis::View> views;
  const bool with_truth = !c.truth.empty ();
  if (with_truth)
  {
    std::set<std::uint32_t> distinct (c.truth.begin (), c.truth.end ());
    distinct.erase (0);
    views.push_back (vis::makeLabelView (
        "ground truth: " + std::to_string (distinct.size ()) + " segments", cloud, pick (c.truth)));
  }
  for (const auto& r : results)
    if (r.ok)
      views.push_back (vis::makeLabelView (tileTitle (r, with_truth), cloud, pick (r.labels)));
  vis::RenderOptions options = vis::makeMontageOptions (views.size (), tile_width, tile_height);
  if (c.organised)
  {
    options.view_direction = Eigen::Vector3d::UnitZ ();
    options.up = -Eigen::Vector3d::UnitY ();
    options.zoom_out = 1.9;
  }
  if (!vis::renderToPng (views, path, options))
    return false;
  timer.done (cloud.size ());
  return true;
}
#endif
}  // namespace

int
main (int argc, char** argv)
{
  const std::vector<SegmenterMethod> all = allMethods ();
  std::string input_path, truth_field, methods_list = "all", csv_path, png_path, labels_path;
  SegmenterSettings s;
  double spacing = 0.0, timeout = 0.0;
  int tile_width = 520, tile_height = 400;
  double png_max_z = std::numeric_limits<double>::infinity ();
  std::string description =
      "Runs pcl_ext's segmenters and stock PCL segmenters on the same cloud (finite points) and "
      "prints one table: segments, mean and point-weighted best IoU, Hoover correct / over / "
      "under / missed (tolerance 0.8), unsegmented fraction, time, peak memory. Without "
      "-truth_field only counts and times. Every length parameter is a multiple of the mean "
      "point spacing s (estimated as sqrt(pi r6^2 / 6), r6 the 6th-neighbour distance, or "
      "-spacing). Each method runs in its own child process: time is its wall time (plus the "
      "normals' for those marked 'normals'), peak memory its resident set above the loaded "
      "input at its peak.\n\nMethods:";
  for (const auto& m : all)
    description += "\n  " + m.name + std::string (m.name.size () < 15 ? 15 - m.name.size () : 1, ' ') +
                   m.description;
  pcl_ext::tools::CommandLine cl ("pcl_ext_compare_segmenters", description);
  cl.addPositional ("input.pcd", input_path, "input cloud (PCD or PLY)");
  cl.addOption ("truth_field", truth_field,
                "field holding the ground-truth segments (e.g. segment, object, label; 0 = "
                "ignored); none: counts and times only");
  cl.addOption ("methods", methods_list, "comma-separated methods, or 'all'");
  cl.addOption ("k", s.k, "neighbours of the normals and of region_growing");
  cl.addOption ("threads", s.threads, "threads of the parallel methods and the normals (0: all cores)");
  cl.addOption ("spacing", spacing, "mean point spacing s in m (0: estimated)");
  cl.addOption ("min_size", s.min_size, "smallest segment kept (methods with a minimum size)");
  cl.addOption ("tolerance", s.tolerance,
                "connection distance / s: euclidean, cec, profile threshold, plane split");
  cl.addOption ("angle", s.angle, "normal angle in degrees: region_growing smoothness, cec");
  cl.addOption ("curvature", s.curvature, "region_growing curvature threshold");
  cl.addOption ("plane_distance", s.plane_distance, "sac_planes inlier distance / s");
  cl.addOption ("max_planes", s.max_planes, "sac_planes: most planes");
  cl.addOption ("voxel", s.voxel, "lccp supervoxel voxel resolution / s");
  cl.addOption ("seed", s.seed, "lccp supervoxel seed resolution / s");
  cl.addOption ("concavity", s.concavity, "lccp concavity tolerance in degrees");
  cl.addOption ("timeout", timeout, "seconds after which a method is stopped (0: none)");
  cl.addOption ("csv", csv_path, "also write the table to this CSV file");
  cl.addOption ("labels", labels_path,
                "also write the input with one label field per method (0: no segment)");
  cl.addOption ("png", png_path, "also render a montage of every result; needs an X display");
  cl.addOption ("tile_width", tile_width, "montage tile width in pixels");
  cl.addOption ("tile_height", tile_height, "montage tile height in pixels");
  cl.addOption ("png_max_z", png_max_z,
                "montage only: leave out points above this z (e.g. a ceiling hiding a room)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;

  std::vector<SegmenterMethod> methods;
  if (!selectMethods (methods_list, all, methods))
    return 1;
  const auto positive = [] (double v) { return std::isfinite (v) && v > 0.0; };
  std::string bad;
  if (s.k < 3)
    bad = "-k must be at least 3";
  else if (s.min_size < 1)
    bad = "-min_size must be at least 1";
  else if (!(std::isfinite (spacing) && spacing >= 0.0))
    bad = "-spacing must be 0 or positive";
  else if (!positive (s.tolerance) || !positive (s.plane_distance) || !positive (s.voxel) ||
           !positive (s.seed))
    bad = "-tolerance, -plane_distance, -voxel and -seed must be positive";
  else if (!positive (s.angle) || !(s.angle < 90.0) || !positive (s.concavity) ||
           !(s.concavity < 180.0))
    bad = "-angle must be in (0, 90) and -concavity in (0, 180) degrees";
  else if (!positive (s.curvature))
    bad = "-curvature must be positive";
  else if (s.max_planes < 1)
    bad = "-max_planes must be at least 1";
  else if (!(std::isfinite (timeout) && timeout >= 0.0))
    bad = "-timeout must be 0 or positive";
  else if (std::isnan (png_max_z))
    bad = "-png_max_z must be a number";
  else if (tile_width < 64 || tile_height < 64 || tile_width > 4096 || tile_height > 4096)
    bad = "-tile_width and -tile_height must be in [64, 4096]";
  if (!bad.empty ())
  {
    std::cerr << "Error: " << bad << ".\n";
    return 1;
  }
#ifndef PCL_EXT_HAVE_VISUALIZATION
  if (!png_path.empty ())
  {
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
  }
#endif
  for (const auto* path : {&csv_path, &labels_path, &png_path})
    if (!path->empty () && !pcl_ext::tools::checkWritable (*path))
      return 1;

  pcl::PCLPointCloud2 blob;
  Comparison c;
  if (!loadInput (input_path, truth_field, blob, c))
    return 1;
  if (spacing > 0.0)
    s.spacing = spacing;
  else
  {
    std::vector<Eigen::Vector3f> xyz;
    xyz.reserve (c.input.cloud->size ());
    for (const auto& p : *c.input.cloud)
      xyz.push_back (p.getVector3fMap ());
    s.spacing = pcl_ext::profiles::estimatePointSpacing (xyz);
    if (!(s.spacing > 0.0))
    {
      std::cerr << "Error: cannot estimate the point spacing (too few distinct points); give "
                   "-spacing.\n";
      return 1;
    }
  }
  std::cout << "Point spacing s = " << s.spacing << " m: tolerance " << s.tolerance * s.spacing
            << " m, plane distance " << s.plane_distance * s.spacing << " m, voxel "
            << s.voxel * s.spacing << " m, seed " << s.seed * s.spacing << " m\n";

  MethodResult normals_cost;
  bool need_normals = false;
  for (const auto& m : methods)
    need_normals = need_normals || m.needs_normals;
  if (need_normals && !computeNormals (c, s.k, s.threads, timeout, normals_cost))
    return 1;

  std::vector<MethodResult> results;
  for (const auto& m : methods)
    results.push_back (runMethod (m, c, s, normals_cost, timeout));
  const bool with_truth = !c.truth.empty ();
  if (with_truth)
    std::cout << "\nScores against '" << truth_field << "' over " << c.truth.size ()
              << " points (label 0 ignored), Hoover tolerance 0.8:";
  printTable (results, with_truth);

  bool ok = true;
  for (const auto& r : results)
    ok = ok && r.ok;
  if (!csv_path.empty ())
  {
    if (!pcl_ext::tools::writeTextFile (csv_path, makeCsv (results, with_truth)))
      return 1;
    std::cout << "Wrote " << csv_path << "\n";
  }
  if (!labels_path.empty () && !writeLabels (labels_path, blob, c, results))
    return 1;
#ifdef PCL_EXT_HAVE_VISUALIZATION
  if (!png_path.empty () &&
      !renderMontage (png_path, c, results, tile_width, tile_height, png_max_z))
    return 1;
#endif
  if (!ok)
  {
    std::cerr << "Error: some methods failed (see the table).\n";
    return 1;
  }
  return 0;
}
