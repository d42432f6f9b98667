/*
 * Benchmark: LAZ decompression speed on one core, in points per second.
 *
 * pcl_ext_benchmark_laz [file.laz ...] [-repeats N] [-block N]
 * Each file is decoded whole N times (default 5) through makeLazRecordSource, N records
 * a call (default 4096); the best run counts, by the wall clock and by the thread's
 * CPU time (on a shared machine the wall clock also counts the time other processes
 * held the core). Default file: autzen_trim.laz of the shared LAS samples.
 */
#include "../io/laz_test_file.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {
/** The CPU time of this thread, to the scheduler's nanosecond. */
double
cpuSeconds ()
{
  timespec t{};
  clock_gettime (CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double> (t.tv_sec) + 1e-9 * static_cast<double> (t.tv_nsec);
}
} // namespace

int
main (int argc, char** argv)
{
  std::vector<std::string> files;
  int repeats = 5;
  std::size_t block = 4096;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h") {
      std::printf ("usage: %s [file.laz ...] [-repeats N (5)] [-block N (4096)]\n",
                   argv[0]);
      return 0;
    }
    if (arg == "-repeats" && i + 1 < argc)
      repeats = std::atoi (argv[++i]);
    else if (arg == "-block" && i + 1 < argc)
      block = static_cast<std::size_t> (std::atol (argv[++i]));
    else if (!arg.empty() && arg[0] == '-') {
      std::fprintf (stderr, "unknown option %s (-h for help)\n", arg.c_str());
      return 1;
    }
    else
      files.push_back (arg);
  }
  if (files.empty())
    files.push_back (std::string (PCL_EXT_SHARED_DATA_DIR) +
                     "/las_samples/autzen_trim.laz");
  if (repeats < 1 || block < 1) {
    std::fprintf (stderr, "-repeats and -block must be positive\n");
    return 1;
  }
  for (const auto& path : files) {
    const LasTestFile f = readLasTestFile (path);
    if (f.laszip_vlr.empty()) {
      std::fprintf (stderr, "%s: no LASzip VLR\n", path.c_str());
      return 1;
    }
    std::vector<std::uint8_t> records (block * f.record_length);
    double best = 1e300, best_cpu = 1e300;
    for (int r = 0; r < repeats; ++r) {
      const double cpu_start = cpuSeconds();
      const auto start = std::chrono::steady_clock::now();
      auto source = pcl_ext::io::makeLazRecordSource (path,
                                                      f.point_data_offset,
                                                      f.point_format,
                                                      f.record_length,
                                                      f.point_count,
                                                      f.laszip_vlr);
      std::uint64_t done = 0;
      while (std::size_t n = source->readRecords (block, records.data()))
        done += n;
      const double s =
          std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
              .count();
      best_cpu = std::min (best_cpu, cpuSeconds() - cpu_start);
      if (done != f.point_count) {
        std::fprintf (stderr,
                      "%s: decoded %llu of %llu points\n",
                      path.c_str(),
                      static_cast<unsigned long long> (done),
                      static_cast<unsigned long long> (f.point_count));
        return 1;
      }
      best = std::min (best, s);
    }
    std::printf ("%s: point format %d, %llu points, best of %d: wall %.1f ms, %.2f M "
                 "points/s; CPU %.1f ms, %.2f M points/s\n",
                 path.c_str(),
                 f.point_format,
                 static_cast<unsigned long long> (f.point_count),
                 repeats,
                 best * 1e3,
                 f.point_count / best * 1e-6,
                 best_cpu * 1e3,
                 f.point_count / best_cpu * 1e-6);
  }
  return 0;
}
