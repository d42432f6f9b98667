/*
 * Benchmark: Belton & Lichti classification (pcl_ext::LocalVarianceClassification)
 * against the shared neighbourhood search alone and against stock PCL's normals +
 * boundaries (pcl::NormalEstimationOMP + pcl::BoundaryEstimation), same cloud, same k,
 * same threads, in one run. Prints times, both ratios and the peak memory per point
 * above the cloud, and the time of the classification with its edges narrowed to their
 * creases (pcl_ext::EdgeLocalisation on the same search), pcl_ext_classify_variance's
 * default.
 */
#include "benchmark_support.h"

#include <pcl_ext/classification/edge_localisation.h>
#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/features/boundary.h>
#include <pcl/features/normal_3d_omp.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using pcl_ext::benchmark::Clock;
using pcl_ext::benchmark::cpuSeconds;
using pcl_ext::benchmark::seconds;
} // namespace

int
main (int argc, char** argv)
{
  pcl_ext::benchmark::returnFreedArraysToTheSystem();
  int points = 1000000, k = 50, repeats = 2;
  unsigned int threads = 2, seed = 1;
  std::string scene_name = "indoor";
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_local_variance",
      "Times the Belton & Lichti classification against the neighbourhood search alone "
      "and "
      "against pcl::NormalEstimationOMP + pcl::BoundaryEstimation.");
  cl.addOption ("points", points, "points in the generated scene");
  cl.addOption ("scene", scene_name, "generated scene");
  cl.addOption ("k", k, "neighbours per point");
  cl.addOption ("threads", threads, "OpenMP threads for every side (0: all cores)");
  cl.addOption ("repeats", repeats, "runs per side; the best time counts");
  cl.addOption ("seed", seed, "random seed of the scene");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (points < 100 || k < 3 || repeats < 1) {
    std::cerr << "Error: need points >= 100, k >= 3, repeats >= 1.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);

  const Cloud::Ptr cloud = pcl_ext::benchmark::generateXyzCloud (
      scene_name, static_cast<std::size_t> (points), seed);
  if (cloud->empty())
    return 1;
  std::cout << "cloud: " << cloud->size() << " points (" << scene_name << ", seed "
            << seed << "), k = " << k << ", threads = " << threads << "\n";

  // 1. The neighbourhood search alone.
  double t_search = 1e30, cpu_search = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const double c0 = cpuSeconds();
    const auto t0 = Clock::now();
    pcl_ext::Neighbourhoods<Point> nb;
    nb.setInputCloud (cloud);
    nb.setKSearch (k);
    nb.setNumberOfThreads (threads);
    if (!nb.compute())
      return 1;
    t_search = std::min (t_search, seconds (t0, Clock::now()));
    cpu_search = std::min (cpu_search, cpuSeconds() - c0);
  }

  // 2. The whole classification: its own search, covariances, all three tests, labels.
  double t_ours = 1e30, cpu_ours = 1e30;
  std::size_t peak_bytes = 0;
  const std::size_t base_bytes = pcl_ext::benchmark::statusBytes ("VmRSS");
  const bool peak_ok = pcl_ext::benchmark::resetPeak();
  std::size_t edges = 0;
  for (int r = 0; r < repeats; ++r) {
    const double c0 = cpuSeconds();
    const auto t0 = Clock::now();
    pcl_ext::LocalVarianceClassification<Point> c;
    c.setInputCloud (cloud);
    c.setKSearch (k);
    c.setNumberOfThreads (threads);
    pcl::PointCloud<pcl::Label> labels;
    c.classify (labels);
    t_ours = std::min (t_ours, seconds (t0, Clock::now()));
    cpu_ours = std::min (cpu_ours, cpuSeconds() - c0);
    if (labels.size() != cloud->size())
      return 1;
    edges = std::count_if (labels.begin(), labels.end(), [] (const pcl::Label& l) {
      return l.label == static_cast<std::uint32_t> (pcl_ext::PointClass::Edge);
    });
  }
  if (peak_ok)
    peak_bytes = pcl_ext::benchmark::statusBytes ("VmHWM");

  // 2b. As pcl_ext_classify_variance runs it by default: one search shared by the
  // classification and the narrowing of the edges to their creases.
  double t_tool = 1e30;
  std::size_t narrowed_edges = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<Point>>();
    nb->setInputCloud (cloud);
    nb->setKSearch (k);
    nb->setNumberOfThreads (threads);
    nb->setStoreSquaredDistances (false);
    if (!nb->compute())
      return 1;
    pcl_ext::LocalVarianceClassification<Point> c;
    c.setInputCloud (cloud);
    c.setNeighbourhoods (nb);
    c.setNumberOfThreads (threads);
    auto labels = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    c.classify (*labels);
    pcl_ext::EdgeLocalisation<Point> localisation;
    localisation.setInputCloud (cloud);
    localisation.setNeighbourhoods (nb);
    localisation.setNumberOfThreads (threads);
    localisation.setPointClasses (labels);
    pcl::PointCloud<pcl::Label> narrowed;
    if (!localisation.localise (narrowed))
      return 1;
    t_tool = std::min (t_tool, seconds (t0, Clock::now()));
    narrowed_edges = localisation.getReport().kept;
  }

  // 3. Stock PCL: normals (OpenMP) then boundaries (single-threaded in PCL), each with
  // its
  //    own FLANN tree, as a user would chain them.
  double t_stock = 1e30, t_normals = 0, t_boundary = 0, cpu_stock = 0;
  for (int r = 0; r < std::min (repeats, 1); ++r) {
    const double c0 = cpuSeconds();
    const auto t0 = Clock::now();
    pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
    pcl::NormalEstimationOMP<Point, pcl::Normal> ne (threads);
    ne.setInputCloud (cloud);
    ne.setKSearch (k);
    ne.compute (*normals);
    const auto t1 = Clock::now();
    pcl::PointCloud<pcl::Boundary> boundaries;
    pcl::BoundaryEstimation<Point, pcl::Normal, pcl::Boundary> be;
    be.setInputCloud (cloud);
    be.setInputNormals (normals);
    be.setKSearch (k);
    be.compute (boundaries);
    const auto t2 = Clock::now();
    if (seconds (t0, t2) < t_stock) {
      t_stock = seconds (t0, t2);
      t_normals = seconds (t0, t1);
      t_boundary = seconds (t1, t2);
      cpu_stock = cpuSeconds() - c0;
    }
  }

  std::cout << std::fixed << std::setprecision (3)
            << "neighbourhood search alone (pcl_ext::Neighbourhoods) : " << t_search
            << " s\n"
            << "pcl_ext::LocalVarianceClassification (search + all)  : " << t_ours
            << " s (" << edges << " edge points)\n"
            << "pcl::NormalEstimationOMP + pcl::BoundaryEstimation   : " << t_stock
            << " s (normals " << t_normals << " s, boundaries " << t_boundary << " s)\n"
            << "ratio classification / search alone : " << t_ours / t_search
            << "  (goal <= 1.5)\n"
            << "ratio stock PCL / classification    : " << t_stock / t_ours
            << "  (goal >= 5)\n"
            << "with the edges narrowed (pcl_ext_classify_variance's default): "
            << t_tool << " s (" << narrowed_edges
            << " edge points); ratio stock PCL / it: " << t_stock / t_tool
            << "  (goal >= 5)\n"
            << "CPU seconds (all threads): search " << cpu_search << ", classification "
            << cpu_ours << ", stock PCL " << cpu_stock << "\n";
  if (peak_bytes > base_bytes && base_bytes > 0)
    std::cout << "peak memory above the cloud        : " << std::setprecision (0)
              << static_cast<double> (peak_bytes - base_bytes) / cloud->size()
              << " bytes per point (resident " << base_bytes / 1048576 << " MB before, "
              << peak_bytes / 1048576 << " MB at the peak)\n";
  return 0;
}
