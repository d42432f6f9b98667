/*
 * Helpers shared by the benchmark programs: wall and CPU clocks, the process's resident
 * memory and its peak (Linux /proc), and a generated scene as a plain XYZ cloud.
 */
#pragma once

#include <pcl_ext/simulation/scenes.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <malloc.h>
#include <sys/resource.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace pcl_ext {
namespace benchmark {
using Clock = std::chrono::steady_clock;

inline double
seconds (Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double> (b - a).count();
}

/** CPU seconds of the whole process (all threads): on a shared machine the wall times
 * of parallel code suffer from other load more than single-threaded code, so both are
 * printed. */
inline double
cpuSeconds ()
{
  rusage u{};
  getrusage (RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec +
         1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/** A field of /proc/self/status in bytes (VmRSS: resident now, VmHWM: peak resident),
 * or 0 where it cannot be read. */
inline std::size_t
statusBytes (const std::string& key)
{
  std::ifstream in ("/proc/self/status");
  std::string line;
  while (std::getline (in, line))
    if (line.compare (0, key.size() + 1, key + ":") == 0)
      return 1024 * std::stoul (line.substr (key.size() + 1));
  return 0;
}

/** Make every allocation of a megabyte or more come from the system and go back to it
 * when freed (glibc otherwise raises that threshold after the first large free, up to
 * 32 MB, and keeps smaller freed blocks in its heap): the peak resident size then
 * counts every array alive at the peak, and an earlier stage's freed memory never hides
 * a later stage's. Call first in main(). */
inline void
returnFreedArraysToTheSystem ()
{
  mallopt (M_MMAP_THRESHOLD, 1 << 20);
  mallopt (M_TRIM_THRESHOLD, 1 << 20);
}

/** Reset the peak resident size to the current one, so VmHWM measures what follows
 * (Linux >= 4.0). False where the kernel does not allow it. */
inline bool
resetPeak ()
{
  std::ofstream out ("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool> (out);
}

/** A generated scene's points as PointXYZ, the scene's labels dropped; empty if the
 * scene could not be generated. \a truth, when given, receives each point's object id.
 */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
generateXyzCloud (const std::string& scene_name,
                  std::size_t points,
                  unsigned int seed,
                  std::vector<std::uint32_t>* truth = nullptr)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl_ext::simulation::SceneParameters parameters;
  parameters.points = points;
  parameters.seed = seed;
  parameters.connected_segments =
      false; // segment ids are not used: skip the piece search
  pcl_ext::simulation::SyntheticScene scene;
  if (!pcl_ext::simulation::generateScene (scene_name, parameters, scene))
    return cloud;
  cloud->reserve (scene.cloud.size());
  if (truth)
    truth->reserve (scene.cloud.size());
  for (const auto& p : scene.cloud) {
    cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    if (truth)
      truth->push_back (p.object);
  }
  return cloud;
}
} // namespace benchmark
} // namespace pcl_ext
