/*
 * Benchmark: profile-intersection segmentation (Sithole & Mapurisa) against stock PCL
 * segmenters on the same generated TLS scenes, in one run.
 *
 * pcl_ext: AutoProfileSegmentation with its defaults (the configuration chosen from the
 * cloud, as pcl_ext_segment_profiles runs it; proximity chaining on these scenes).
 * Scenes: cubes (41,500 points; the paper: 9 s) and spheres (155,000; the paper: 35 s)
 * at their defaults, and cubes rescanned at a finer step to a large cloud (1M points by
 * default). Stock PCL: pcl::EuclideanClusterExtraction with our proximity threshold as
 * its tolerance (same spacing), and pcl::RegionGrowing (normals from
 * pcl::NormalEstimationOMP, k = 30, counted in its time) on the small scenes. Same
 * thread count for everyone. Prints the best time of the repeats, the ratios ours / PCL
 * (lower is better) and the object-level mean best IoU of each.
 */
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/region_growing.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

struct Run {
  double seconds = 1e30;
  double iou = 0.0;
  std::size_t segments = 0;
};

Run
timeIt (int repeats,
        const std::vector<std::uint32_t>& truth,
        const std::function<void (std::vector<pcl::PointIndices>&)>& segment)
{
  Run run;
  std::vector<pcl::PointIndices> clusters;
  for (int r = 0; r < repeats; ++r) {
    clusters.clear(); // pcl::EuclideanClusterExtraction appends to what it is given
    const auto t0 = std::chrono::steady_clock::now();
    segment (clusters);
    run.seconds = std::min (
        run.seconds,
        std::chrono::duration<double> (std::chrono::steady_clock::now() - t0).count());
  }
  pcl_ext::SegmentationMetrics metrics;
  pcl_ext::evaluateSegmentation (clusters, truth, metrics);
  run.iou = metrics.mean_best_iou;
  run.segments = clusters.size();
  return run;
}

void
print (const std::string& name, const Run& run, const Run* ours)
{
  std::cout << "  " << std::left << std::setw (44) << name << std::right << std::fixed
            << std::setprecision (3) << std::setw (8) << run.seconds << " s  "
            << std::setw (6) << run.segments << " segments  IoU "
            << std::setprecision (3) << run.iou;
  if (ours)
    std::cout << "  ratio ours/PCL " << std::setprecision (3)
              << ours->seconds / run.seconds;
  std::cout << "\n";
}

bool
benchmarkScene (const std::string& scene_name,
                std::size_t points,
                unsigned int threads,
                int repeats,
                bool region_growing,
                double goal)
{
  pcl_ext::simulation::SceneParameters parameters;
  parameters.points = points;
  pcl_ext::simulation::SyntheticScene scene;
  if (!pcl_ext::simulation::generateScene (scene_name, parameters, scene))
    return false;
  Cloud::Ptr cloud (new Cloud);
  std::vector<std::uint32_t> truth;
  cloud->reserve (scene.cloud.size());
  for (const auto& p : scene.cloud) {
    cloud->push_back (Point (p.x, p.y, p.z));
    truth.push_back (p.object);
  }
  std::cout << scene_name << ": " << cloud->size() << " points, " << threads
            << " threads\n";

  pcl_ext::AutoProfileSegmentation<Point> ours;
  ours.setInputCloud (cloud);
  ours.setNumberOfThreads (threads);
  const Run profile = timeIt (repeats, truth, [&] (auto& c) { ours.extract (c); });
  std::cout << std::defaultfloat << "  (spacing " << ours.getUsedPointSpacing()
            << ", width " << ours.getUsedProfileWidth() << ", threshold "
            << ours.getUsedDistanceThreshold() << ")\n";
  print (ours.getConfiguration().curve_fitting
             ? "pcl_ext::AutoProfileSegmentation (curves)"
             : "pcl_ext::AutoProfileSegmentation (proximity)",
         profile,
         nullptr);
  if (goal > 0)
    std::cout << "  goal: at most " << goal << " s -> "
              << (profile.seconds <= goal ? "met" : "NOT met") << "\n";

  const double tolerance = ours.getUsedDistanceThreshold();
  const Run euclidean = timeIt (repeats, truth, [&] (auto& c) {
    pcl::search::KdTree<Point>::Ptr tree (new pcl::search::KdTree<Point>);
    pcl::EuclideanClusterExtraction<Point> ece;
    ece.setInputCloud (cloud);
    ece.setSearchMethod (tree);
    ece.setClusterTolerance (tolerance);
    ece.extract (c);
  });
  print ("pcl::EuclideanClusterExtraction (same tol.)", euclidean, &profile);

  if (region_growing) {
    const Run growing = timeIt (repeats, truth, [&] (auto& c) {
      pcl::search::KdTree<Point>::Ptr tree (new pcl::search::KdTree<Point>);
      pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
      pcl::NormalEstimationOMP<Point, pcl::Normal> ne (threads);
      ne.setInputCloud (cloud);
      ne.setSearchMethod (tree);
      ne.setKSearch (30);
      ne.compute (*normals);
      pcl::RegionGrowing<Point, pcl::Normal> rg;
      rg.setInputCloud (cloud);
      rg.setInputNormals (normals);
      rg.setSearchMethod (tree);
      rg.setNumberOfNeighbours (30);
      rg.setSmoothnessThreshold (static_cast<float> (10.0 * M_PI / 180.0));
      rg.setCurvatureThreshold (0.05f);
      rg.extract (c);
    });
    print ("pcl::RegionGrowing (+ normals, k = 30)", growing, &profile);
  }
  return true;
}
} // namespace

int
main (int argc, char** argv)
{
  unsigned int threads = 2;
  int repeats = 3, large = 1000000, small = 0;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_profile_segmentation",
      "Times pcl_ext::ProfileSegmentation against pcl::EuclideanClusterExtraction and "
      "pcl::RegionGrowing on generated scenes (cubes, spheres, a large cubes scan).");
  cl.addOption ("threads", threads, "OpenMP threads for every method (0: all cores)");
  cl.addOption ("repeats", repeats, "runs per method; the best time counts");
  cl.addOption (
      "points", small, "points of the cubes and spheres scenes (0: their defaults)");
  cl.addOption ("large", large, "points of the large scene (0: skip it)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (repeats < 1 || small < 0 || large < 0) {
    std::cerr << "Error: need repeats >= 1 and non-negative point counts.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);
  const bool defaults = small == 0;
  if (!benchmarkScene ("cubes", small, threads, repeats, true, defaults ? 0.1 : 0.0) ||
      !benchmarkScene (
          "spheres", small, threads, repeats, true, defaults ? 0.5 : 0.0) ||
      (large > 0 && !benchmarkScene ("cubes",
                                     static_cast<std::size_t> (large),
                                     threads,
                                     repeats,
                                     false,
                                     large == 1000000 ? 3.0 : 0.0))) {
    std::cerr << "Error: scene generation failed.\n";
    return 1;
  }
  return 0;
}
