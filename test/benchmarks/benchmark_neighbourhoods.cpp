/*
 * Benchmark: the shared neighbourhood pass against a plain pcl::search::KdTree (FLANN)
 * loop.
 *
 * The cloud is a generated TLS scene (default: `indoor`, 1M points). Both sides build
 * their tree and fill the same compact output (k indices and squared distances per
 * point) with the same number of OpenMP threads, on the same cloud, in one run. Prints
 * the times and the ratio ours / FLANN (lower is better).
 */
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/common/io.h>

#include <pcl/search/kdtree.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

/** The generated TLS scene \a name with about \a points points, as plain XYZ. */
Cloud::Ptr
makeScene (const std::string& name, std::size_t points, unsigned seed)
{
  pcl_ext::simulation::SceneParameters parameters;
  parameters.points = points;
  parameters.seed = seed;
  pcl_ext::simulation::SyntheticScene scene;
  Cloud::Ptr cloud (new Cloud);
  if (pcl_ext::simulation::generateScene (name, parameters, scene))
    pcl::copyPointCloud (scene.cloud, *cloud);
  return cloud;
}

double
seconds (std::chrono::steady_clock::time_point a,
         std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double> (b - a).count();
}

/** The stock-PCL way: build a FLANN tree, query every point in an OpenMP loop. */
double
runFlann (const Cloud::ConstPtr& cloud,
          int k,
          unsigned threads,
          pcl::Indices& out_indices,
          std::vector<float>& out_d2)
{
  const auto t0 = std::chrono::steady_clock::now();
  pcl::search::KdTree<Point> tree;
  tree.setInputCloud (cloud);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (cloud->size());
  out_indices.resize (cloud->size() * k);
  out_d2.resize (cloud->size() * k);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn (k);
    std::vector<float> d2 (k);
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      tree.nearestKSearch ((*cloud)[i], k, nn, d2);
      std::copy (nn.begin(), nn.end(), out_indices.begin() + i * k);
      std::copy (d2.begin(), d2.end(), out_d2.begin() + i * k);
    }
  }
  return seconds (t0, std::chrono::steady_clock::now());
}

double
runOurs (const Cloud::ConstPtr& cloud,
         int k,
         unsigned threads,
         pcl_ext::Neighbourhoods<Point>& nb)
{
  const auto t0 = std::chrono::steady_clock::now();
  nb.setInputCloud (cloud);
  nb.setKSearch (k);
  nb.setNumberOfThreads (threads);
  if (!nb.compute())
    return -1.0;
  return seconds (t0, std::chrono::steady_clock::now());
}
} // namespace

int
main (int argc, char** argv)
{
  int points = 1000000, k = 50, repeats = 3;
  std::string scene = "indoor";
  unsigned int threads = 2, seed = 1;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_neighbourhoods",
      "Times the shared neighbourhood pass (pcl_ext::Neighbourhoods, "
      "nanoflann) against a pcl::search::KdTree (FLANN) kNN loop.");
  cl.addOption ("scene", scene, "generated TLS scene (see pcl_ext_generate_scene)");
  cl.addOption ("points", points, "target points of the generated scene");
  cl.addOption ("k", k, "neighbours per point");
  cl.addOption ("threads", threads, "OpenMP threads for both sides (0: all cores)");
  cl.addOption ("repeats", repeats, "runs per side; the best time counts");
  cl.addOption ("seed", seed, "random seed of the generated scene");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (points < 1 || k < 1 || k > points || repeats < 1) {
    std::cerr << "Error: need points >= 1, 1 <= k <= points, repeats >= 1.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);

  Cloud::ConstPtr cloud = makeScene (scene, static_cast<std::size_t> (points), seed);
  if (cloud->size() < static_cast<std::size_t> (k)) {
    std::cerr << "Error: could not generate scene '" << scene
              << "' with at least k points.\n";
    return 1;
  }
  std::cout << "cloud: " << cloud->size() << " points (scene '" << scene << "', seed "
            << seed << "), k = " << k << ", threads = " << threads << "\n";

  double best_flann = 1e30, best_ours = 1e30;
  pcl::Indices flann_indices;
  std::vector<float> flann_d2;
  pcl_ext::Neighbourhoods<Point> nb;
  for (int r = 0; r < repeats; ++r) {
    best_flann =
        std::min (best_flann, runFlann (cloud, k, threads, flann_indices, flann_d2));
    const double ours = runOurs (cloud, k, threads, nb);
    if (ours < 0) {
      std::cerr << "Error: neighbourhood computation failed.\n";
      return 1;
    }
    best_ours = std::min (best_ours, ours);
  }

  // Same neighbourhoods (by distance: ties may order differently).
  double max_diff = 0;
  for (std::size_t i = 0; i < flann_d2.size(); ++i)
    max_diff = std::max (max_diff,
                         std::abs (double (flann_d2[i]) - nb.getSquaredDistances()[i]));
  const bool agree =
      nb.getSquaredDistances().size() == flann_d2.size() && max_diff < 1e-6;

  std::cout << std::fixed << std::setprecision (3)
            << "pcl::search::KdTree (FLANN) loop : " << best_flann << " s\n"
            << "pcl_ext::Neighbourhoods          : " << best_ours << " s\n"
            << "ratio ours / FLANN               : " << best_ours / best_flann
            << "  (goal <= 0.70)\n"
            << "results agree                    : " << (agree ? "yes" : "NO") << "\n";
  return agree ? 0 : 1;
}
