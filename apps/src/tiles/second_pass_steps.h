/*
 * pcl_ext_tiles: the second pass over the tiles of a method that has one (Belton &
 * Lichti's section 4 after their segmentation): the tiles' segments joined and numbered
 * over the whole cloud, then each tile again with them.
 */
#pragma once

#include "tile_method.h"

#include <pcl_ext/tiling/tile_plan.h>

#include <string>

namespace pcl_ext {
namespace apps {
/** \brief The work files of the second pass: what the first pass keeps per point for it
 * (TileMethod::getRefineValues), the second pass's results, and each tile's largest
 * radius and estimated margin (TileMethod::getRefineRadius, getRefineMargin). */
constexpr const char* kRefineValues = "values";
constexpr const char* kRefined = "refined";
constexpr const char* kRefineBounds = "refine";

/** \brief For a method with a second pass (TileMethod::needsRefine), once every tile
 * has run: join the tiles' segments and number them over the whole cloud (minimum size
 * applied), saving each tile's segment ids; nothing when done before. */
bool
joinStep (const tiling::TilePlan& plan, TileMethod& method, const std::string& workdir);

/** \brief The second pass of \a tile (TileMethod::refine), the segments joined first
 * when they are not yet; nothing for a method without one. A progress line with
 * points/s. */
bool
refineStep (const tiling::TilePlan& plan,
            TileMethod& method,
            const std::string& workdir,
            std::size_t tile,
            unsigned int threads);

/** \brief The pass of the tiles a merge of \a method needs finished: "refined" for a
 * method with a second pass, else "done". */
std::string
lastPassOf (const TileMethod& method);

} // namespace apps
} // namespace pcl_ext
