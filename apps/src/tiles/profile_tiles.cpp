/*
 * pcl_ext_tiles segment_profiles: Sithole & Mapurisa's segmentation split by profiles,
 * as one command (under mpirun too) or in steps.
 */
#include "profile_tiles.h"
#include "profile_stages.h"
#include "tile_steps.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/output.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace pcl_ext {
namespace apps {
namespace {

/** The tool's own options beside the segmentation's. */
struct RunOptions {
  std::string workdir;
  unsigned int threads = 0;
  double tile_size = 0.0;
  bool keep_workdir = false;
  bool verbose = false;
};

/** The inputs, the output (\a whole_run; else -workdir is required) and the options of
 * a run or its plan; argv[1] is the method. \return -1 to go on, else the exit code */
int
parse (int argc,
       char** argv,
       bool whole_run,
       CommandLine& cl,
       ProfileOptions& options,
       RunOptions& run,
       ResultField& field,
       std::vector<std::string>& inputs,
       std::string& output,
       std::vector<std::string>& arguments)
{
  std::string method;
  cl.addPositional ("METHOD", method, "segment_profiles");
  cl.addPositionalList ("input", inputs, kInputFormats);
  if (whole_run)
    cl.addPositional ("output", output, kOutputFormats);
  options.addTo (cl);
  field.addTo (cl);
  cl.addOption ("workdir",
                run.workdir,
                whole_run ? "work folder of the parts (default: the output's name + "
                            ".tiles, removed at the end)"
                          : "work folder of the parts (required)");
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
  if (whole_run && !field.checkOutput (output))
    return 1;
  if (!whole_run && run.workdir.empty()) {
    std::cerr << "Error: -workdir is required.\n";
    return 1;
  }
  arguments =
      cl.getGivenOptions ({"workdir", "threads", "tile_size", "keep_workdir", "v"});
  return -1;
}

/** The passes from where \a run stands, each shared among the processes and reduced
 * by the first, then its merge into \a output; \a done counts the parts this process
 * ran. \return whether every process succeeded */
bool
runPasses (TileScheduler& scheduler,
           ProfileRun& run,
           const RunOptions& options,
           ResultField& field,
           const std::string& output,
           std::chrono::steady_clock::time_point start,
           std::size_t& done,
           std::uint32_t& segments)
{
  const bool leader = scheduler.getRank() == 0;
  bool ok = true;
  JoinedParts joined;
  while (ok && run.stage != ProfileStage::Merge) {
    const std::string stage = stageName (run.stage);
    std::size_t i, count = 0;
    scheduler.startPhase (run.parts.size());
    while (ok && scheduler.next (i)) {
      ok = runProfilePart (run, options.workdir, options.threads, i);
      if (!ok) {
        std::cerr << "Error: pass '" << stage << "' of part " << i
                  << " failed; the work folder " << options.workdir
                  << " is kept: run 'pcl_ext_tiles part " << i << " -workdir "
                  << options.workdir << "', then 'next', or 'resume'.\n";
        break;
      }
      ++count;
      ++done;
      const double seconds =
          std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
              .count();
      if (scheduler.getSize() == 1)
        std::cout << "  " << stage << ": " << count << " / " << run.parts.size()
                  << " parts, " << static_cast<long> (seconds) << " s\n";
    }
    ok = scheduler.allOk (ok);
    ok = scheduler.allOk (
        ok &&
        (!leader || advanceProfileRun (run, options.workdir, options.verbose, joined)));
    ok = scheduler.allOk (ok && (leader || loadProfileRun (options.workdir, run)));
  }
  if (leader && ok)
    ok = mergeProfileRun (
        run, options.workdir, options.threads, field, output, joined, segments);
  return scheduler.allOk (ok);
}

/** The summary line of every process. */
void
summarise (const TileScheduler& scheduler,
           bool ok,
           std::size_t done,
           std::uint32_t segments,
           std::uint64_t points,
           std::chrono::steady_clock::time_point start)
{
  const double seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  std::string what = std::to_string (done) + " part runs";
  if (scheduler.getRank() == 0 && ok)
    what += ", " + std::to_string (segments) + " segments";
  printRunSummary (scheduler, ok, what, points, seconds);
}

/** -workdir's value in argv, empty when not given. */
std::string
workdirArgument (int argc, char** argv)
{
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string (argv[i]) == "-workdir")
      return argv[i + 1];
  return "";
}
} // namespace

int
runProfileStep (int argc, char** argv, TileScheduler& scheduler)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string step = argv[1];
  const bool takes_output = step == "merge" || step == "resume";
  std::string argument;
  RunOptions options;
  CommandLine cl ("pcl_ext_tiles " + step,
                  "A step of a segment_profiles plan: 'part I' runs the plan's pass on "
                  "part I, 'next' reduces what every part saved and names the next "
                  "pass, 'merge output' writes the segments once no pass is left, "
                  "'resume output' runs the passes left and merges.");
  if (step == "part")
    cl.addPositional ("I", argument, "part index");
  else if (takes_output)
    cl.addPositional ("output", argument, kOutputFormats);
  cl.addOption ("workdir", options.workdir, "work folder of the plan (required)");
  cl.addOption ("threads", options.threads, "OpenMP threads (0: all cores)");
  cl.addSwitch ("v",
                options.verbose,
                "print the configuration -method auto chooses (next, resume)");
  if (const int code = cl.parse (argc - 1, argv + 1); code >= 0)
    return code;
  if (options.workdir.empty()) {
    std::cerr << "Error: -workdir is required.\n";
    return 1;
  }
  ProfileRun run;
  CommandLine plan_options ("pcl_ext_tiles", "The options of the plan.");
  ResultField field = segmentIdField();
  if (!loadProfileRun (options.workdir, plan_options, field, run) ||
      (takes_output && !field.checkOutput (argument)))
    return 1;
  std::size_t done = 0;
  std::uint32_t segments = 0;
  if (step == "resume") {
    if (scheduler.getRank() == 0)
      std::cout << "Resuming at pass '" << stageName (run.stage) << "' of "
                << run.parts.size() << " parts in " << options.workdir << "\n";
    const bool ok =
        runPasses (scheduler, run, options, field, argument, start, done, segments);
    summarise (scheduler, ok, done, segments, run.plan.getTotalPoints(), start);
    return ok ? 0 : 1;
  }
  if (step == "merge") {
    JoinedParts joined;
    return mergeProfileRun (
               run, options.workdir, options.threads, field, argument, joined, segments)
               ? 0
               : 1;
  }
  if (step == "next") {
    JoinedParts joined;
    if (!advanceProfileRun (run, options.workdir, options.verbose, joined))
      return 1;
    std::cout << "Next: " << stageName (run.stage);
    if (run.stage != ProfileStage::Merge)
      std::cout << " on " << run.parts.size() << " parts";
    std::cout << "\n";
    return 0;
  }
  char* end = nullptr;
  const unsigned long long part = std::strtoull (argument.c_str(), &end, 10);
  if (argument.empty() || *end != '\0' || part >= run.parts.size()) {
    std::cerr << "Error: part '" << argument << "' is not one of 0 .. "
              << run.parts.size() - 1 << ".\n";
    return 1;
  }
  return runProfilePart (run, options.workdir, options.threads, part) ? 0 : 1;
}

bool
isProfilePlan (int argc, char** argv)
{
  const std::string workdir = workdirArgument (argc, argv);
  std::ifstream plan (planPath (workdir));
  for (std::string line; !workdir.empty() && std::getline (plan, line);)
    if (line == "setting method segment_profiles")
      return true;
  return false;
}

int
planProfileTiles (int argc, char** argv)
{
  ProfileOptions options;
  RunOptions run;
  std::vector<std::string> inputs, arguments;
  std::string unused;
  CommandLine cl ("pcl_ext_tiles plan",
                  "segment_profiles in steps: the plan of the parts in -workdir, then "
                  "'part I' for every part and 'next', again until 'next' names the "
                  "merge, then 'merge output'.");
  ResultField field = segmentIdField(); // reads cl: declared after it
  if (const int code =
          parse (argc, argv, false, cl, options, run, field, inputs, unused, arguments);
      code >= 0)
    return code;
  if (!planProfileRun (inputs, options, run.tile_size, arguments, run.workdir))
    return 1;
  ProfileRun loaded;
  if (!loadProfileRun (run.workdir, loaded))
    return 1;
  std::cout << "Next: " << stageName (loaded.stage) << " on " << loaded.parts.size()
            << " parts\n";
  return 0;
}

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
          parse (argc, argv, true, cl, options, run, field, inputs, output, arguments);
      code >= 0)
    return code;
  const bool own_workdir = run.workdir.empty();
  if (own_workdir)
    run.workdir = output + ".tiles";
  // Rank 0 plans; every process follows the plan's passes.
  bool ok = !leader ||
            planProfileRun (inputs, options, run.tile_size, arguments, run.workdir);
  ProfileRun state;
  if (!scheduler.allOk (ok) || !scheduler.allOk (loadProfileRun (run.workdir, state)))
    return 1;
  std::size_t done = 0;
  std::uint32_t segments = 0;
  ok = runPasses (scheduler, state, run, field, output, start, done, segments);
  summarise (scheduler, ok, done, segments, state.plan.getTotalPoints(), start);
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
