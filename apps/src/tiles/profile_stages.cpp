/*
 * pcl_ext_tiles segment_profiles: the passes of a run over its parts, kept in its plan.
 */
#include "profile_stages.h"
#include "input_fields.h"
#include "merge_output.h"
#include "profile_curve_steps.h"
#include "profile_cylinder_join.h"
#include "tile_steps.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/tiling/tile_results.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
/** At most this many points in a part (unless one profile holds more): with the
 * segmentation's arrays a process stays well under 2 GB. */
constexpr std::uint64_t kPointsPerPart = 4000000;
constexpr const char* kMethod = "segment_profiles";
constexpr ProfileStage kStages[] = {ProfileStage::LocalGaps,
                                    ProfileStage::Chains,
                                    ProfileStage::CurveScores,
                                    ProfileStage::CurveJoins,
                                    ProfileStage::Merge};
// The plan's settings of a run beside its frame and parts.
constexpr const char* kStageSetting = "profile_stage";
constexpr const char* kPartCountSetting = "profile_part_count";
constexpr const char* kThicknessSetting = "profile_part_thickness";
constexpr const char* kChoiceSetting = "profile_auto";
constexpr const char* kMeanGapsSetting = "profile_mean_gaps";
constexpr const char* kTolerancesSetting = "profile_junction_tolerances";
/** The stage while the parts are written again for -method auto's new width. */
constexpr const char* kReplanning = "replanning";

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

std::string
choiceText (const profiles::AutoConfiguration& chosen)
{
  return std::to_string (chosen.curve_fitting) + " " + std::to_string (chosen.noisy) +
         " " + std::to_string (chosen.local_threshold) + " " +
         std::to_string (chosen.side_frames) + " " +
         std::to_string (chosen.join_cylinders);
}

bool
parseChoice (const std::string& text, profiles::AutoConfiguration& chosen)
{
  std::istringstream in (text);
  int flags[5];
  for (int& f : flags)
    if (!(in >> f) || (f != 0 && f != 1))
      return false;
  chosen.curve_fitting = flags[0];
  chosen.noisy = flags[1];
  chosen.local_threshold = flags[2];
  chosen.side_frames = flags[3];
  chosen.join_cylinders = flags[4];
  return true;
}

/** Whether AutoProfileSegmentation runs again after choosing \a chosen for \a options
 * (the options given): for curve fitting, or for local thresholds not given. */
bool
runsAgain (const profiles::AutoConfiguration& chosen, const ProfileOptions& options)
{
  return chosen.curve_fitting || (chosen.local_threshold && !options.local_threshold);
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

/** The first pass of a segmentation with \a local_threshold and \a curves. */
ProfileStage
firstPass (bool local_threshold, bool curves)
{
  if (local_threshold)
    return ProfileStage::LocalGaps;
  return curves ? ProfileStage::CurveScores : ProfileStage::Chains;
}

/** \a parts of whole profiles of \a frame (its width) planned and written, both saved
 * in \a plan's settings. \return false (message printed) on error */
bool
writeParts (tiling::TilePlan& plan,
            const ProfileFrame& frame,
            double thickness,
            const std::string& workdir,
            ProfileParts& parts)
{
  InputPasses passes (plan);
  parts = ProfileParts();
  if (!planProfileParts (passes, frame, thickness, kPointsPerPart, parts) ||
      !writeProfileParts (passes, frame, parts, workdir))
    return false;
  frame.saveTo (plan.settings);
  parts.saveTo (plan.settings);
  plan.settings[kPartCountSetting] = std::to_string (parts.size());
  return true;
}

/** Name \a next in the plan, with the files its pass writes into made, and save it.
 */
bool
startStage (tiling::TilePlan& plan,
            const ProfileParts& parts,
            ProfileStage next,
            const std::string& workdir)
{
  if (next == ProfileStage::LocalGaps &&
      !createGapFiles (workdir, parts.firsts.size(), plan.getTotalPoints()))
    return false;
  plan.settings[kStageSetting] = stageName (next);
  return tiling::saveTilePlan (planPath (workdir), plan);
}

/** The run's state from its loaded plan and options. */
bool
deriveRun (ProfileRun& run)
{
  const auto& settings = run.plan.settings;
  const auto setting = [&settings] (const char* key) {
    const auto it = settings.find (key);
    return it == settings.end() ? std::string() : it->second;
  };
  const std::string stage = setting (kStageSetting);
  bool known = false;
  for (const ProfileStage s : kStages)
    if (stage == stageName (s)) {
      run.stage = s;
      known = true;
    }
  if (!known || !run.frame.loadFrom (settings) ||
      !run.parts.loadFrom (settings, run.frame.normals.size()))
    return false;
  run.join_cylinders = run.options.join_cylinders;
  run.curves =
      !run.options.automatic() &&
      run.options.method == ProfileOptions::Segmentation::ProfileMethod::CurveFitting;
  run.pass.first_automatic = run.options.automatic();
  if (settings.count (kChoiceSetting)) {
    profiles::AutoConfiguration chosen;
    if (!parseChoice (setting (kChoiceSetting), chosen))
      return false;
    run.pass.first_automatic = false;
    run.join_cylinders = run.join_cylinders || chosen.join_cylinders;
    if (runsAgain (chosen, run.options)) {
      applyChoice (chosen, run.options);
      run.curves = chosen.curve_fitting;
    }
  }
  run.pass.local_threshold = run.options.local_threshold;
  // Absent until their pass has run.
  if ((settings.count (kMeanGapsSetting) &&
       !parseValues (settings, kMeanGapsSetting, run.pass.mean_gaps)) ||
      (settings.count (kTolerancesSetting) &&
       !parseValues (settings, kTolerancesSetting, run.junction_tolerances)))
    return false;
  const std::size_t stacks = run.frame.normals.size();
  return (run.pass.mean_gaps.empty() || run.pass.mean_gaps.size() == stacks) &&
         (run.junction_tolerances.empty() ||
          run.junction_tolerances.size() == stacks) &&
         // A pass that needs a reduction before it has it.
         !(run.stage == ProfileStage::CurveJoins && run.junction_tolerances.empty()) &&
         !(run.pass.local_threshold && run.pass.mean_gaps.empty() &&
           run.stage != ProfileStage::LocalGaps);
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

/** After the segmentation's last pass: -method auto's choice made (once), and the pass
 * that starts its second run, or the merge. */
bool
afterSegmentation (ProfileRun& run,
                   const std::string& workdir,
                   bool verbose,
                   JoinedParts& joined,
                   ProfileStage& next)
{
  next = ProfileStage::Merge;
  auto& settings = run.plan.settings;
  if (!run.options.automatic() || settings.count (kChoiceSetting))
    return true;
  if (!joinParts (run.plan, run.parts, workdir, joined))
    return false;
  const profiles::AutoConfiguration chosen =
      chooseAutomatically (run.frame, joined, verbose);
  settings[kChoiceSetting] = choiceText (chosen);
  if (!runsAgain (chosen, run.options))
    return true;
  // The second run: its segments replace the first's.
  joined = JoinedParts();
  const bool had_gaps = run.options.local_threshold;
  ProfileOptions options = run.options;
  applyChoice (chosen, options);
  // The noisy-scan width: profiles of that width, in parts of their own.
  const double width =
      options.width > 0.0 ? options.width : options.width_factor * run.frame.spacing;
  const bool new_width = width != run.frame.width;
  if (new_width) {
    // Marked, so that a run that dies while the part files change is not resumed on
    // files its plan does not describe.
    settings[kStageSetting] = kReplanning;
    if (!tiling::saveTilePlan (planPath (workdir), run.plan))
      return false;
    try {
      run.frame.width = width;
      std::vector<double> thickness;
      if (!parseValues (settings, kThicknessSetting, thickness) ||
          thickness.size() != 1) {
        std::cerr << "Error: the plan in " << workdir << " has no part thickness.\n";
        return false;
      }
      if (!writeParts (run.plan, run.frame, thickness.front(), workdir, run.parts))
        return false;
    }
    catch (const std::exception& e) {
      std::cerr << "\nError: " << e.what() << "\n";
      return false;
    }
    settings.erase (kMeanGapsSetting);
    std::cout << run.parts.size() << " parts of whole profiles of the noisy-scan width "
              << std::setprecision (6) << width << "\n";
  }
  next =
      options.local_threshold && (!had_gaps || new_width)
          ? ProfileStage::LocalGaps
          : (chosen.curve_fitting ? ProfileStage::CurveScores : ProfileStage::Chains);
  return true;
}
} // namespace

const char*
stageName (ProfileStage stage)
{
  switch (stage) {
  case ProfileStage::LocalGaps:
    return "local_gaps";
  case ProfileStage::Chains:
    return "chains";
  case ProfileStage::CurveScores:
    return "curve_scores";
  case ProfileStage::CurveJoins:
    return "curve_joins";
  case ProfileStage::Merge:
    break;
  }
  return "merge";
}

bool
planProfileRun (const std::vector<std::string>& inputs,
                const ProfileOptions& options,
                double thickness,
                const std::vector<std::string>& arguments,
                const std::string& workdir)
{
  if (!clearWorkdir (workdir))
    return false;
  StageTimer timer ("Planning");
  tiling::TilePlan plan;
  try {
    // The grid only lays the files of an output named with '#'.
    if (!tiling::planTiles (inputs, 1e9, 0.0, plan))
      return false;
    const double tile_size =
        thickness > 0.0 ? thickness : tiling::fitTileSize (plan, kPointsPerPart / 2);
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
    plan.settings[kThicknessSetting] = joinValues (&thickness, 1, 17);
    ProfileParts parts;
    if (!writeParts (plan, frame, thickness, workdir, parts))
      return false;
    plan.settings["method"] = kMethod;
    plan.settings["arguments"] = joinArguments (arguments);
    const bool curves =
        !options.automatic() &&
        options.method == ProfileOptions::Segmentation::ProfileMethod::CurveFitting;
    if (!startStage (plan, parts, firstPass (options.local_threshold, curves), workdir))
      return false;
    timer.done (plan.getTotalPoints());
    std::cout << parts.size() << " parts of whole profiles (" << normals.size()
              << " stacks, width " << std::setprecision (6) << frame.width << ") in "
              << workdir << "\n";
  }
  catch (const std::exception& e) {
    std::cerr << "\nError: " << e.what() << "\n";
    return false;
  }
  return true;
}

bool
loadProfileRun (const std::string& workdir,
                CommandLine& cl,
                ResultField& field,
                ProfileRun& run)
{
  run = ProfileRun();
  if (!tiling::loadTilePlan (planPath (workdir), run.plan))
    return false;
  if (run.plan.settings["method"] != kMethod) {
    std::cerr << "Error: the plan in " << workdir << " is not segment_profiles'.\n";
    return false;
  }
  if (run.plan.settings[kStageSetting] == kReplanning) {
    std::cerr << "Error: the run in " << workdir
              << " stopped while its parts were written again for -method auto's "
                 "width: plan it again.\n";
    return false;
  }
  run.options.addTo (cl);
  field.addTo (cl);
  std::vector<std::string> args = splitArguments (run.plan.settings["arguments"]);
  args.insert (args.begin(), "pcl_ext_tiles");
  std::vector<const char*> argv;
  for (const auto& a : args)
    argv.push_back (a.c_str());
  if (cl.parse (static_cast<int> (argv.size()), argv.data()) >= 0 ||
      !run.options.valid() || !deriveRun (run)) {
    std::cerr << "Error: the plan in " << workdir << " is not valid.\n";
    return false;
  }
  return true;
}

bool
loadProfileRun (const std::string& workdir, ProfileRun& run)
{
  CommandLine cl ("pcl_ext_tiles", "The options of the plan.");
  ResultField field = segmentIdField();
  return loadProfileRun (workdir, cl, field, run);
}

bool
runProfilePart (const ProfileRun& run,
                const std::string& workdir,
                unsigned int threads,
                std::size_t i)
{
  if (i >= run.parts.size()) {
    std::cerr << "Error: part " << i << " is not one of the plan's " << run.parts.size()
              << ".\n";
    return false;
  }
  switch (run.stage) {
  case ProfileStage::LocalGaps:
    return computePartGaps (
        run.frame, run.parts, run.options, run.pass, workdir, threads, i);
  case ProfileStage::Chains:
    return segmentPart (
        run.frame, run.parts, run.options, run.pass, workdir, threads, i);
  case ProfileStage::CurveScores:
    return scorePartCurves (
        run.frame, run.parts, run.options, run.pass, workdir, threads, i);
  case ProfileStage::CurveJoins:
    return joinPartCurves (run.frame,
                           run.parts,
                           run.options,
                           run.pass,
                           run.junction_tolerances,
                           workdir,
                           threads,
                           i);
  case ProfileStage::Merge:
    break;
  }
  std::cerr << "Error: the parts have run every pass: the merge is next.\n";
  return false;
}

bool
advanceProfileRun (ProfileRun& run,
                   const std::string& workdir,
                   bool verbose,
                   JoinedParts& joined)
{
  auto& settings = run.plan.settings;
  ProfileStage next = ProfileStage::Merge;
  switch (run.stage) {
  case ProfileStage::LocalGaps:
    if (!reduceGaps (run.plan, run.parts, workdir, run.pass.mean_gaps))
      return false;
    settings[kMeanGapsSetting] =
        joinValues (run.pass.mean_gaps.data(), run.pass.mean_gaps.size(), 17);
    next = run.curves ? ProfileStage::CurveScores : ProfileStage::Chains;
    break;
  case ProfileStage::CurveScores:
    if (!findCurveEnds (run.plan,
                        run.frame,
                        run.parts,
                        run.options,
                        workdir,
                        run.junction_tolerances))
      return false;
    settings[kTolerancesSetting] =
        joinValues (run.junction_tolerances.data(), run.junction_tolerances.size(), 17);
    next = ProfileStage::CurveJoins;
    break;
  case ProfileStage::Chains:
  case ProfileStage::CurveJoins:
    if (!afterSegmentation (run, workdir, verbose, joined, next))
      return false;
    break;
  case ProfileStage::Merge:
    std::cerr << "Error: the parts have run every pass: the merge is next.\n";
    return false;
  }
  // The state as any process reads it from the plan.
  return startStage (run.plan, run.parts, next, workdir) &&
         loadProfileRun (workdir, run);
}

bool
mergeProfileRun (const ProfileRun& run,
                 const std::string& workdir,
                 unsigned int threads,
                 ResultField& field,
                 const std::string& output,
                 JoinedParts& joined,
                 std::uint32_t& segments)
{
  if (run.stage != ProfileStage::Merge) {
    std::cerr << "Error: the parts have not run every pass: the plan in " << workdir
              << " is at '" << stageName (run.stage)
              << "' (run 'pcl_ext_tiles part I' for every part, then 'next').\n";
    return false;
  }
  StageTimer timer ("Joining the parts");
  if (!(joined.sets.size() > 0 ||
        (run.curves ? labelCurveSegments (run.plan, run.parts, workdir, joined)
                    : joinParts (run.plan, run.parts, workdir, joined))) ||
      !saveSegments (
          workdir, static_cast<std::uint64_t> (run.options.min_size), joined, segments))
    return false;
  timer.done (run.plan.getTotalPoints());
  joined = JoinedParts();
  if (run.join_cylinders) {
    StageTimer joining ("Joining cylinders");
    std::size_t cylinders = 0;
    if (!joinProfileCylinders (
            run.plan, run.parts, run.options, workdir, threads, segments, cylinders))
      return false;
    joining.done (run.plan.getTotalPoints());
    std::cout << "  " << cylinders << " cylinders joined\n";
  }
  MergeReading reading;
  reading.segments = true;
  return writeMergedOutput (run.plan, field, workdir, output, reading);
}
} // namespace apps
} // namespace pcl_ext
