/*
 * pcl_ext_tiles: the passes over the tiles after the first, for a method that has them:
 * the tiles' segments joined and numbered over the whole cloud, then each tile again
 * with them (Belton & Lichti's section 4 after their segmentation), and a pass that
 * groups the points left without a segment (new segments among them).
 */
#pragma once

#include "tile_method.h"

#include <pcl_ext/tiling/tile_plan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The work files of the second pass: what the first pass keeps per point for it
 * (TileMethod::getRefineValues), the second pass's results, and each tile's largest
 * radius and estimated margin (TileMethod::getRefineRadius, getRefineMargin). */
constexpr const char* kRefineValues = "values";
constexpr const char* kRefined = "refined";
constexpr const char* kRefineBounds = "refine";
/** \brief The pass that groups the points left without a segment (TileMethod::grow):
 * its mark, and the name of its files (tiling::SegmentPassFiles::named). */
constexpr const char* kGrown = "grown";

/** \brief For a method with a second pass (TileMethod::needsRefine) or a grouping pass
 * (needsGrow), once every tile has run: join the tiles' segments and number them over
 * the whole cloud (minimum size applied), saving each tile's segment ids; nothing when
 * done before. */
bool
joinStep (const tiling::TilePlan& plan, TileMethod& method, const std::string& workdir);

/** \brief The number of segments joinStep numbered in \a workdir. \return false
 * (message printed) when the segments were not joined */
bool
loadJoinedSegmentCount (const std::string& workdir, std::uint32_t& count);

/** \brief The second pass of \a tile (TileMethod::refine), the segments joined first
 * when they are not yet; nothing for a method without one. A progress line with
 * points/s. */
bool
refineStep (const tiling::TilePlan& plan,
            TileMethod& method,
            const std::string& workdir,
            std::size_t tile,
            unsigned int threads);

/** \brief The grouping pass of \a tile (TileMethod::grow), after every tile's last
 * pass before it; nothing for a method without one. A progress line with points/s. */
bool
growStep (const tiling::TilePlan& plan,
          TileMethod& method,
          const std::string& workdir,
          std::size_t tile,
          unsigned int threads);

/** \brief The passes of the tiles \a method makes, in order: "done" (the tiles'),
 * then kRefined with a second pass, then kGrown with a grouping pass; a merge needs
 * every tile through all of them. */
std::vector<std::string>
passesOf (const TileMethod& method);

/** \brief The step that runs pass \a pass of one tile: "tile", "refine" or "grow". */
std::string
stepOfPass (const std::string& pass);

} // namespace apps
} // namespace pcl_ext
