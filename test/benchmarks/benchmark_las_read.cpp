/*
 * Benchmark: LAS reading into pcl::PCLPointCloud2 on one thread, in chunks
 * (LasReader::read) and whole (loadLas), next to pcl::PCDReader on the same points in
 * binary PCD.
 *
 * Reads the file given with -file, or writes a synthetic one first (-points points of
 * LAS 1.4 format 7: coordinates, intensity, GPS time and colour, about 1 km across) in
 * the system's temporary folder. Each way is run -repeats times; prints the best and
 * the median points per second, by the wall clock and by the process's CPU time (on a
 * shared machine the wall clock also counts the time other processes held the core).
 * The file is read once before timing, so that it is in the page cache: the figures are
 * the decoding's, not the disk's.
 */
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/las_writer.h>

#include <pcl/console/parse.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace {
using Clock = std::chrono::steady_clock;

double
cpuSeconds ()
{
  rusage u{};
  getrusage (RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec +
         1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/** Points per second of one run, by the wall clock and by CPU time. */
struct Rate {
  double wall = 0.0, cpu = 0.0;
};

template <typename Run>
Rate
measure (Run run)
{
  const double c0 = cpuSeconds();
  const auto t0 = Clock::now();
  const double n = static_cast<double> (run());
  return {n / std::chrono::duration<double> (Clock::now() - t0).count(),
          n / std::max (cpuSeconds() - c0, 1e-9)};
}

bool
writeSyntheticFile (const std::string& path, std::size_t points)
{
  pcl::PCLPointCloud2 cloud;
  const char* names[] = {
      "x", "y", "z", "intensity", "gps_time", "red", "green", "blue"};
  const std::uint8_t types[] = {pcl::PCLPointField::FLOAT32,
                                pcl::PCLPointField::FLOAT32,
                                pcl::PCLPointField::FLOAT32,
                                pcl::PCLPointField::FLOAT32,
                                pcl::PCLPointField::FLOAT64,
                                pcl::PCLPointField::UINT16,
                                pcl::PCLPointField::UINT16,
                                pcl::PCLPointField::UINT16};
  const std::uint32_t offsets[] = {0, 4, 8, 12, 16, 24, 26, 28};
  for (int i = 0; i < 8; ++i)
    cloud.fields.push_back ({names[i], offsets[i], types[i], 1});
  cloud.point_step = 32;
  cloud.width = static_cast<std::uint32_t> (points);
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize (cloud.row_step);
  std::mt19937 rng (1);
  std::uniform_real_distribution<float> xy (-500.f, 500.f), z (0.f, 50.f);
  for (std::size_t i = 0; i < points; ++i) {
    std::uint8_t* p = cloud.data.data() + i * cloud.point_step;
    const float v[4] = {
        xy (rng), xy (rng), z (rng), static_cast<float> (rng() % 65536)};
    const double t = 1e5 + 1e-5 * i;
    const std::uint16_t c[3] = {
        std::uint16_t (rng()), std::uint16_t (rng()), std::uint16_t (rng())};
    std::memcpy (p, v, 16);
    std::memcpy (p + 16, &t, 8);
    std::memcpy (p + 24, c, 6);
  }
  return pcl_ext::io::saveLas (path, cloud, Eigen::Vector3d (500000, 6000000, 0));
}

double
median (std::vector<double> v)
{
  std::sort (v.begin(), v.end());
  return v[v.size() / 2];
}

void
report (const std::string& name, const std::vector<Rate>& rates)
{
  std::vector<double> wall, cpu;
  for (const auto& r : rates) {
    wall.push_back (r.wall);
    cpu.push_back (r.cpu);
  }
  std::cout << std::left << std::setw (34) << name << std::right << std::fixed
            << std::setprecision (1) << "M points/s: wall best" << std::setw (6)
            << *std::max_element (wall.begin(), wall.end()) / 1e6 << " median"
            << std::setw (6) << median (wall) / 1e6 << "; CPU best" << std::setw (6)
            << *std::max_element (cpu.begin(), cpu.end()) / 1e6 << " median"
            << std::setw (6) << median (cpu) / 1e6 << std::endl;
}
} // namespace

int
main (int argc, char** argv)
{
  if (pcl::console::find_switch (argc, argv, "-h")) {
    std::cout << "Usage: " << argv[0]
              << " [-file in.las] [-points 3300000] [-chunk 1000000] [-repeats 5]\n";
    return 0;
  }
  std::string file;
  int points = 3300000, chunk = 1000000, repeats = 5;
  pcl::console::parse_argument (argc, argv, "-file", file);
  pcl::console::parse_argument (argc, argv, "-points", points);
  pcl::console::parse_argument (argc, argv, "-chunk", chunk);
  pcl::console::parse_argument (argc, argv, "-repeats", repeats);
  if (points < 1 || chunk < 1 || repeats < 1) {
    std::cerr << "-points, -chunk and -repeats must be positive" << std::endl;
    return 1;
  }
  const bool synthetic = file.empty();
  if (synthetic) {
    const char* tmp = std::getenv ("TMPDIR");
    file = std::string (tmp ? tmp : "/tmp") + "/pcl_ext_benchmark_las_" +
           std::to_string (::getpid()) + ".las";
    if (!writeSyntheticFile (file, static_cast<std::size_t> (points)))
      return 1;
  }
  int status = 0;
  try {
    pcl::PCLPointCloud2 cloud;
    pcl_ext::io::LasFileInfo info;
    pcl_ext::io::loadLas (file, cloud, info); // into the page cache
    std::cout << file << ": " << cloud.width << " points, format "
              << info.header.pointFormat() << ", " << info.header.record_length
              << "-byte records, " << cloud.point_step << "-byte points" << std::endl;
    std::vector<Rate> chunked, whole;
    for (int r = 0; r < repeats; ++r) {
      chunked.push_back (measure ([&file, chunk] {
        pcl_ext::io::LasReader reader;
        reader.open (file);
        pcl::PCLPointCloud2 part;
        std::size_t n = 0;
        while (const std::size_t got =
                   reader.read (static_cast<std::size_t> (chunk), part))
          n += got;
        return n;
      }));
      whole.push_back (measure ([&file, &info] {
        pcl::PCLPointCloud2 all;
        pcl_ext::io::loadLas (file, all, info);
        return all.width;
      }));
    }
    report ("chunks of " + std::to_string (chunk) + " (LasReader)", chunked);
    report ("whole file (loadLas)", whole);

    // The peer: PCL's own reader on the same points, as the LAS reader gives them, in
    // binary PCD (the fastest PCD encoding), read into a PCLPointCloud2 as well.
    const std::string pcd = file + ".pcd";
    pcl::PCDWriter writer;
    if (writer.writeBinary (pcd, cloud) != 0) {
      std::cerr << "cannot write " << pcd << std::endl;
      status = 1;
    }
    else {
      std::vector<Rate> peer;
      for (int r = 0; r < repeats; ++r)
        peer.push_back (measure ([&pcd] {
          pcl::PCLPointCloud2 all;
          pcl::PCDReader reader;
          reader.read (pcd, all);
          return static_cast<std::size_t> (all.width) * all.height;
        }));
      report ("pcl::PCDReader, binary PCD", peer);
      std::remove (pcd.c_str());
    }
  }
  catch (const pcl_ext::io::ReadError& e) {
    std::cerr << e.what() << std::endl;
    status = 1;
  }
  if (synthetic)
    std::remove (file.c_str());
  return status;
}
