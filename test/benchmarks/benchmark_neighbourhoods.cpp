/*
 * Benchmark: the shared neighbourhood pass against a plain pcl::search::KdTree (FLANN) loop.
 *
 * Both sides build their tree and fill the same compact output (k indices and squared
 * distances per point) with the same number of OpenMP threads, on the same cloud, in one run.
 * Prints the times and the ratio ours / FLANN (lower is better).
 */
#include <pcl_ext/common/neighbourhoods.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/tools/command_line.h>

#include <pcl/search/kdtree.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>

namespace
{
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;

/** A room-like TLS cloud: points on walls, floor, ceiling and boxes, sampled by an equal-angle
  * scan from one station (density falls with range), 5 mm noise, fixed seed. */
Cloud::Ptr
makeScanLikeCloud (std::size_t target_points, unsigned seed)
{
  Cloud::Ptr cloud (new Cloud);
  cloud->reserve (target_points);
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> noise (0.0, 0.005);
  const double half_x = 6.0, half_y = 4.0, height = 3.0;
  const Eigen::Vector3d scanner (0.7, -0.4, 1.5);
  // Boxes (axis-aligned) standing on the floor: min and max corners.
  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> boxes = {
      {{2.0, 1.0, 0.0}, {3.0, 2.5, 1.0}}, {{-4.0, -3.0, 0.0}, {-2.5, -2.0, 2.0}},
      {{-1.0, 2.0, 0.0}, {0.0, 3.0, 0.7}}};
  const std::size_t rows = static_cast<std::size_t> (std::sqrt (target_points / 2.0)) + 1;
  const std::size_t cols = 2 * rows;
  for (std::size_t r = 0; r < rows && cloud->size () < target_points; ++r)
  {
    const double elevation = -M_PI / 2 * 0.95 + M_PI * 0.95 * (r + 0.5) / rows;
    for (std::size_t c = 0; c < cols && cloud->size () < target_points; ++c)
    {
      const double azimuth = 2 * M_PI * c / cols;
      const Eigen::Vector3d d (std::cos (elevation) * std::cos (azimuth),
                               std::cos (elevation) * std::sin (azimuth), std::sin (elevation));
      // Nearest hit among the room's inner faces and the boxes (slab test).
      double t_best = std::numeric_limits<double>::infinity ();
      const auto slab = [&] (const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool inside) {
        double t0 = 0, t1 = std::numeric_limits<double>::infinity ();
        for (int a = 0; a < 3; ++a)
        {
          if (std::abs (d[a]) < 1e-12)
            continue;
          double ta = (lo[a] - scanner[a]) / d[a], tb = (hi[a] - scanner[a]) / d[a];
          if (ta > tb)
            std::swap (ta, tb);
          t0 = std::max (t0, ta);
          t1 = std::min (t1, tb);
        }
        if (inside)
          return t1;  // leaving the room
        return t0 <= t1 && t0 > 0 ? t0 : std::numeric_limits<double>::infinity ();
      };
      t_best = slab ({-half_x, -half_y, 0}, {half_x, half_y, height}, true);
      for (const auto& b : boxes)
        t_best = std::min (t_best, slab (b.first, b.second, false));
      const Eigen::Vector3d p = scanner + (t_best + noise (rng)) * d;
      cloud->push_back (Point (p.x (), p.y (), p.z ()));
    }
  }
  return cloud;
}

double
seconds (std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double> (b - a).count ();
}

/** The stock-PCL way: build a FLANN tree, query every point in an OpenMP loop. */
double
runFlann (const Cloud::ConstPtr& cloud, int k, unsigned threads, pcl::Indices& out_indices,
          std::vector<float>& out_d2)
{
  const auto t0 = std::chrono::steady_clock::now ();
  pcl::search::KdTree<Point> tree;
  tree.setInputCloud (cloud);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (cloud->size ());
  out_indices.resize (cloud->size () * k);
  out_d2.resize (cloud->size () * k);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn (k);
    std::vector<float> d2 (k);
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t i = 0; i < n; ++i)
    {
      tree.nearestKSearch ((*cloud)[i], k, nn, d2);
      std::copy (nn.begin (), nn.end (), out_indices.begin () + i * k);
      std::copy (d2.begin (), d2.end (), out_d2.begin () + i * k);
    }
  }
  return seconds (t0, std::chrono::steady_clock::now ());
}

double
runOurs (const Cloud::ConstPtr& cloud, int k, unsigned threads,
         pcl_ext::Neighbourhoods<Point>& nb)
{
  const auto t0 = std::chrono::steady_clock::now ();
  nb.setInputCloud (cloud);
  nb.setKSearch (k);
  nb.setNumberOfThreads (threads);
  if (!nb.compute ())
    return -1.0;
  return seconds (t0, std::chrono::steady_clock::now ());
}
}  // namespace

int
main (int argc, char** argv)
{
  int points = 1000000, k = 50, repeats = 3;
  unsigned int threads = 2, seed = 1;
  pcl_ext::tools::CommandLine cl ("pcl_ext_benchmark_neighbourhoods",
                                  "Times the shared neighbourhood pass (pcl_ext::Neighbourhoods, "
                                  "nanoflann) against a pcl::search::KdTree (FLANN) kNN loop.");
  cl.addOption ("points", points, "points in the generated scan-like cloud");
  cl.addOption ("k", k, "neighbours per point");
  cl.addOption ("threads", threads, "OpenMP threads for both sides (0: all cores)");
  cl.addOption ("repeats", repeats, "runs per side; the best time counts");
  cl.addOption ("seed", seed, "random seed of the generated cloud");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (points < 1 || k < 1 || k > points || repeats < 1)
  {
    std::cerr << "Error: need points >= 1, 1 <= k <= points, repeats >= 1.\n";
    return 1;
  }
  threads = pcl_ext::resolveThreadCount (threads);

  Cloud::ConstPtr cloud = makeScanLikeCloud (static_cast<std::size_t> (points), seed);
  std::cout << "cloud: " << cloud->size () << " points (scan-like room, seed " << seed
            << "), k = " << k << ", threads = " << threads << "\n";

  double best_flann = 1e30, best_ours = 1e30;
  pcl::Indices flann_indices;
  std::vector<float> flann_d2;
  pcl_ext::Neighbourhoods<Point> nb;
  for (int r = 0; r < repeats; ++r)
  {
    best_flann = std::min (best_flann, runFlann (cloud, k, threads, flann_indices, flann_d2));
    const double ours = runOurs (cloud, k, threads, nb);
    if (ours < 0)
    {
      std::cerr << "Error: neighbourhood computation failed.\n";
      return 1;
    }
    best_ours = std::min (best_ours, ours);
  }

  // Same neighbourhoods (by distance: ties may order differently).
  double max_diff = 0;
  for (std::size_t i = 0; i < flann_d2.size (); ++i)
    max_diff = std::max (max_diff, std::abs (double (flann_d2[i]) - nb.getSquaredDistances ()[i]));
  const bool agree = nb.getSquaredDistances ().size () == flann_d2.size () && max_diff < 1e-6;

  std::cout << std::fixed << std::setprecision (3)
            << "pcl::search::KdTree (FLANN) loop : " << best_flann << " s\n"
            << "pcl_ext::Neighbourhoods          : " << best_ours << " s\n"
            << "ratio ours / FLANN               : " << best_ours / best_flann
            << "  (goal <= 0.70)\n"
            << "results agree                    : " << (agree ? "yes" : "NO") << "\n";
  return agree ? 0 : 1;
}
