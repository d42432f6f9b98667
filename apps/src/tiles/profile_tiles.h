/*
 * pcl_ext_tiles segment_profiles: Sithole & Mapurisa's segmentation split by profiles.
 */
#pragma once

#include "tile_scheduler.h"

namespace pcl_ext {
namespace apps {
/** \brief `pcl_ext_tiles segment_profiles input... output [options]`: the result of
 * pcl_ext_segment_profiles on the whole cloud, computed on parts that each hold whole
 * profiles of one stack.
 *
 * A profile's chains depend on its points alone, so the rank of the run (rank 0
 * planning and merging, the parts shared among the ranks) splits the cloud by profiles
 * rather than by boxes: (1) passes over the inputs find what the segmentation derives
 * from the whole cloud (its centre, the stack origins, the spacing and statistics of
 * the sampled neighbourhoods: ProfileFrame), (2) the points go into part files, each a
 * run of whole profiles of one stack, (3) each part is segmented with the whole
 * cloud's frame (ProfileSegmentation::setCloudFrame) and its chains saved as links to
 * the first point of their component, (4) the merge joins the links of all parts over
 * all points (union-find), numbers the segments largest first and writes the output.
 * The passes and where the run stands are kept in the plan (ProfileRun), so that the
 * same run goes in steps (planProfileTiles, runProfileStep). \return the exit code */
int
runProfileTiles (int argc, char** argv, TileScheduler& scheduler);

/** \brief `pcl_ext_tiles plan segment_profiles input... -workdir D [options]` (argv[1]
 * the method): the plan of the parts and its first pass. \return the exit code */
int
planProfileTiles (int argc, char** argv);

/** \brief `part I`, `next`, `merge output` or `resume output` (argv[1]) with -workdir
 * of a segment_profiles plan: part I's share of the plan's pass; the parts' results
 * reduced and the next pass named; the merge once no pass is left; the passes left
 * (the current one on every part again) and the merge, shared among the MPI ranks.
 * \return the exit code */
int
runProfileStep (int argc, char** argv, TileScheduler& scheduler);

/** \brief Whether argv's -workdir holds a segment_profiles plan. */
bool
isProfilePlan (int argc, char** argv);
} // namespace apps
} // namespace pcl_ext
