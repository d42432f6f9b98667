/*
 * pcl_ext_tiles segment_profiles: Sithole & Mapurisa's segmentation split by profiles.
 */
#include "profile_tiles.h"
#include "../profiles/profile_options.h"
#include "input_fields.h"
#include "merge_output.h"
#include "profile_parts.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/io/read_error.h>
#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>
#include <sys/resource.h>

namespace pcl_ext {
namespace apps {
namespace {
/** At most this many points in a part (unless one profile holds more): with the
 * segmentation's arrays a process stays well under 2 GB. */
constexpr std::uint64_t kPointsPerPart = 4000000;
constexpr const char* kMethod = "segment_profiles";

/** The tool's own options beside the segmentation's. */
struct RunOptions {
  std::string workdir;
  unsigned int threads = 0;
  double tile_size = 0.0;
  bool keep_workdir = false;
  bool verbose = false;
};

long
peakMegabytes ()
{
  rusage usage{};
  ::getrusage (RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

std::string
planFile (const std::string& workdir)
{
  return workdir + "/plan.txt";
}

/** Remove what an earlier run left in \a workdir: only the names this run writes. */
bool
clearWorkdir (const std::string& workdir)
{
  std::error_code error;
  std::filesystem::create_directories (workdir, error);
  if (error || !std::filesystem::is_directory (workdir)) {
    std::cerr << "Error: cannot make the work folder " << workdir << ".\n";
    return false;
  }
  std::vector<std::filesystem::path> earlier;
  for (const auto& entry : std::filesystem::directory_iterator (workdir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind ("profiles_", 0) == 0 || name == "plan.txt" || name == "results.bin")
      earlier.push_back (entry.path());
  }
  for (const auto& path : earlier)
    std::filesystem::remove (path, error);
  if (error) {
    std::cerr << "Error: cannot clear the work folder " << workdir << ": "
              << error.message() << ".\n";
    return false;
  }
  return true;
}

/** What a tiled run cannot give yet: the curve fitting's stack-wide medians and the
 * local thresholds' stack-wide mean gap, over every part of a stack, and the cylinder
 * join's reach along an axis. \return false (message printed) for those */
bool
supportedOptions (const ProfileOptions& options)
{
  const char* missing = nullptr;
  if (options.method == ProfileOptions::Segmentation::ProfileMethod::CurveFitting &&
      !options.automatic())
    missing = "-method curve";
  else if (options.local_threshold)
    missing = "-local_threshold";
  else if (options.join_cylinders)
    missing = "-join_cylinders";
  if (!missing)
    return true;
  std::cerr << "Error: pcl_ext_tiles segment_profiles does not run " << missing
            << " yet: run pcl_ext_segment_profiles on the whole cloud.\n";
  return false;
}

bool
plan (const std::vector<std::string>& inputs,
      const ProfileOptions& options,
      const RunOptions& run,
      const std::vector<std::string>& arguments,
      tiling::TilePlan& plan)
{
  if (!clearWorkdir (run.workdir))
    return false;
  StageTimer timer ("Planning");
  try {
    // The grid only lays the files of an output named with '#'.
    if (!tiling::planTiles (inputs, 1e9, 0.0, plan))
      return false;
    const double tile_size = run.tile_size > 0.0
                                 ? run.tile_size
                                 : tiling::fitTileSize (plan, kPointsPerPart / 2);
    if (!tiling::planTiles (inputs, tile_size, 0.0, plan))
      return false;
    pcl::PCLPointCloud2 layout;
    if (!unionOfInputFields (inputs, layout) || !sameCoordinateSystem (inputs))
      return false;
    if (plan.getTotalPoints() >= tiling::TileResults::kNoResult) {
      std::cerr << "\nError: " << plan.getTotalPoints()
                << " points: segment_profiles merges at most 4,294,967,294.\n";
      return false;
    }
    const auto normals =
        profiles::makeStackNormals (options.stacks, options.stackDistribution());
    const bool sample =
        options.automatic() || options.width == 0.0 || options.threshold == 0.0;
    ProfileFrame frame;
    if (!estimateProfileFrame (
            plan, normals, sample, options.width, options.width_factor, frame))
      return false;
    ProfileParts parts;
    if (!planProfileParts (plan, frame, run.tile_size, kPointsPerPart, parts) ||
        !writeProfileParts (plan, frame, parts, run.workdir))
      return false;
    plan.settings["method"] = kMethod;
    std::string text;
    for (const auto& a : arguments)
      text += (text.empty() ? "" : "\t") + a;
    plan.settings["arguments"] = text;
    frame.saveTo (plan.settings);
    parts.saveTo (plan.settings);
    if (!tiling::saveTilePlan (planFile (run.workdir), plan))
      return false;
    timer.done (plan.getTotalPoints());
    std::cout << parts.size() << " parts of whole profiles (" << normals.size()
              << " stacks, width " << std::setprecision (6) << frame.width << ") in "
              << run.workdir << "\n";
  }
  catch (const std::exception& e) {
    std::cerr << "\nError: " << e.what() << "\n";
    return false;
  }
  return true;
}

/** Segment part \a i and save each point's link to the first point of its component
 * (none for that first point). */
bool
runPart (const ProfileFrame& frame,
         const ProfileParts& parts,
         const ProfileOptions& options,
         const RunOptions& run,
         std::size_t i)
{
  std::size_t stack, part;
  parts.locate (i, stack, part);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::vector<std::uint64_t> indices;
  if (!readProfilePart (
          profilePartPath (run.workdir, stack, part, "points"), indices, *cloud))
    return false;
  ProfileOptions::Segmentation seg;
  options.apply (seg, run.threads);
  if (options.automatic()) // AutoProfileSegmentation's first run
    seg.setProfileSegmentation (ProfileOptions::Segmentation::ProfileMethod::Proximity);
  seg.setMinClusterSize (1); // the sizes count over all parts, at the merge
  seg.setStackNormals ({frame.normals[stack]});
  if (frame.spacing > 0.0)
    seg.setPointSpacing (frame.spacing);
  seg.setCloudFrame (frame.centre, {frame.origins[stack]});
  seg.setInputCloud (cloud);
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  if (clusters.empty() && !cloud->empty()) {
    std::cerr << "Error: part " << i << " (stack " << stack << ") failed (see the "
              << "message above).\n";
    return false;
  }
  std::vector<std::uint64_t> links;
  for (const auto& c : clusters)
    for (std::size_t k = 1; k < c.indices.size(); ++k) {
      links.push_back (indices[c.indices[k]]);
      links.push_back (indices[c.indices.front()]);
    }
  const std::string path = profilePartPath (run.workdir, stack, part, "links");
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen (partial.c_str(), "wb");
  const bool written =
      file && std::fwrite (links.data(), sizeof (std::uint64_t), links.size(), file) ==
                  links.size();
  if (!file || std::fclose (file) != 0 || !written ||
      std::rename (partial.c_str(), path.c_str()) != 0) {
    std::cerr << "Error: cannot write " << path << " (disk full?).\n";
    std::remove (partial.c_str());
    return false;
  }
  return true;
}

bool
readLinks (const std::string& path, std::vector<std::uint64_t>& links)
{
  links.clear();
  std::FILE* file = std::fopen (path.c_str(), "rb");
  if (!file) {
    std::cerr << "Error: " << path << " is missing: that part has not run.\n";
    return false;
  }
  std::uint64_t buffer[8192];
  std::size_t n;
  while ((n = std::fread (buffer, sizeof (std::uint64_t), 8192, file)) > 0)
    links.insert (links.end(), buffer, buffer + n);
  const bool ok = !std::ferror (file) && links.size() % 2 == 0;
  std::fclose (file);
  if (!ok)
    std::cerr << "Error: " << path << " is broken.\n";
  return ok;
}

/** Join the parts' links over all points, choose as -method auto would, number the
 * segments largest first (ties by first point) and save them as the run's results.
 * \return false (message printed) when a part is missing or the automatic choice is
 * one the parts cannot give */
bool
merge (const tiling::TilePlan& plan,
       const ProfileFrame& frame,
       const ProfileParts& parts,
       const ProfileOptions& options,
       const RunOptions& run,
       std::uint32_t& segments)
{
  StageTimer timer ("Joining the parts");
  const std::uint64_t total = plan.getTotalPoints();
  std::vector<std::uint32_t> parent (total), size (total, 0);
  std::iota (parent.begin(), parent.end(), 0u);
  const auto find = [&] (std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::uint64_t> links, indices;
  pcl::PointCloud<pcl::PointXYZ> unused;
  // Every finite point lies in one part of the first stack.
  for (std::size_t p = 0; p < parts.firsts[0].size(); ++p) {
    if (!readProfilePart (
            profilePartPath (run.workdir, 0, p, "points"), indices, unused))
      return false;
    for (const auto i : indices)
      size[i] = 1;
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::size_t s, p;
    parts.locate (i, s, p);
    if (!readLinks (profilePartPath (run.workdir, s, p, "links"), links))
      return false;
    for (std::size_t k = 0; k < links.size(); k += 2) {
      if (links[k] >= total || links[k + 1] >= total) {
        std::cerr << "Error: part " << i << "'s links are broken.\n";
        return false;
      }
      const std::uint32_t a = find (static_cast<std::uint32_t> (links[k]));
      const std::uint32_t b = find (static_cast<std::uint32_t> (links[k + 1]));
      if (a != b) // the smaller index is the root: a component's first point
        parent[std::max (a, b)] = std::min (a, b);
    }
  }
  std::uint32_t largest = 0;
  for (std::uint32_t i = 0; i < total; ++i)
    if (size[i]) {
      const std::uint32_t root = find (i);
      if (root != i) {
        size[root] += 1;
        size[i] = 0;
      }
    }
  for (std::uint32_t i = 0; i < total; ++i)
    largest = std::max (largest, size[i]);
  if (options.automatic()) {
    const double share =
        static_cast<double> (largest) / static_cast<double> (frame.points);
    const auto chosen = profiles::chooseConfiguration (frame.statistics, share);
    if (run.verbose)
      std::cout << profiles::describeConfiguration (frame.statistics, share, chosen)
                << "\n";
    if (chosen.curve_fitting || chosen.local_threshold) {
      std::cerr << "\nError: -method auto chose "
                << (chosen.curve_fitting ? "curve fitting" : "local thresholds")
                << " for this cloud ("
                << profiles::describeConfiguration (frame.statistics, share, chosen)
                << "), which pcl_ext_tiles segment_profiles does not run yet: run "
                   "pcl_ext_segment_profiles on the whole cloud.\n";
      return false;
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> kept; // (size, first point)
  for (std::uint32_t i = 0; i < total; ++i)
    if (size[i] >= static_cast<std::uint32_t> (options.min_size))
      kept.emplace_back (size[i], i);
  std::sort (kept.begin(), kept.end(), [] (const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  // size[] becomes each root's segment id (none for the points that are not finite,
  // their own roots, and for the segments dropped).
  std::fill (size.begin(), size.end(), tiling::TileResults::kNoResult);
  for (std::size_t k = 0; k < kept.size(); ++k)
    size[kept[k].second] = static_cast<std::uint32_t> (k);
  segments = static_cast<std::uint32_t> (kept.size());
  if (!tiling::TileResults::create (run.workdir, total))
    return false;
  std::vector<std::uint64_t> block_indices;
  std::vector<std::uint32_t> values;
  for (std::uint64_t first = 0; first < total; first += 1 << 20) {
    const std::uint64_t end = std::min<std::uint64_t> (total, first + (1 << 20));
    block_indices.clear();
    values.clear();
    for (std::uint64_t i = first; i < end; ++i) {
      const std::uint32_t root = find (static_cast<std::uint32_t> (i));
      block_indices.push_back (i);
      values.push_back (size[root]);
    }
    if (!tiling::TileResults::write (run.workdir, block_indices, values))
      return false;
  }
  timer.done (total);
  return true;
}

/** The inputs, the output and the options of a whole run. \return -1 to go on, else
 * the exit code */
int
parse (int argc,
       char** argv,
       CommandLine& cl,
       ProfileOptions& options,
       RunOptions& run,
       ResultField& field,
       std::vector<std::string>& inputs,
       std::string& output,
       std::vector<std::string>& arguments)
{
  std::string method;
  cl.addPositional ("METHOD", method, kMethod);
  cl.addPositionalList ("input", inputs, kInputFormats);
  cl.addPositional ("output", output, kOutputFormats);
  options.addTo (cl);
  field.addTo (cl);
  cl.addOption ("workdir",
                run.workdir,
                "work folder of the parts (default: the output's name + .tiles, "
                "removed at the end)");
  cl.addOption ("threads", run.threads, "OpenMP threads per process (0: all cores)");
  cl.addOption ("tile_size",
                run.tile_size,
                "thickness of a part in metres, along its stack's normal, in whole "
                "profiles (0: at most 4 million points a part), and the side of the "
                "tiles of an output named with '#' (0: at most 2 million points in the "
                "densest)");
  cl.addSwitch ("keep_workdir", run.keep_workdir, "keep the work folder");
  cl.addSwitch ("v",
                run.verbose,
                "print the cloud's spacing, noise and spacing variation and the "
                "configuration chosen from them (-method auto)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!options.valid() || !supportedOptions (options))
    return 1;
  if (!(run.tile_size >= 0.0) || !std::isfinite (run.tile_size)) {
    std::cerr << "Error: -tile_size must be >= 0.\n";
    return 1;
  }
  if (!field.checkOutput (output))
    return 1;
  arguments =
      cl.getGivenOptions ({"workdir", "threads", "tile_size", "keep_workdir", "v"});
  return -1;
}
} // namespace

int
runProfileTiles (int argc, char** argv, TileScheduler& scheduler)
{
  const auto start = std::chrono::steady_clock::now();
  const bool leader = scheduler.getRank() == 0;
  ProfileOptions options;
  RunOptions run;
  std::vector<std::string> inputs, arguments;
  std::string output;
  CommandLine cl ("pcl_ext_tiles",
                  "segment_profiles: the result of pcl_ext_segment_profiles on the "
                  "whole cloud, computed on parts that each hold whole profiles of "
                  "one stack (the parts shared among the ranks under mpirun).");
  ResultField field = segmentIdField(); // reads cl: declared after it
  if (const int code =
          parse (argc, argv, cl, options, run, field, inputs, output, arguments);
      code >= 0)
    return code;
  const bool own_workdir = run.workdir.empty();
  if (own_workdir)
    run.workdir = output + ".tiles";
  tiling::TilePlan tile_plan;
  bool ok = !leader || plan (inputs, options, run, arguments, tile_plan);
  ok = scheduler.allOk (ok) &&
       (leader || tiling::loadTilePlan (planFile (run.workdir), tile_plan));
  ProfileFrame frame;
  ProfileParts parts;
  ok = scheduler.allOk (ok && frame.loadFrom (tile_plan.settings) &&
                        parts.loadFrom (tile_plan.settings, frame.normals.size()));
  if (!ok)
    return 1;
  std::size_t i, done = 0;
  scheduler.startPhase (parts.size());
  while (ok && scheduler.next (i)) {
    ok = runPart (frame, parts, options, run, i);
    if (!ok) {
      std::cerr << "Error: part " << i << " failed; the work folder " << run.workdir
                << " is kept.\n";
      break;
    }
    ++done;
    const double seconds =
        std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
            .count();
    if (scheduler.getSize() == 1)
      std::cout << "  " << done << " / " << parts.size() << " parts, ETA "
                << static_cast<long> (seconds / done * (parts.size() - done)) << " s\n";
  }
  ok = scheduler.allOk (ok);
  std::uint32_t segments = 0;
  if (leader && ok) {
    ok = merge (tile_plan, frame, parts, options, run, segments);
    if (ok) {
      MergeReading reading;
      reading.segments = true;
      ok = writeMergedOutput (tile_plan, field, run.workdir, output, reading);
    }
  }
  ok = scheduler.allOk (ok);
  const double seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  std::cout << (scheduler.getSize() > 1
                    ? "Rank " + std::to_string (scheduler.getRank()) + ": "
                    : std::string())
            << (ok ? "done: " : "failed after ") << done << " of " << parts.size()
            << " parts";
  if (leader && ok)
    std::cout << ", " << segments << " segments";
  std::cout << ", " << tile_plan.getTotalPoints() << " points, " << std::fixed
            << std::setprecision (1) << seconds << " s, peak memory " << peakMegabytes()
            << " MB\n";
  if (leader && ok && own_workdir && !run.keep_workdir) {
    std::error_code ignored;
    std::filesystem::remove_all (run.workdir, ignored);
  }
  return ok ? 0 : 1;
}
} // namespace apps
} // namespace pcl_ext
