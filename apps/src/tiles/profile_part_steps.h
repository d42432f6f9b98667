/*
 * pcl_ext_tiles segment_profiles: what runs on each part (its local gaps, its chains)
 * and what joins the parts (the stacks' mean gaps, the segments over all points).
 */
#pragma once

#include "../profiles/profile_options.h"
#include "profile_parts.h"

#include <pcl_ext/common/union_find.h>
#include <pcl_ext/tiling/tile_plan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief How the parts run in a pass: as the options say, except -method auto's first
 * run (proximity) and its choice of local thresholds. */
struct PartPass {
  bool first_automatic = false;  ///< -method auto's first run: proximity chaining
  bool local_threshold = false;  ///< local thresholds (then mean_gaps is set)
  std::vector<double> mean_gaps; ///< each stack's mean local gap over the whole cloud
};

/** \brief The local gap of every point of part \a i in its stack (the pass's settings),
 * saved at the points' global indices (the file of its stack, gapsFileName) with the
 * longest local threshold beside (its mark of being done). \return false (message
 * printed) on error */
bool
computePartGaps (const ProfileFrame& frame,
                 const ProfileParts& parts,
                 const ProfileOptions& options,
                 const PartPass& pass,
                 const std::string& workdir,
                 unsigned int threads,
                 std::size_t i);

/** \brief Make the files of every stack's local gaps for \a points points. */
bool
createGapFiles (const std::string& workdir, std::size_t stacks, std::uint64_t points);

/** \brief Each stack's mean local gap as the untiled segmentation takes it: the gaps
 * below the longest local threshold, summed in the points' order. \return false
 * (message printed) when a part's gaps are missing */
bool
reduceGaps (const tiling::TilePlan& plan,
            const ProfileParts& parts,
            const std::string& workdir,
            std::vector<double>& mean_gaps);

/** \brief Segment part \a i as the pass says and save each point's link to the first
 * point of its chain's component in the part (none for that first point). \return
 * false (message printed) on error */
bool
segmentPart (const ProfileFrame& frame,
             const ProfileParts& parts,
             const ProfileOptions& options,
             const PartPass& pass,
             const std::string& workdir,
             unsigned int threads,
             std::size_t i);

/** \brief The segments over all points: the parts' links joined (each component's root
 * its first point). */
struct JoinedParts {
  UnionFind sets;
  std::vector<std::uint32_t> size; ///< points of each root's component (0 elsewhere)
  std::uint32_t largest = 0;       ///< points of the largest component
};

/** \brief Join the links of every part of \a parts. \return false (message printed)
 * when a part has not run or its files are broken */
bool
joinParts (const tiling::TilePlan& plan,
           const ProfileParts& parts,
           const std::string& workdir,
           JoinedParts& joined);

/** \brief Number the joined segments of at least \a min_size points largest first
 * (ties by first point), as ProfileSegmentation does, and save them as the run's
 * results (tiling::TileResults; none for a point in no segment). \return false
 * (message printed) when they cannot be written */
bool
saveSegments (const std::string& workdir,
              std::uint64_t min_size,
              JoinedParts& joined,
              std::uint32_t& segments);
} // namespace apps
} // namespace pcl_ext
