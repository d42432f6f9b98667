/*
 * Benchmark: each pcl_ext segmenter against its stock PCL counterpart on the generated
 * `indoor` scene, at several sizes and thread counts, as a Markdown table.
 *
 * Pairs: the profile segmenters (proximity, mst, curve) against
 * pcl::EuclideanClusterExtraction (both join points closer than 3 s); adaptive
 * super-voxels against pcl::SupervoxelClustering (voxel 2 s, seed 8 s); variance region
 * growing, when registered, against pcl::RegionGrowing with its normals. Methods and
 * parameters are those of pcl_ext_compare_segmenters (the same table). Every run
 * happens in its own child process (the scene too, so OpenMP never starts in this one):
 * time is the wall time of the method (normals included where the method needs them),
 * memory the child's peak resident set above what it started with. The best of the
 * repeats counts. A stock method that is the counterpart of several pcl_ext methods
 * (EuclideanClusterExtraction) is timed once per size and thread count.
 */
#include "isolated_run.h"
#include "segmenter_methods.h"

#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>

namespace {
using namespace pcl_ext::compare;

/** pcl::SupervoxelClustering alone: the stock counterpart of the adaptive super-voxels.
 */
bool
runPclSupervoxels (const SegmenterInput& in,
                   const SegmenterSettings& s,
                   std::vector<pcl::PointIndices>& clusters)
{
  pcl::SupervoxelClustering<pcl::PointXYZ> super (
      static_cast<float> (s.voxel * s.spacing),
      static_cast<float> (s.seed * s.spacing));
  super.setUseSingleCameraTransform (false);
  super.setInputCloud (in.cloud);
  std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr> supervoxels;
  super.extract (supervoxels);
  clusters.resize (supervoxels.size());
  return !supervoxels.empty();
}

struct Timing {
  bool ok = false;
  double seconds = 0.0;
  std::size_t peak_bytes = 0;
};

/** Best of \a repeats isolated runs; normals, when needed, are estimated inside the
 * run. */
Timing
timeMethod (const SegmenterMethod& method,
            SegmenterInput input,
            const SegmenterSettings& s,
            int repeats,
            double timeout)
{
  Timing best;
  for (int r = 0; r < repeats; ++r) {
    const auto run = runIsolated (
        [&] {
          if (method.needs_normals) {
            pcl::PointCloud<pcl::Normal>::Ptr normals (
                new pcl::PointCloud<pcl::Normal>);
            pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne (s.threads);
            ne.setInputCloud (input.cloud);
            ne.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
                new pcl::search::KdTree<pcl::PointXYZ>));
            ne.setKSearch (s.k);
            ne.compute (*normals);
            input.normals = normals;
          }
          std::vector<pcl::PointIndices> clusters;
          return method.run (input, s, clusters);
        },
        [] { return std::vector<char>(); },
        timeout);
    if (!run.ok) {
      std::cerr << "  " << method.name << ": " << run.error << "\n";
      return Timing();
    }
    if (!best.ok || run.seconds < best.seconds) {
      best.seconds = run.seconds;
      best.peak_bytes = run.peak_bytes;
    }
    best.ok = true;
  }
  return best;
}

/** The indoor scene at about \a points points, generated in a child process. */
bool
makeScene (std::size_t points, pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud)
{
  std::vector<float> xyz;
  const auto run = runIsolated (
      [&] {
        pcl_ext::simulation::SceneParameters parameters;
        parameters.points = points;
        pcl_ext::simulation::SyntheticScene scene;
        if (!pcl_ext::simulation::generateScene ("indoor", parameters, scene))
          return false;
        for (const auto& p : scene.cloud)
          xyz.insert (xyz.end(), {p.x, p.y, p.z});
        return true;
      },
      [&] {
        std::vector<char> bytes;
        appendBytes (xyz, bytes);
        return bytes;
      });
  if (!run.ok || run.result.size() % (3 * sizeof (float)) != 0)
    return false;
  std::size_t offset = 0;
  readBytes (run.result, offset, run.result.size() / sizeof (float), xyz);
  cloud.reset (new pcl::PointCloud<pcl::PointXYZ>);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    cloud->push_back (pcl::PointXYZ (xyz[i], xyz[i + 1], xyz[i + 2]));
  return !cloud->empty();
}

std::vector<std::size_t>
parseList (const std::string& text)
{
  std::vector<std::size_t> values;
  std::stringstream in (text);
  std::string item;
  while (std::getline (in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod (item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(v >= 1.0 && v <= 1e8))
      return {};
    values.push_back (static_cast<std::size_t> (v));
  }
  return values;
}

std::string
cell (const char* pattern, double value)
{
  char buffer[64];
  std::snprintf (buffer, sizeof (buffer), pattern, value);
  return buffer;
}
} // namespace

int
main (int argc, char** argv)
{
  std::string points_text = "100000", threads_text = "1,2";
  int repeats = 1;
  double timeout = 0.0;
  pcl_ext::apps::CommandLine cl ("pcl_ext_benchmark_segmenters",
                                 "Times each pcl_ext segmenter against its stock PCL "
                                 "counterpart on the generated indoor "
                                 "scene and prints a Markdown table: points per "
                                 "second, the time ratio pcl_ext / PCL "
                                 "(below 1: pcl_ext is faster), peak memory per point. "
                                 "Every run is a child process.");
  cl.addOption (
      "points", points_text, "scene sizes, comma-separated (e.g. 100000,1000000)");
  cl.addOption ("threads", threads_text, "thread counts, comma-separated");
  cl.addOption ("repeats", repeats, "runs per method and case; the best counts");
  cl.addOption ("timeout", timeout, "seconds after which a run is stopped (0: none)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  const auto sizes = parseList (points_text), thread_counts = parseList (threads_text);
  if (sizes.empty() || thread_counts.empty() || repeats < 1 || !(timeout >= 0.0)) {
    std::cerr
        << "Error: -points and -threads must be lists of positive numbers, -repeats at "
           "least 1, -timeout 0 or more.\n";
    return 1;
  }

  std::map<std::string, SegmenterMethod> methods;
  for (auto& m : allMethods())
    methods[m.name] = m;
  methods["supervoxels"] = {
      "supervoxels", "PCL", false, "pcl::SupervoxelClustering", runPclSupervoxels};
  const std::pair<const char*, const char*> pairs[] = {{"variance", "region_growing"},
                                                       {"proximity", "euclidean"},
                                                       {"mst", "euclidean"},
                                                       {"curve", "euclidean"},
                                                       {"adaptive_sv", "supervoxels"}};

  std::cout
      << "| scene points | threads | pcl_ext | points/s | B/point | PCL | points/s | "
         "B/point | time ratio |\n|---|---|---|---|---|---|---|---|---|\n";
  bool ok = true;
  for (const std::size_t size : sizes) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
    if (!makeScene (size, cloud)) {
      std::cerr << "Error: cannot generate the indoor scene with " << size
                << " points.\n";
      return 1;
    }
    SegmenterSettings settings;
    std::vector<Eigen::Vector3f> xyz;
    for (const auto& p : *cloud)
      xyz.push_back (p.getVector3fMap());
    settings.spacing = pcl_ext::profiles::estimatePointSpacing (xyz);
    SegmenterInput input;
    input.cloud = cloud;
    const double n = static_cast<double> (cloud->size());
    for (const std::size_t threads : thread_counts) {
      settings.threads = static_cast<unsigned int> (threads);
      std::map<std::string, Timing> stock_timings;
      for (const auto& [ours_name, stock_name] : pairs) {
        if (!methods.count (ours_name))
          continue; // not built into this version
        const auto ours =
            timeMethod (methods[ours_name], input, settings, repeats, timeout);
        if (!stock_timings.count (stock_name))
          stock_timings[stock_name] =
              timeMethod (methods[stock_name], input, settings, repeats, timeout);
        const Timing stock = stock_timings[stock_name];
        ok = ok && ours.ok && stock.ok;
        const auto rate = [n] (const Timing& t) {
          return t.ok ? cell ("%.3g", n / t.seconds) : std::string ("failed");
        };
        const auto per_point = [n] (const Timing& t) {
          return t.ok ? cell ("%.0f", static_cast<double> (t.peak_bytes) / n)
                      : std::string ("-");
        };
        std::cout << "| " << cloud->size() << " | " << threads << " | " << ours_name
                  << " | " << rate (ours) << " | " << per_point (ours) << " | "
                  << methods[stock_name].name << " | " << rate (stock) << " | "
                  << per_point (stock) << " | "
                  << (ours.ok && stock.ok ? cell ("%.2f", ours.seconds / stock.seconds)
                                          : std::string ("-"))
                  << " |" << std::endl;
      }
    }
  }
  return ok ? 0 : 1;
}
