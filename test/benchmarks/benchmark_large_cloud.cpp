/*
 * Benchmark: one large generated scene (20 million points by default) through the
 * Belton & Lichti classification (pcl_ext::LocalVarianceClassification), the Belton &
 * Lichti segmentation (pcl_ext::VarianceRegionGrowing: its own search, classification
 * and region growing) and the Sithole & Mapurisa profile segmentation
 * (pcl_ext::ProfileSegmentation), one after the other in one process. For each stage:
 * wall and CPU time, what it produced, and its peak resident memory, both above the
 * resident memory before it (the stage's working memory) and in total, per point of the
 * cloud.
 */
#include "benchmark_support.h"

#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/apps/command_line.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
namespace bm = pcl_ext::benchmark;

struct Measure {
  double wall = 0.0, cpu = 0.0;
  std::size_t base_bytes = 0, peak_bytes = 0;
  bool peak_valid = false;
};

/** Run \a stage and measure its time and its peak resident memory. */
Measure
measure (const std::function<void()>& stage)
{
  Measure m;
  m.base_bytes = bm::statusBytes ("VmRSS");
  m.peak_valid = bm::resetPeak();
  const double c0 = bm::cpuSeconds();
  const auto t0 = bm::Clock::now();
  stage();
  m.wall = bm::seconds (t0, bm::Clock::now());
  m.cpu = bm::cpuSeconds() - c0;
  m.peak_bytes = bm::statusBytes ("VmHWM");
  return m;
}

void
report (const std::string& name,
        const Measure& m,
        std::size_t points,
        const std::string& result)
{
  std::cout << std::left << std::setw (40) << name << std::right << std::fixed
            << std::setprecision (1) << std::setw (8) << m.wall << " s wall"
            << std::setw (8) << m.cpu << " s CPU";
  if (m.peak_valid && m.peak_bytes >= m.base_bytes)
    std::cout << std::setprecision (0) << std::setw (7)
              << static_cast<double> (m.peak_bytes - m.base_bytes) / points
              << " B/point working" << std::setw (7)
              << static_cast<double> (m.peak_bytes) / points << " B/point peak ("
              << std::setprecision (2) << m.peak_bytes / 1073741824.0 << " GiB)";
  std::cout << "  " << result << std::endl;
}

std::vector<std::string>
split (const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream in (text);
  for (std::string part; std::getline (in, part, ',');)
    parts.push_back (part);
  return parts;
}
} // namespace

int
main (int argc, char** argv)
{
  pcl_ext::benchmark::returnFreedArraysToTheSystem();
  int points = 20000000, k = 50;
  unsigned int threads = 2, seed = 1;
  std::string scene_name = "indoor", stages = "classify,segment,profiles";
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_large_cloud",
      "Runs one large generated scene through the Belton & Lichti classification and "
      "segmentation and the profile segmentation; prints time and peak memory per "
      "point.");
  cl.addOption ("points", points, "points in the generated scene");
  cl.addOption ("scene", scene_name, "generated scene");
  cl.addOption ("k", k, "neighbours per point of the Belton & Lichti stages");
  cl.addOption ("threads", threads, "OpenMP threads (0: all cores)");
  cl.addOption ("seed", seed, "random seed of the scene");
  cl.addOption (
      "stages", stages, "comma-separated stages: classify, segment, profiles");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  const std::vector<std::string> wanted = split (stages);
  const auto want = [&] (const std::string& s) {
    return std::find (wanted.begin(), wanted.end(), s) != wanted.end();
  };
  for (const auto& s : wanted)
    if (s != "classify" && s != "segment" && s != "profiles") {
      std::cerr << "Error: unknown stage '" << s
                << "' (classify, segment, profiles).\n";
      return 1;
    }
  if (points < 100 || k < 3 || wanted.empty()) {
    std::cerr << "Error: need points >= 100, k >= 3 and at least one stage.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);

  Cloud::Ptr cloud;
  const Measure gen = measure ([&] {
    cloud = bm::generateXyzCloud (scene_name, static_cast<std::size_t> (points), seed);
  });
  if (cloud->empty())
    return 1;
  const std::size_t n = cloud->size();
  std::cout << "cloud: " << n << " points (" << scene_name << ", seed " << seed
            << "), k = " << k << ", threads = " << threads << "\n";
  report ("scene generation (PointXYZ kept)", gen, n, "");

  bool ok = true;
  if (want ("classify")) {
    std::size_t classified = 0;
    const Measure m = measure ([&] {
      pcl_ext::LocalVarianceClassification<Point> c;
      c.setInputCloud (cloud);
      c.setKSearch (k);
      c.setNumberOfThreads (threads);
      pcl::PointCloud<pcl::Label> labels;
      c.classify (labels);
      classified = std::count_if (labels.begin(),
                                  labels.end(),
                                  [] (const pcl::Label& l) { return l.label != 0; });
    });
    report ("LocalVarianceClassification",
            m,
            n,
            std::to_string (classified) + " points classified");
    ok = ok && classified > 0;
  }
  if (want ("segment")) {
    std::size_t segments = 0;
    const Measure m = measure ([&] {
      pcl_ext::VarianceRegionGrowing<Point> rg;
      rg.setInputCloud (cloud);
      rg.setKSearch (k);
      rg.setMinClusterSize (50);
      rg.setNumberOfThreads (threads);
      pcl_ext::LocalVarianceClassification<Point> classifier;
      classifier.setNumberOfThreads (threads);
      std::vector<pcl::PointIndices> clusters;
      pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
      segments = clusters.size();
    });
    report ("VarianceRegionGrowing", m, n, std::to_string (segments) + " segments");
    ok = ok && segments > 0;
  }
  if (want ("profiles")) {
    std::size_t segments = 0;
    const Measure m = measure ([&] {
      pcl_ext::ProfileSegmentation<Point> ps;
      ps.setInputCloud (cloud);
      ps.setNumberOfThreads (threads);
      std::vector<pcl::PointIndices> clusters;
      ps.extract (clusters);
      segments = clusters.size();
    });
    report ("ProfileSegmentation", m, n, std::to_string (segments) + " segments");
    ok = ok && segments > 0;
  }
  std::cout << "cloud itself: " << sizeof (Point) << " B/point\n";
  return ok ? 0 : 1;
}
