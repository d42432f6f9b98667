/*
 * pcl_ext_tiles segment_profiles: what runs on each part (its local gaps, its chains)
 * and what joins the parts (the stacks' mean gaps, the segments over all points).
 */
#pragma once

#include "../profiles/profile_options.h"
#include "profile_parts.h"

#include <pcl_ext/common/union_find.h>
#include <pcl_ext/segmentation/profile_part_segmentation.h>
#include <pcl_ext/tiling/tile_plan.h>

#include <cstdint>
#include <functional>
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

/** \brief Part \a i's points (\a indices: their global indices) and \a seg set up for
 * them as \a pass says: the options, one stack (\a stack), the whole cloud's frame.
 * \return false (message printed) when its file cannot be read */
bool
setUpPart (const ProfileFrame& frame,
           const ProfileParts& parts,
           const ProfileOptions& options,
           const PartPass& pass,
           const std::string& workdir,
           unsigned int threads,
           std::size_t i,
           std::size_t& stack,
           std::vector<std::uint64_t>& indices,
           ProfilePartSegmentation<pcl::PointXYZ>& seg);

/** \brief Write \a bytes of \a data to \a path whole or not at all (through a partial
 * file renamed). \return false (message printed) on error */
bool
writePartFile (const std::string& path, const void* data, std::size_t bytes);

/** \brief \a visit every pair of global indices of a part's "links" file, read in
 * blocks. \return false (message printed) when missing (the part has not run) or
 * broken (an odd count, an index not below \a points) */
bool
forEachPartLink (const std::string& path,
                 std::uint64_t points,
                 const std::function<void (std::uint64_t, std::uint64_t)>& visit);

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

/** \brief Set \a flags to 1 at the global index of every finite point (every point
 * of the first stack's parts). \return false (message printed) on error */
bool
markFinitePoints (const ProfileParts& parts,
                  const std::string& workdir,
                  std::vector<std::uint32_t>& flags);

/** \brief With \a joined's sets made and its size 1 at every finite point: each root's
 * component size (0 elsewhere) and the largest. */
void
countComponents (JoinedParts& joined);

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
