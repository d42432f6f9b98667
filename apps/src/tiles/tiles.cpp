/*
 * pcl_ext_tiles: a method over a cloud larger than memory, tile by tile with halos,
 * with the result of the method's own tool on the whole cloud.
 */
#include "profile_tiles.h"
#include "second_pass_steps.h"
#include "tile_scheduler.h"
#include "tile_steps.h"

#include <pcl_ext/tiling/tile_results.h>

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace {
using pcl_ext::apps::CommandLine;

constexpr const char* kDescription =
    "Runs a method over clouds of any size tile by tile: each tile reads only its "
    "points and a halo around them, and the output is what the method's own tool "
    "gives on the whole cloud (the same classes point by point; the same segments "
    "with the same ids). Methods: classify_variance and segment_variance (the options "
    "of pcl_ext_classify_variance and pcl_ext_segment_variance), crf_classify (-model "
    "model.txt of pcl_ext_crf_train, a model on x y z; a tile widens its margin "
    "until the super-voxels its points lie in are the whole cloud's, and at least "
    "99 % of the points get pcl_ext_crf_classify's class), segment_profiles (the "
    "options of pcl_ext_segment_profiles; split by profiles rather than by tiles, in "
    "steps 'plan segment_profiles input... -workdir D', then 'part I -workdir D' for "
    "every part and 'next -workdir D', again until 'next' names the merge). An output "
    "named "
    "with a '#' (out_#.las) gives one LAS file per tile, '#' its number, and an index "
    "of the files with their boxes (out_index.csv). Steps for scheduler "
    "array jobs: 'plan METHOD input... -workdir D', then 'estimate I -workdir D', "
    "'tile I -workdir D', (segment_variance -reintegrate: section 4, a second pass "
    "over the tiles once their segments are joined) 'refine I -workdir D' and "
    "(segment_variance's new segments among the points left out, unless "
    "-no_leftovers) 'grow I -workdir D' for every tile I, "
    "each step for all tiles before the next, then 'merge output -workdir D'; "
    "'resume output -workdir D' runs what has not run or did not finish (a process "
    "that died), then merges.";

/** The tool's own options, kept out of the method's. */
struct TileOptions {
  std::string method;
  double tile_size = 0.0;
  double halo = -1.0;
  std::string workdir;
  unsigned int threads = 0;
  bool keep_workdir = false;

  void
  addTo (CommandLine& cl, bool planning)
  {
    cl.addOption (
        "workdir",
        workdir,
        "work folder of the tiles (default: the output's name + .tiles, removed "
        "at the end)");
    cl.addOption ("threads", threads, "OpenMP threads per process (0: all cores)");
    if (!planning)
      return;
    cl.addOption ("tile_size",
                  tile_size,
                  "tile side in metres (0: the largest with at most 2.5M points in the "
                  "densest tile)");
    cl.addOption (
        "halo",
        halo,
        "halo around each tile in metres (-1: from the inputs' density; a tile "
        "widens itself where a neighbourhood reaches beyond it)");
    cl.addSwitch ("keep_workdir", keep_workdir, "keep the work folder");
  }

  static std::vector<std::string>
  names ()
  {
    return {"workdir", "threads", "tile_size", "halo", "keep_workdir"};
  }
};

/** The method given as the first argument with its options, the tool's options and the
 * positionals of a plan or a whole run. */
int
parsePlan (int argc,
           char** argv,
           bool whole_run,
           CommandLine& cl,
           std::unique_ptr<pcl_ext::apps::TileMethod>& method,
           TileOptions& options,
           std::vector<std::string>& inputs,
           std::string& output,
           std::vector<std::string>& method_arguments,
           pcl_ext::apps::ResultField& field)
{
  cl.addPositional ("METHOD", options.method, pcl_ext::apps::kTileMethods);
  cl.addPositionalList ("input", inputs, pcl_ext::apps::kInputFormats);
  if (whole_run)
    cl.addPositional ("output", output, pcl_ext::apps::kOutputFormats);
  // The method's options can only be declared once it is known.
  const int first = whole_run ? 1 : 2;
  method = pcl_ext::apps::makeTileMethod (argc > first ? argv[first] : "");
  if (method) {
    method->addOptions (cl);
    field = method->makeResultField();
    field.addTo (cl);
  }
  options.addTo (cl, true);
  if (const int code = cl.parse (argc - first + 1, argv + first - 1); code >= 0)
    return code;
  if (!method) {
    std::cerr << "Error: unknown method '" << options.method << "' ("
              << pcl_ext::apps::kTileMethods << ", segment_profiles).\n";
    return 1;
  }
  if (!method->checkOptions (cl, true))
    return 1;
  if (!method->getExtraFieldName().empty() &&
      method->getExtraFieldName() == field.name()) {
    std::cerr << "Error: -probability_field must differ from the result's field '"
              << field.name() << "'.\n";
    return 1;
  }
  if (!(options.tile_size >= 0.0) || !(options.halo >= 0.0 || options.halo == -1.0)) {
    std::cerr << "Error: -tile_size must be >= 0 and -halo >= 0 (or -1).\n";
    return 1;
  }
  method_arguments = cl.getGivenOptions (TileOptions::names());
  return -1;
}

std::vector<std::size_t>
allTiles (const pcl_ext::tiling::TilePlan& plan)
{
  std::vector<std::size_t> tiles (plan.getGrid().size());
  for (std::size_t t = 0; t < tiles.size(); ++t)
    tiles[t] = t;
  return tiles;
}

/** The estimates (when the method needs them and the plan has none yet), the tiles
 * \a to_run shared among the processes, then the merge into \a output by the first
 * process; a summary line per process. \return whether every process succeeded */
bool
runTiles (pcl_ext::apps::TileScheduler& scheduler,
          pcl_ext::tiling::TilePlan& plan,
          pcl_ext::apps::TileMethod& method,
          pcl_ext::apps::ResultField& field,
          const TileOptions& options,
          const std::string& output,
          const std::vector<std::size_t>& to_run,
          std::chrono::steady_clock::time_point start)
{
  const bool leader = scheduler.getRank() == 0;
  const std::size_t tiles = plan.getGrid().size();
  std::size_t phase_index, done = 0;
  bool ok = true;
  if (method.needsEstimate() && !plan.settings.count ("estimated")) {
    scheduler.startPhase (tiles);
    while (ok && scheduler.next (phase_index))
      ok = pcl_ext::apps::estimateStep (
          plan, method, options.workdir, phase_index, options.threads);
    ok = scheduler.allOk (ok);
    ok = scheduler.allOk (
        ok && (!leader || pcl_ext::apps::reduceStep (plan, method, options.workdir)));
    ok = ok && (leader || pcl_ext::tiling::loadTilePlan (
                              pcl_ext::apps::planPath (options.workdir), plan));
  }
  scheduler.startPhase (to_run.size());
  while (ok && scheduler.next (phase_index)) {
    const std::size_t tile = to_run[phase_index];
    ok = pcl_ext::apps::tileStep (plan, method, options.workdir, tile, options.threads);
    if (!ok) {
      std::cerr << "Error: tile " << tile << " failed; the work folder "
                << options.workdir << " is kept: run 'pcl_ext_tiles tile " << tile
                << " -workdir " << options.workdir << "', then 'merge', or 'resume'.\n";
      break;
    }
    ++done;
    const double seconds =
        std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
            .count();
    if (scheduler.getSize() == 1)
      std::cout << "  " << done << " / " << to_run.size() << " tiles, ETA "
                << static_cast<long> (seconds / done * (to_run.size() - done))
                << " s\n";
  }
  ok = scheduler.allOk (ok);
  // The passes after the first: the segments joined once, then the tiles that have
  // not run the pass (every process lists the same ones before any runs one).
  const auto later_pass = [&] (const std::string& pass, const auto& step) {
    ok = scheduler.allOk (
        ok && (!leader || pcl_ext::apps::joinStep (plan, method, options.workdir)));
    const auto to_run_pass =
        ok ? pcl_ext::tiling::findTilesNotDone (options.workdir, tiles, pass)
           : std::vector<std::size_t>();
    ok = scheduler.allOk (ok);
    scheduler.startPhase (to_run_pass.size());
    while (ok && scheduler.next (phase_index)) {
      const std::size_t tile = to_run_pass[phase_index];
      ok = step (plan, method, options.workdir, tile, options.threads);
      if (!ok)
        std::cerr << "Error: pass '" << pcl_ext::apps::stepOfPass (pass) << "' of tile "
                  << tile << " failed; the work folder " << options.workdir
                  << " is kept: run 'pcl_ext_tiles " << pcl_ext::apps::stepOfPass (pass)
                  << " " << tile << " -workdir " << options.workdir
                  << "', then 'merge', or 'resume'.\n";
    }
    ok = scheduler.allOk (ok);
  };
  if (ok && method.needsRefine())
    later_pass (pcl_ext::apps::kRefined, pcl_ext::apps::refineStep);
  if (ok && method.needsGrow())
    later_pass (pcl_ext::apps::kGrown, pcl_ext::apps::growStep);
  if (leader && ok)
    ok = pcl_ext::apps::mergeStep (plan, method, field, options.workdir, output);
  ok = scheduler.allOk (ok);
  const double seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  pcl_ext::apps::printRunSummary (scheduler,
                                  ok,
                                  std::to_string (done) + " of " +
                                      std::to_string (to_run.size()) + " tiles",
                                  plan.getTotalPoints(),
                                  seconds);
  return ok;
}

int
runAll (int argc, char** argv, pcl_ext::apps::TileScheduler& scheduler)
{
  const auto start = std::chrono::steady_clock::now();
  const bool leader = scheduler.getRank() == 0;
  std::unique_ptr<pcl_ext::apps::TileMethod> method;
  TileOptions options;
  std::vector<std::string> inputs, arguments;
  std::string output;
  pcl_ext::apps::ResultField field ("", "", "");
  CommandLine cl ("pcl_ext_tiles", kDescription); // outlives field, which reads it
  if (const int code = parsePlan (
          argc, argv, true, cl, method, options, inputs, output, arguments, field);
      code >= 0)
    return code;
  if (!field.checkOutput (output))
    return 1;
  const bool own_workdir = options.workdir.empty();
  if (own_workdir)
    options.workdir = output + ".tiles";
  pcl_ext::tiling::TilePlan plan;
  // Rank 0 plans; the others read its plan.
  bool ok = !leader || pcl_ext::apps::planStep (options.method,
                                                *method,
                                                arguments,
                                                inputs,
                                                options.tile_size,
                                                options.halo,
                                                options.workdir,
                                                plan);
  ok = scheduler.allOk (ok) &&
       (leader || pcl_ext::tiling::loadTilePlan (
                      pcl_ext::apps::planPath (options.workdir), plan));
  if (!scheduler.allOk (ok))
    return 1;
  const auto all = allTiles (plan);
  const bool done =
      runTiles (scheduler, plan, *method, field, options, output, all, start);
  if (leader && done && own_workdir && !options.keep_workdir) {
    std::error_code ignored;
    std::filesystem::remove_all (options.workdir, ignored);
  }
  return done ? 0 : 1;
}

/** The positional \a name (into \a argument) and -workdir / -threads of a step that
 * works in an existing work folder, then the folder's plan and method. \return -1 to go
 * on, else the exit code (message printed) */
int
parseWorkdirStep (int argc,
                  char** argv,
                  const std::string& name,
                  const std::string& description,
                  CommandLine& cl,
                  CommandLine& plan_options,
                  std::string& argument,
                  TileOptions& options,
                  pcl_ext::tiling::TilePlan& plan,
                  std::unique_ptr<pcl_ext::apps::TileMethod>& method,
                  pcl_ext::apps::ResultField& field)
{
  cl.addPositional (name, argument, description);
  options.addTo (cl, false);
  if (const int code = cl.parse (argc - 1, argv + 1); code >= 0)
    return code;
  if (options.workdir.empty()) {
    std::cerr << "Error: -workdir is required.\n";
    return 1;
  }
  return pcl_ext::apps::loadPlanAndMethod (
             options.workdir, plan, method, plan_options, field)
             ? -1
             : 1;
}

/** `resume output -workdir D`: the tiles of D that have not run or did not finish, then
 * the merge; under mpirun too. */
int
runResume (int argc, char** argv, pcl_ext::apps::TileScheduler& scheduler)
{
  const auto start = std::chrono::steady_clock::now();
  std::string output;
  TileOptions options;
  CommandLine cl ("pcl_ext_tiles resume", kDescription);
  CommandLine plan_options ("pcl_ext_tiles", "The options of the plan.");
  pcl_ext::tiling::TilePlan plan;
  std::unique_ptr<pcl_ext::apps::TileMethod> method;
  pcl_ext::apps::ResultField field ("", "", "");
  const int code = parseWorkdirStep (argc,
                                     argv,
                                     "output",
                                     pcl_ext::apps::kOutputFormats,
                                     cl,
                                     plan_options,
                                     output,
                                     options,
                                     plan,
                                     method,
                                     field);
  // Every process parses the same arguments and folder: all return here or none.
  if (code >= 0)
    return code;
  bool ok = field.checkOutput (output);
  // Every process lists the same tiles: all list before any runs one.
  const auto missing =
      ok ? pcl_ext::tiling::findTilesNotDone (options.workdir, plan.getGrid().size())
         : std::vector<std::size_t>();
  if (!scheduler.allOk (ok))
    return 1;
  if (scheduler.getRank() == 0)
    std::cout << missing.size() << " of " << plan.getGrid().size()
              << " tiles to run in " << options.workdir << "\n";
  return runTiles (scheduler, plan, *method, field, options, output, missing, start)
             ? 0
             : 1;
}

/** `estimate I`, `tile I`, `refine I`, `grow I` or `merge output`, each with
 * -workdir. */
int
runStep (int argc, char** argv)
{
  const std::string step = argv[1];
  std::string argument;
  TileOptions options;
  CommandLine cl ("pcl_ext_tiles " + step, kDescription);
  CommandLine plan_options ("pcl_ext_tiles", "The options of the plan.");
  pcl_ext::tiling::TilePlan plan;
  std::unique_ptr<pcl_ext::apps::TileMethod> method;
  pcl_ext::apps::ResultField field ("", "", "");
  if (const int code = parseWorkdirStep (argc,
                                         argv,
                                         step == "merge" ? "output" : "I",
                                         "output file or tile index",
                                         cl,
                                         plan_options,
                                         argument,
                                         options,
                                         plan,
                                         method,
                                         field);
      code >= 0)
    return code;
  if (step == "merge")
    return field.checkOutput (argument) &&
                   pcl_ext::apps::mergeStep (
                       plan, *method, field, options.workdir, argument)
               ? 0
               : 1;
  char* end = nullptr;
  const unsigned long long tile = std::strtoull (argument.c_str(), &end, 10);
  if (argument.empty() || *end != '\0' || tile >= plan.getGrid().size()) {
    std::cerr << "Error: tile '" << argument << "' is not one of 0 .. "
              << plan.getGrid().size() - 1 << ".\n";
    return 1;
  }
  if (step == "estimate")
    return pcl_ext::apps::estimateStep (
               plan, *method, options.workdir, tile, options.threads)
               ? 0
               : 1;
  if (step == "refine")
    return pcl_ext::apps::refineStep (
               plan, *method, options.workdir, tile, options.threads)
               ? 0
               : 1;
  if (step == "grow")
    return pcl_ext::apps::growStep (
               plan, *method, options.workdir, tile, options.threads)
               ? 0
               : 1;
  return pcl_ext::apps::reduceStep (plan, *method, options.workdir) &&
                 pcl_ext::apps::tileStep (
                     plan, *method, options.workdir, tile, options.threads)
             ? 0
             : 1;
}
} // namespace

int
main (int argc, char** argv)
{
  // Under mpirun every rank runs main; the steps are for one process each.
  const auto scheduler = pcl_ext::apps::makeTileScheduler (argc, argv);
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "part" || first == "next" ||
      ((first == "merge" || first == "resume") &&
       pcl_ext::apps::isProfilePlan (argc, argv)))
    return pcl_ext::apps::runProfileStep (argc, argv, *scheduler);
  if (first == "estimate" || first == "tile" || first == "refine" || first == "grow" ||
      first == "merge")
    return runStep (argc, argv);
  if (first == "resume")
    return runResume (argc, argv, *scheduler);
  if (first == "segment_profiles")
    return pcl_ext::apps::runProfileTiles (argc, argv, *scheduler);
  if (first == "plan" && argc > 2 && std::string (argv[2]) == "segment_profiles")
    return pcl_ext::apps::planProfileTiles (argc - 1, argv + 1);
  if (first == "plan") {
    std::unique_ptr<pcl_ext::apps::TileMethod> method;
    TileOptions options;
    std::vector<std::string> inputs, arguments;
    std::string unused;
    pcl_ext::apps::ResultField field ("", "", "");
    CommandLine cl ("pcl_ext_tiles", kDescription);
    if (const int code = parsePlan (
            argc, argv, false, cl, method, options, inputs, unused, arguments, field);
        code >= 0)
      return code;
    if (options.workdir.empty()) {
      std::cerr << "Error: -workdir is required.\n";
      return 1;
    }
    pcl_ext::tiling::TilePlan plan;
    return pcl_ext::apps::planStep (argv[2],
                                    *method,
                                    arguments,
                                    inputs,
                                    options.tile_size,
                                    options.halo,
                                    options.workdir,
                                    plan)
               ? 0
               : 1;
  }
  return runAll (argc, argv, *scheduler);
}
