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
 * \return the exit code */
int
runProfileTiles (int argc, char** argv, TileScheduler& scheduler);
} // namespace apps
} // namespace pcl_ext
