/*
 * Benchmark: Belton & Lichti segmentation (pcl_ext::VarianceRegionGrowing:
 * neighbourhood search, classification and region growing) against stock PCL's normals
 * + region growing (pcl::NormalEstimationOMP + pcl::RegionGrowing), same cloud, same
 * threads, in one run. Prints both times, the ratio and where our time goes, and the
 * time of section 4's re-integration and of the new segments among the points left
 * out, which pcl_ext_segment_variance runs by default.
 */
#include "benchmark_support.h"

#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using pcl_ext::benchmark::Clock;
using pcl_ext::benchmark::seconds;
} // namespace

int
main (int argc, char** argv)
{
  int points = 1000000, k = 50, rg_k = 30, repeats = 1;
  unsigned int threads = 2, seed = 1;
  std::string scene_name = "indoor";
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_variance_segmentation",
      "Times Belton & Lichti segmentation (search + classification + region growing) "
      "against "
      "pcl::NormalEstimationOMP + pcl::RegionGrowing on the same generated scene.");
  cl.addOption ("points", points, "points in the generated scene");
  cl.addOption ("scene", scene_name, "generated scene");
  cl.addOption ("k", k, "neighbours per point (ours, and PCL's normals)");
  cl.addOption ("rg_k", rg_k, "neighbours of pcl::RegionGrowing");
  cl.addOption ("threads", threads, "OpenMP threads for every side (0: all cores)");
  cl.addOption ("repeats", repeats, "runs per side; the best time counts");
  cl.addOption ("seed", seed, "random seed of the scene");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (points < 100 || k < 3 || rg_k < 1 || repeats < 1) {
    std::cerr << "Error: need points >= 100, k >= 3, rg_k >= 1, repeats >= 1.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);

  const Cloud::Ptr cloud = pcl_ext::benchmark::generateXyzCloud (
      scene_name, static_cast<std::size_t> (points), seed);
  if (cloud->empty())
    return 1;
  std::cout << "cloud: " << cloud->size() << " points (" << scene_name << ", seed "
            << seed << "), k = " << k << ", pcl::RegionGrowing k = " << rg_k
            << ", threads = " << threads << "\n";

  // 1. Ours, as a user calls it: one call that searches, classifies and grows.
  double t_ours = 1e30;
  std::size_t ours_segments = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    pcl_ext::VarianceRegionGrowing<Point> rg;
    rg.setInputCloud (cloud);
    rg.setKSearch (k);
    rg.setMinClusterSize (50);
    rg.setNumberOfThreads (threads);
    pcl_ext::LocalVarianceClassification<Point> classifier;
    classifier.setNumberOfThreads (threads);
    std::vector<pcl::PointIndices> clusters;
    pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
    t_ours = std::min (t_ours, seconds (t0, Clock::now()));
    if (clusters.empty())
      return 1;
    ours_segments = clusters.size();
  }

  // 2. Stock PCL: normals (OpenMP), then region growing (single-threaded in PCL) with
  // its own
  //    FLANN tree, as a user would chain them.
  double t_stock = 1e30, t_normals = 0, t_growing = 0;
  std::size_t stock_segments = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
    pcl::NormalEstimationOMP<Point, pcl::Normal> ne (threads);
    ne.setInputCloud (cloud);
    ne.setKSearch (k);
    ne.compute (*normals);
    const auto t1 = Clock::now();
    pcl::RegionGrowing<Point, pcl::Normal> stock;
    stock.setInputCloud (cloud);
    stock.setInputNormals (normals);
    stock.setSearchMethod (
        pcl::search::KdTree<Point>::Ptr (new pcl::search::KdTree<Point>));
    stock.setNumberOfNeighbours (rg_k);
    stock.setSmoothnessThreshold (3.0 * M_PI / 180.0);
    stock.setCurvatureThreshold (1.0);
    stock.setMinClusterSize (50);
    std::vector<pcl::PointIndices> clusters;
    stock.extract (clusters);
    const auto t2 = Clock::now();
    if (seconds (t0, t2) < t_stock) {
      t_stock = seconds (t0, t2);
      t_normals = seconds (t0, t1);
      t_growing = seconds (t1, t2);
    }
    stock_segments = clusters.size();
  }

  // 3. Where our time goes: the same steps one by one, sharing the neighbourhoods.
  const auto t0 = Clock::now();
  pcl_ext::Neighbourhoods<Point>::Ptr nb (new pcl_ext::Neighbourhoods<Point>);
  nb->setInputCloud (cloud);
  nb->setKSearch (k);
  nb->setNumberOfThreads (threads);
  nb->setStoreSquaredDistances (false); // as segmentByLocalVariance and the tool
  if (!nb->compute())
    return 1;
  const auto t1 = Clock::now();
  pcl::PointCloud<pcl::Label>::Ptr classes (new pcl::PointCloud<pcl::Label>);
  pcl_ext::LocalVarianceClassification<Point> lvc;
  lvc.setInputCloud (cloud);
  lvc.setNeighbourhoods (nb);
  lvc.setNumberOfThreads (threads);
  lvc.classify (*classes);
  const auto t2 = Clock::now();
  pcl_ext::VarianceRegionGrowing<Point> rg;
  rg.setInputCloud (cloud);
  rg.setNeighbourhoods (nb);
  rg.setInputClasses (classes);
  rg.setMinClusterSize (50);
  rg.setNumberOfThreads (threads);
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  const auto t3 = Clock::now();
  // Section 4 (pcl_ext_segment_variance's default): the edge and boundary points
  // re-integrated into the segments, on the same neighbourhoods.
  pcl::PointCloud<pcl::Label>::Ptr segments (new pcl::PointCloud<pcl::Label>);
  rg.getSegmentLabels (*segments);
  pcl_ext::LocalSurfaceIntersection<Point> lsi;
  lsi.setInputCloud (cloud);
  lsi.setNeighbourhoods (nb);
  lsi.setSegmentLabels (segments);
  lsi.setPointClasses (classes);
  lsi.setNumberOfThreads (threads);
  pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
  pcl::PointCloud<pcl::Label> reintegrated;
  if (!lsi.compute (intersections, reintegrated))
    return 1;
  const auto t4 = Clock::now();
  pcl_ext::LeftoverRegionGrowing<Point> leftovers;
  leftovers.setInputCloud (cloud);
  leftovers.setNeighbourhoods (nb);
  leftovers.setSegmentLabels (
      pcl::make_shared<pcl::PointCloud<pcl::Label>> (reintegrated));
  leftovers.setNumberOfThreads (threads);
  auto grown = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  if (!leftovers.compute (*grown))
    return 1;
  const auto t5 = Clock::now();
  // The interleaved pieces of one plane merged and the points left over assigned
  // (default too).
  pcl_ext::CoplanarSegmentMerging<Point> merging;
  merging.setInputCloud (cloud);
  merging.setNeighbourhoods (nb);
  merging.setSegmentLabels (grown);
  merging.setNumberOfThreads (threads);
  auto merged = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  if (!merging.compute (*merged))
    return 1;
  pcl_ext::LeftoverPlaneAssignment<Point> assignment;
  assignment.setInputCloud (cloud);
  assignment.setNeighbourhoods (nb);
  assignment.setSegmentLabels (merged);
  assignment.setNumberOfThreads (threads);
  pcl::PointCloud<pcl::Label> assigned;
  if (!assignment.compute (assigned))
    return 1;
  const auto t6 = Clock::now();
  const double t_section4 = seconds (t3, t4), t_leftovers = seconds (t4, t5),
               t_last = seconds (t5, t6);

  std::cout << std::fixed << std::setprecision (3)
            << "pcl_ext::VarianceRegionGrowing (search + classes + growing): " << t_ours
            << " s (" << ours_segments << " segments)\n"
            << "  steps: search " << seconds (t0, t1) << " s, classification "
            << seconds (t1, t2) << " s, growing " << seconds (t2, t3) << " s\n"
            << "pcl::NormalEstimationOMP + pcl::RegionGrowing             : " << t_stock
            << " s (normals " << t_normals << " s, growing " << t_growing << " s; "
            << stock_segments << " segments)\n"
            << "ratio stock PCL / ours : " << t_stock / t_ours << "  (goal >= 3)\n"
            << "section 4's re-integration (pcl_ext_segment_variance's default): "
            << t_section4 << " s ("
            << lsi.getReport().reintegrated + lsi.getReport().ambiguous
            << " points re-integrated); ratio stock PCL / ours with it: "
            << t_stock / (t_ours + t_section4) << "\n"
            << "new segments among the points left out (default too): " << t_leftovers
            << " s (" << leftovers.getReport().segments
            << " segments); ratio stock PCL / ours with both: "
            << t_stock / (t_ours + t_section4 + t_leftovers) << "\n"
            << "interleaved pieces merged and the points left over assigned (default "
               "too): "
            << t_last << " s (" << merging.getReport().merges << " merges, "
            << assignment.getReport().assigned
            << " points assigned); ratio stock PCL / ours with every default stage: "
            << t_stock / (t_ours + t_section4 + t_leftovers + t_last) << "\n";
  return 0;
}
