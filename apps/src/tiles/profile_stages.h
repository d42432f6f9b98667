/*
 * pcl_ext_tiles segment_profiles: the passes of a run over its parts, where the run
 * stands kept in its plan, so that one command, MPI ranks and scheduler steps follow
 * the same course.
 */
#pragma once

#include "../profiles/profile_options.h"
#include "profile_frame.h"
#include "profile_part_steps.h"
#include "profile_parts.h"

#include <pcl_ext/apps/output.h>
#include <pcl_ext/tiling/tile_plan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The passes over the parts. Each runs on every part; then one process reduces
 * what the parts saved and names the next pass (advanceProfileRun): the local gaps'
 * means, the curve ends, -method auto's choice. */
enum class ProfileStage {
  LocalGaps,   ///< computePartGaps
  Chains,      ///< segmentPart
  CurveScores, ///< scorePartCurves
  CurveJoins,  ///< joinPartCurves
  Merge        ///< no pass left: the merge
};

/** \brief The stage's name in the plan and in messages. */
const char*
stageName (ProfileStage stage);

/** \brief A run as its plan says: the options given, with -method auto's choice applied
 * once it has made one that runs again; the frame, the parts and the pass to run. */
struct ProfileRun {
  tiling::TilePlan plan;
  ProfileOptions options;
  ProfileFrame frame;
  ProfileParts parts;
  PartPass pass;
  bool curves = false;         ///< the segments come from curve fitting's graph
  bool join_cylinders = false; ///< CylinderSegmentJoin after the merge
  std::vector<double> junction_tolerances; ///< curve fitting's, after CurveScores
  ProfileStage stage = ProfileStage::Merge;
};

/** \brief The plan of a run: \a workdir cleared of an earlier run, the whole cloud's
 * frame estimated, the parts of whole profiles (at most \a thickness metres, 0: by
 * their points) written and the first pass named. \a arguments are the options given
 * (as CommandLine::getGivenOptions lists them). \return false (message printed) on
 * error */
bool
planProfileRun (const std::vector<std::string>& inputs,
                const ProfileOptions& options,
                double thickness,
                const std::vector<std::string>& arguments,
                const std::string& workdir);

/** \brief \a run from the plan in \a workdir, the options parsed from the plan's
 * arguments on \a cl (with \a field's -output_field). \return false (message printed)
 * when the plan is missing, not segment_profiles' or broken */
bool
loadProfileRun (const std::string& workdir,
                CommandLine& cl,
                ResultField& field,
                ProfileRun& run);

/** \brief loadProfileRun for a process that does not write the output. */
bool
loadProfileRun (const std::string& workdir, ProfileRun& run);

/** \brief Part \a i's share of the run's pass. \return false (message printed) on error
 */
bool
runProfilePart (const ProfileRun& run,
                const std::string& workdir,
                unsigned int threads,
                std::size_t i);

/** \brief After every part has run the pass: what it saved reduced into the plan, and
 * the next pass named in it (-method auto's choice printed when \a verbose). \a joined
 * keeps the parts' segments when the run has none left to change them. \return false
 * (message printed) when a part has not run or its files are broken */
bool
advanceProfileRun (ProfileRun& run,
                   const std::string& workdir,
                   bool verbose,
                   JoinedParts& joined);

/** \brief The merge after the last pass: the segments over all points (\a joined when
 * advanceProfileRun kept them), numbered, the cylinders joined where the run asks, and
 * the output written with \a field; \a segments their number. \return false (message
 * printed) on error */
bool
mergeProfileRun (const ProfileRun& run,
                 const std::string& workdir,
                 unsigned int threads,
                 ResultField& field,
                 const std::string& output,
                 JoinedParts& joined,
                 std::uint32_t& segments);
} // namespace apps
} // namespace pcl_ext
