/*
 * pcl_ext_tiles segment_profiles: Sithole & Mapurisa's segmentation split by profiles.
 */
#include "profile_tiles.h"
#include "../profiles/profile_options.h"
#include "input_fields.h"
#include "merge_output.h"
#include "profile_curve_steps.h"
#include "profile_cylinder_join.h"
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

/** -method auto's choice after its first run (AutoProfileSegmentation), from the
 * whole cloud's statistics and the share of its largest segment. */
profiles::AutoConfiguration
chooseAutomatically (const ProfileFrame& frame, const JoinedParts& joined, bool verbose)
{
  const double share =
      static_cast<double> (joined.largest) / static_cast<double> (frame.points);
  const auto chosen = profiles::chooseConfiguration (frame.statistics, share);
  if (verbose)
    std::cout << profiles::describeConfiguration (frame.statistics, share, chosen)
              << "\n";
  return chosen;
}

/** The options of AutoProfileSegmentation's second run after its choice \a chosen:
 * curve fitting, the noisy-scan settings where the paper's values were left, side
 * frames, local thresholds. */
void
applyChoice (const profiles::AutoConfiguration& chosen, ProfileOptions& options)
{
  if (chosen.curve_fitting)
    options.method = ProfileOptions::Segmentation::ProfileMethod::CurveFitting;
  if (chosen.noisy) {
    options.aicc = true;
    if (options.turn_significance == 0.0)
      options.turn_significance = 3.0;
    if (options.width_factor == 1.5)
      options.width_factor = 2.5;
  }
  options.side_frames = options.side_frames || chosen.side_frames;
  options.local_threshold = options.local_threshold || chosen.local_threshold;
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
saveChoice (tiling::TilePlan& plan,
            const profiles::AutoConfiguration& chosen,
            const std::string& workdir)
{
  plan.settings["profile_auto"] = std::to_string (chosen.curve_fitting) + " " +
                                  std::to_string (chosen.noisy) + " " +
                                  std::to_string (chosen.local_threshold) + " " +
                                  std::to_string (chosen.side_frames) + " " +
                                  std::to_string (chosen.join_cylinders);
  return tiling::saveTilePlan (planFile (workdir), plan);
}

bool
loadChoice (const tiling::TilePlan& plan, profiles::AutoConfiguration& chosen)
{
  const auto it = plan.settings.find ("profile_auto");
  if (it == plan.settings.end())
    return false;
  std::istringstream in (it->second);
  int flags[5];
  for (int& f : flags)
    if (!(in >> f))
      return false;
  chosen.curve_fitting = flags[0];
  chosen.noisy = flags[1];
  chosen.local_threshold = flags[2];
  chosen.side_frames = flags[3];
  chosen.join_cylinders = flags[4];
  return true;
}

/** Parts of whole profiles of the frame's new width \a width (AutoProfileSegmentation's
 * noisy-scan width), their files written again and saved in the plan. \return false
 * (message printed) on error */
bool
replanParts (tiling::TilePlan& plan,
             const RunOptions& run,
             double width,
             ProfileFrame& frame,
             ProfileParts& parts)
{
  try {
    frame.width = width;
    InputPasses passes (plan);
    parts = ProfileParts();
    if (!planProfileParts (passes, frame, run.tile_size, kPointsPerPart, parts) ||
        !writeProfileParts (passes, frame, parts, run.workdir))
      return false;
    frame.saveTo (plan.settings);
    parts.saveTo (plan.settings);
    if (!tiling::saveTilePlan (planFile (run.workdir), plan))
      return false;
    std::cout << parts.size() << " parts of whole profiles of the noisy-scan width "
              << std::setprecision (6) << width << "\n";
    return true;
  }
  catch (const std::exception& e) {
    std::cerr << "\nError: " << e.what() << "\n";
    return false;
  }
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
  if (!options.valid())
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
  bool curves =
      !options.automatic() &&
      options.method == ProfileOptions::Segmentation::ProfileMethod::CurveFitting;
  bool join_cylinders = options.join_cylinders;
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
    profiles::AutoConfiguration chosen;
    if (leader) {
      ok = joinParts (tile_plan, parts, run.workdir, joined);
      if (ok) {
        chosen = chooseAutomatically (frame, joined, run.verbose);
        ok = saveChoice (tile_plan, chosen, run.workdir);
      }
    }
    ok = scheduler.allOk (ok) &&
         (leader || (tiling::loadTilePlan (planFile (run.workdir), tile_plan) &&
                     loadChoice (tile_plan, chosen)));
    ok = scheduler.allOk (ok);
    const bool had_gaps = pass.local_threshold;
    if (ok && (chosen.curve_fitting || (chosen.local_threshold && !had_gaps))) {
      applyChoice (chosen, options);
      curves = chosen.curve_fitting;
      join_cylinders = join_cylinders || chosen.join_cylinders;
      pass.first_automatic = false;
      pass.local_threshold = options.local_threshold;
      // The noisy-scan width: profiles of that width, in parts of their own.
      const double width =
          options.width > 0.0 ? options.width : options.width_factor * frame.spacing;
      const bool new_width = width != frame.width;
      if (new_width) {
        ok = scheduler.allOk (!leader ||
                              replanParts (tile_plan, run, width, frame, parts));
        ok = scheduler.allOk (
            ok &&
            (leader || (tiling::loadTilePlan (planFile (run.workdir), tile_plan) &&
                        frame.loadFrom (tile_plan.settings) &&
                        parts.loadFrom (tile_plan.settings, frame.normals.size()))));
      }
      if (ok && pass.local_threshold && (!had_gaps || new_width))
        gaps_pass();
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
    if (ok && join_cylinders) {
      StageTimer joining ("Joining cylinders");
      std::size_t cylinders = 0;
      ok = joinProfileCylinders (
          tile_plan, parts, options, run.workdir, run.threads, segments, cylinders);
      if (ok) {
        joining.done (tile_plan.getTotalPoints());
        std::cout << "  " << cylinders << " cylinders joined\n";
      }
    }
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
