/*
 * pcl_ext_segment_profiles: segments a cloud by intersecting profiles (Sithole &
 * Mapurisa) and writes the input points and fields, in the input's coordinates, with
 * the segment in the field `segment` (-output_field; 1, 2, ... by decreasing size; 0
 * for points in no segment).
 */
#include "profiles/profile_options.h"

#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/apps/picture_options.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <pcl/common/io.h>
#include <pcl/conversions.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <numeric>
#include <sstream>

namespace {
using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

#ifdef PCL_EXT_HAVE_VISUALIZATION
/** Figure 3 and 5 of the paper for the first stack: points coloured by profile, and by
 * chain (connected run of profile edges). */
bool
renderProfiles (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                const Segmentation& seg,
                const std::string& path,
                pcl_ext::visualization::RenderOptions options)
{
  const std::vector<int> profile = seg.getProfileOfPoints (0);
  if (profile.size() != cloud.size() || seg.getStackEdges().empty())
    return false;
  std::vector<std::uint32_t> parent (cloud.size());
  std::iota (parent.begin(), parent.end(), 0u);
  const auto find = [&] (std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& e : seg.getStackEdges()[0]) {
    const std::uint32_t a = find (e.source), b = find (e.target);
    parent[std::max (a, b)] = std::min (a, b);
  }
  std::vector<std::uint32_t> by_profile (cloud.size()), by_chain (cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    by_profile[i] = profile[i] < 0 ? 0 : 1 + static_cast<std::uint32_t> (profile[i]);
    by_chain[i] = profile[i] < 0 ? 0 : 1 + find (static_cast<std::uint32_t> (i));
  }
  const Eigen::Vector3f phi = seg.getStackNormals()[0];
  pcl_ext::visualization::View profiles, chains;
  char title[160];
  std::snprintf (title,
                 sizeof (title),
                 "Stack 1 (normal %.2f %.2f %.2f): profiles, width %.4g",
                 phi.x(),
                 phi.y(),
                 phi.z(),
                 seg.getUsedProfileWidth());
  profiles.title = title;
  profiles.layers.push_back ({pcl_ext::visualization::makeColouredCloud (
      cloud, pcl_ext::visualization::colourByLabel (by_profile))});
  chains.title = "Stack 1: chains after profile segmentation";
  chains.layers.push_back ({pcl_ext::visualization::makeColouredCloud (
      cloud, pcl_ext::visualization::colourByLabel (by_chain))});
  options.width = 1600;
  options.height = 800;
  // Seen edge-on, the profiles (slabs across phi) are clean stripes: with -view auto,
  // look as steeply down as a direction orthogonal to phi allows.
  if (options.view == pcl_ext::visualization::ViewKind::Auto) {
    const Eigen::Vector3d n = phi.cast<double>().normalized();
    Eigen::Vector3d down = -(options.up - options.up.dot (n) * n);
    if (down.norm() < 1e-6) // phi vertical: any horizontal direction is orthogonal
      down = n.cross (Eigen::Vector3d::UnitX()).norm() > 1e-6
                 ? Eigen::Vector3d (n.cross (Eigen::Vector3d::UnitX()))
                 : Eigen::Vector3d (n.cross (Eigen::Vector3d::UnitY()));
    options.view_direction = down.normalized();
  }
  return pcl_ext::visualization::renderToPng ({profiles, chains}, path, options);
}
#endif
} // namespace

int
main (int argc, char** argv)
{
  std::string input_path, output_path, png_path, png_profiles_path;
  unsigned int threads = 0;
  bool verbose = false;
  pcl_ext::apps::ProfileOptions options;
  pcl_ext::apps::CommandLine cl ("pcl_ext_segment_profiles",
                                 "Segments a cloud by intersecting profiles (Sithole & "
                                 "Mapurisa): stacks of thin profiles "
                                 "along several normals, chains in every profile, "
                                 "segments = connected components of all "
                                 "chains. Writes the input points and fields, in the "
                                 "input's coordinates, with the segment in the field "
                                 "'segment' (1.. by decreasing size, 0: none).");
  pcl_ext::apps::ResultField result = pcl_ext::apps::segmentIdField();
  result.addTo (cl, input_path, output_path);
  options.addTo (cl);
  cl.addOption ("threads", threads, "OpenMP threads (0: all cores)");
  cl.addSwitch ("v",
                verbose,
                "print the cloud's spacing, noise and spacing variation and the "
                "configuration chosen from them (-method auto)");
  cl.addOption (
      "png", png_path, "also render the segments to this PNG; needs an X display");
  cl.addOption ("png_profiles",
                png_profiles_path,
                "also render the first stack's profiles and chains to this PNG");
  pcl_ext::apps::PictureOptions picture;
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;
  if (!options.valid())
    return 1;
  const bool automatic = options.automatic();
  if (!result.checkOutput (output_path, {png_path, png_profiles_path}))
    return 1;

  pcl_ext::io::PointFile input;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (!pcl_ext::apps::loadInput (input_path, input, *cloud) ||
      !result.checkInput (input, input_path))
    return 1;

  // -method auto: AutoProfileSegmentation chooses the profile segmenter and the
  // options for noisy or unevenly dense clouds from the cloud; the options given on the
  // command line still apply.
  pcl_ext::AutoProfileSegmentation<pcl::PointXYZ> automatic_segmentation;
  Segmentation given_segmentation;
  Segmentation& seg = automatic ? automatic_segmentation : given_segmentation;
  seg.setInputCloud (cloud);
  options.apply (seg, threads);
  pcl_ext::CylinderSegmentJoin<pcl::PointXYZ> join = options.makeJoin();
  automatic_segmentation.setCylinderJoin (join);

  std::vector<pcl::PointIndices> clusters;
  {
    pcl_ext::apps::StageTimer timer ("Segmenting");
    seg.extract (clusters);
    if (clusters.empty()) {
      std::cerr << "Error: segmentation failed (see the message above).\n";
      return 1;
    }
    timer.done (cloud->size());
  }
  bool curve_fitting = options.method == Segmentation::ProfileMethod::CurveFitting;
  if (automatic) {
    const auto& chosen = automatic_segmentation.getConfiguration();
    if (verbose)
      std::cout << pcl_ext::profiles::describeConfiguration (
                       automatic_segmentation.getCloudStatistics(),
                       automatic_segmentation.getLargestProximityShare(),
                       chosen)
                << "\n";
    curve_fitting = chosen.curve_fitting;
  }
  const bool joined_by_segmentation =
      automatic && automatic_segmentation.getCylindersJoined();
  const bool join_cylinders = options.join_cylinders || joined_by_segmentation;
  if (join_cylinders && !joined_by_segmentation) {
    join.setInputCloud (cloud);
    join.setInputSegments (clusters);
    join.setNumberOfThreads (threads);
    pcl_ext::apps::StageTimer joining ("Joining cylinders");
    join.join (clusters);
    if (clusters.empty()) {
      std::cerr << "Error: joining the cylinders failed (see the message above).\n";
      return 1;
    }
    joining.done (cloud->size());
  }
  std::size_t joined_cylinders = 0;
  std::ostringstream join_settings;
  if (join_cylinders) {
    const auto& used_join =
        joined_by_segmentation ? automatic_segmentation.getCylinderJoin() : join;
    for (const auto& c : used_join.getCylinders())
      joined_cylinders += c.output_segment >= 0;
    const auto& used = used_join.getUsedParameters();
    join_settings << " (spacing " << used_join.getUsedPointSpacing() << ", tolerance "
                  << used.detection.distance_tolerance << ", radii "
                  << used.detection.min_radius << " to " << used.detection.max_radius
                  << ", gap " << used.max_gap << ", patch "
                  << used.detection.neighbourhood_radius << ")";
  }
  std::size_t edges = 0;
  for (const auto& stack : seg.getStackEdges())
    edges += stack.size();
  std::cout << "spacing " << seg.getUsedPointSpacing() << ", width "
            << seg.getUsedProfileWidth() << ", threshold "
            << seg.getUsedDistanceThreshold() << "; " << seg.getStackEdges().size()
            << " stacks, " << edges << " edges, " << clusters.size() << " segments";
  if (curve_fitting)
    std::cout << ", " << seg.getBreakpoints().size() << " curve ends, "
              << seg.getJunctionJoins() << " curves followed across junctions";
  if (join_cylinders)
    std::cout << ", " << joined_cylinders << " cylinders joined" << join_settings.str();
  std::cout << "\n";

  pcl::PointCloud<pcl::Label> labels;
  labels.resize (cloud->size());
  for (auto& l : labels)
    l.label = 0;
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const auto i : clusters[c].indices)
      labels[i].label = static_cast<std::uint32_t> (c + 1);
  std::vector<std::uint32_t> ids (labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    ids[i] = labels[i].label;
  if (!result.save (output_path, input, ids))
    return 1;

  if (!png_path.empty() || !png_profiles_path.empty()) {
#ifdef PCL_EXT_HAVE_VISUALIZATION
    if (!png_path.empty()) {
      pcl_ext::apps::StageTimer render ("Rendering " + png_path);
      std::vector<std::uint32_t> ids;
      for (const auto& l : labels)
        ids.push_back (l.label);
      pcl_ext::visualization::View view;
      view.title = "Sithole & Mapurisa: " + std::to_string (clusters.size()) +
                   " segments (" + options.method_name + ")";
      view.layers.push_back ({pcl_ext::visualization::makeColouredCloud (
          *cloud, pcl_ext::visualization::colourByLabel (ids))});
      view.legend.push_back (
          {"unsegmented", pcl_ext::visualization::colourByLabel ({0u}).front()});
      if (!pcl_ext::visualization::renderToPng (
              {view}, png_path, picture.renderOptions (*cloud)))
        return 1;
      render.done (labels.size());
    }
    if (!png_profiles_path.empty()) {
      pcl_ext::apps::StageTimer render ("Rendering " + png_profiles_path);
      if (!renderProfiles (
              *cloud, seg, png_profiles_path, picture.renderOptions (*cloud)))
        return 1;
      render.done (labels.size());
    }
#else
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
#endif
  }
  return 0;
}
