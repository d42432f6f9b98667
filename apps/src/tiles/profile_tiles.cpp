/*
 * pcl_ext_tiles segment_profiles: Sithole & Mapurisa's segmentation split by profiles.
 */
#include "profile_tiles.h"
#include "../profiles/profile_options.h"
#include "input_fields.h"
#include "merge_output.h"
#include "profile_curve_steps.h"
#include "profile_part_steps.h"
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
#include <sstream>
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

/** What a run over parts cannot give yet: the cylinder join, which fits cylinders to
 * whole segments and reaches 80 spacings along an axis. \return false (message
 * printed) for it */
bool
supportedOptions (const ProfileOptions& options)
{
  const char* missing = nullptr;
  if (options.join_cylinders)
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
    InputPasses passes (plan);
    if (!estimateProfileFrame (
            passes, normals, sample, options.width, options.width_factor, frame))
      return false;
    ProfileParts parts;
    if (!planProfileParts (passes, frame, run.tile_size, kPointsPerPart, parts) ||
        !writeProfileParts (passes, frame, parts, run.workdir))
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

/** -method auto's choice after its first run (AutoProfileSegmentation): \a rerun when
 * it adds local thresholds. \return false (message printed) for a choice the parts
 * cannot give yet */
bool
chooseAutomatically (const ProfileFrame& frame,
                     const JoinedParts& joined,
                     const ProfileOptions& options,
                     bool verbose,
                     bool& rerun)
{
  const double share =
      static_cast<double> (joined.largest) / static_cast<double> (frame.points);
  const auto chosen = profiles::chooseConfiguration (frame.statistics, share);
  const std::string line =
      profiles::describeConfiguration (frame.statistics, share, chosen);
  if (verbose)
    std::cout << line << "\n";
  if (chosen.curve_fitting) {
    std::cerr << "\nError: -method auto chose curve fitting with the cylinder join for "
                 "this cloud ("
              << line
              << "); pcl_ext_tiles segment_profiles runs curve fitting (-method curve) "
                 "but not the cylinder join yet: run pcl_ext_segment_profiles on the "
                 "whole cloud.\n";
    return false;
  }
  rerun = chosen.local_threshold && !options.local_threshold;
  return true;
}

/** Save \a values in the plan's settings under \a key (17 digits each). */
bool
saveValues (tiling::TilePlan& plan,
            const std::string& key,
            const std::vector<double>& values,
            const std::string& workdir)
{
  std::string text;
  char value[32];
  for (const double v : values) {
    std::snprintf (value, sizeof (value), "%.17g", v);
    text += (text.empty() ? "" : " ") + std::string (value);
  }
  plan.settings[key] = text;
  return tiling::saveTilePlan (planFile (workdir), plan);
}

bool
loadValues (const tiling::TilePlan& plan,
            const std::string& key,
            std::vector<double>& values)
{
  values.clear();
  const auto it = plan.settings.find (key);
  if (it == plan.settings.end()) {
    std::cerr << "Error: the plan has no " << key << ".\n";
    return false;
  }
  std::istringstream in (it->second);
  double v;
  while (in >> v)
    values.push_back (v);
  return true;
}

bool
saveRerun (tiling::TilePlan& plan, bool rerun, const std::string& workdir)
{
  plan.settings["profile_rerun"] = rerun ? "1" : "0";
  return tiling::saveTilePlan (planFile (workdir), plan);
}

bool
loadRerun (const tiling::TilePlan& plan, bool& rerun)
{
  const auto it = plan.settings.find ("profile_rerun");
  rerun = it != plan.settings.end() && it->second == "1";
  return it != plan.settings.end();
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
  std::size_t done = 0;
  // A pass over the parts shared among the processes; \a step names it in messages.
  const auto over_parts = [&] (const char* step, const auto& run_part) {
    std::size_t i, count = 0;
    scheduler.startPhase (parts.size());
    while (ok && scheduler.next (i)) {
      ok = run_part (i);
      if (!ok) {
        std::cerr << "Error: " << step << " of part " << i << " failed.\n";
        break;
      }
      ++count;
      ++done;
      const double seconds =
          std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
              .count();
      if (scheduler.getSize() == 1)
        std::cout << "  " << step << ": " << count << " / " << parts.size()
                  << " parts, " << static_cast<long> (seconds) << " s\n";
    }
    ok = scheduler.allOk (ok);
  };
  PartPass pass;
  pass.first_automatic = options.automatic();
  pass.local_threshold = options.local_threshold;
  // The local thresholds' mean gaps over the whole cloud, before the segmentation.
  const auto gaps_pass = [&] {
    ok = scheduler.allOk (ok &&
                          (!leader || createGapFiles (run.workdir,
                                                      parts.firsts.size(),
                                                      tile_plan.getTotalPoints())));
    over_parts ("local gaps", [&] (std::size_t i) {
      return computePartGaps (frame, parts, options, pass, run.workdir, run.threads, i);
    });
    ok = scheduler.allOk (
        ok && (!leader || reduceGaps (tile_plan, parts, run.workdir, pass.mean_gaps)));
    if (leader && ok) {
      pass.first_automatic = false;
      ok = saveValues (tile_plan, "profile_mean_gaps", pass.mean_gaps, run.workdir);
    }
    ok = scheduler.allOk (ok) &&
         (leader || (tiling::loadTilePlan (planFile (run.workdir), tile_plan) &&
                     loadValues (tile_plan, "profile_mean_gaps", pass.mean_gaps)));
    ok = scheduler.allOk (ok);
  };
  // Curve fitting (-method curve): the scores, each stack's curve ends from its
  // medians over every part, then the joins across junctions given every stack's ends.
  const bool curves =
      !options.automatic() &&
      options.method == ProfileOptions::Segmentation::ProfileMethod::CurveFitting;
  std::vector<double> junction_tolerances;
  const auto segment_pass = [&] {
    if (!curves) {
      over_parts ("chains", [&] (std::size_t i) {
        return segmentPart (frame, parts, options, pass, run.workdir, run.threads, i);
      });
      return;
    }
    over_parts ("curve scores", [&] (std::size_t i) {
      return scorePartCurves (frame, parts, options, pass, run.workdir, run.threads, i);
    });
    ok = scheduler.allOk (
        ok &&
        (!leader ||
         (findCurveEnds (
              tile_plan, frame, parts, options, run.workdir, junction_tolerances) &&
          saveValues (tile_plan,
                      "profile_junction_tolerances",
                      junction_tolerances,
                      run.workdir))));
    ok = scheduler.allOk (
        ok &&
        (leader ||
         (tiling::loadTilePlan (planFile (run.workdir), tile_plan) &&
          loadValues (tile_plan, "profile_junction_tolerances", junction_tolerances))));
    over_parts ("curve joins", [&] (std::size_t i) {
      return joinPartCurves (frame,
                             parts,
                             options,
                             pass,
                             junction_tolerances,
                             run.workdir,
                             run.threads,
                             i);
    });
  };
  if (pass.local_threshold)
    gaps_pass();
  if (ok)
    segment_pass();
  JoinedParts joined;
  std::uint32_t segments = 0;
  if (ok && options.automatic()) {
    // -method auto: the choice from the first run's largest segment, as
    // AutoProfileSegmentation makes it; the other ranks learn it through the plan.
    bool rerun = false;
    if (leader) {
      ok = joinParts (tile_plan, parts, run.workdir, joined) &&
           chooseAutomatically (frame, joined, options, run.verbose, rerun) &&
           saveRerun (tile_plan, rerun, run.workdir);
    }
    ok = scheduler.allOk (ok) &&
         (leader || (tiling::loadTilePlan (planFile (run.workdir), tile_plan) &&
                     loadRerun (tile_plan, rerun)));
    ok = scheduler.allOk (ok);
    if (ok && rerun) {
      pass.local_threshold = true;
      gaps_pass();
      pass.first_automatic = false;
      if (ok)
        segment_pass();
      joined = JoinedParts();
    }
  }
  if (leader && ok) {
    StageTimer timer ("Joining the parts");
    ok = (joined.sets.size() > 0 ||
          (curves ? labelCurveSegments (tile_plan, parts, run.workdir, joined)
                  : joinParts (tile_plan, parts, run.workdir, joined))) &&
         saveSegments (run.workdir,
                       static_cast<std::uint64_t> (options.min_size),
                       joined,
                       segments);
    if (ok)
      timer.done (tile_plan.getTotalPoints());
    joined = JoinedParts();
    if (ok) {
      MergeReading reading;
      reading.segments = true;
      ok = writeMergedOutput (tile_plan, field, run.workdir, output, reading);
    }
  }
  ok = scheduler.allOk (ok);
  const double seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  std::string what = std::to_string (done) + " part runs";
  if (leader && ok)
    what += ", " + std::to_string (segments) + " segments";
  printRunSummary (scheduler, ok, what, tile_plan.getTotalPoints(), seconds);
  if (leader && ok && own_workdir && !run.keep_workdir) {
    std::error_code ignored;
    std::filesystem::remove_all (run.workdir, ignored);
  }
  if (!ok && leader)
    std::cerr << "The work folder " << run.workdir << " is kept.\n";
  return ok ? 0 : 1;
}
} // namespace apps
} // namespace pcl_ext
