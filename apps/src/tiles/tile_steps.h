/*
 * pcl_ext_tiles: the steps of a tiled run (plan, estimate, tile, merge), each usable
 * alone (scheduler array jobs) or one after another.
 */
#pragma once

#include "tile_method.h"

#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_results.h>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief Points read at a time from an input. */
constexpr std::size_t kChunkPoints = 1 << 20;

/** \brief The work file of a method's float per point (TileMethod::getExtraValues), as
 * the bits of each float, at the points' global indices. */
constexpr const char* kExtraValues = "extra";

/** \brief The points each segment of \a labels (one per point of \a cloud, numbered
 * in the tile; kNoSegment for none) has in the tile's core, and the first of them. */
std::vector<tiling::SegmentSize>
segmentSizes (const TileCloud& cloud, const std::vector<std::uint32_t>& labels);

/** \brief A method's options as one plan setting (tab-separated). */
std::string
joinArguments (const std::vector<std::string>& args);

/** \brief The options joined by joinArguments. */
std::vector<std::string>
splitArguments (const std::string& text);

/** \brief The plan's file in a work folder. */
std::string
planPath (const std::string& workdir);

/** \brief Plan a run: the inputs' box and points, the tile grid (\a tile_size 0: at
 * most 2.5 million points in the densest tile), the halo (\a halo < 0: from the
 * neighbourhood radii of a sample of the first input), the
 * method and its options (\a method_arguments, to parse again in the other steps), and
 * the points sorted into the tiles' files. \return false (message printed) on error */
bool
planStep (const std::string& method_name,
          const TileMethod& method,
          const std::vector<std::string>& method_arguments,
          const std::vector<std::string>& inputs,
          double tile_size,
          double halo,
          const std::string& workdir,
          tiling::TilePlan& plan);

/** \brief The plan of \a workdir and its method with the options the plan was made
 * with, parsed by \a cl (which \a result_field reads: keep it as long). \return false
 * (message printed) when either cannot be read */
bool
loadPlanAndMethod (const std::string& workdir,
                   tiling::TilePlan& plan,
                   std::unique_ptr<TileMethod>& method,
                   CommandLine& cl,
                   ResultField& result_field);

/** \brief Run the estimate of \a tile (when the method needs one). */
bool
estimateStep (const tiling::TilePlan& plan,
              TileMethod& method,
              const std::string& workdir,
              std::size_t tile,
              unsigned int threads);

/** \brief Reduce the tiles' estimates into the plan's settings (saved) when the method
 * needs one and the plan has none yet. */
bool
reduceStep (tiling::TilePlan& plan, TileMethod& method, const std::string& workdir);

/** \brief Run \a tile: its core points' results (and its halo labels, for segments) in
 * the work folder. A progress line with points/s. */
bool
tileStep (const tiling::TilePlan& plan,
          TileMethod& method,
          const std::string& workdir,
          std::size_t tile,
          unsigned int threads);

/** \brief Print which tiles of \a workdir have not run or did not finish pass \a pass
 * (\a missing), naming the process that started each unfinished one, and how to
 * complete the run. */
void
reportTilesNotDone (const std::string& workdir,
                    const std::vector<std::size_t>& missing,
                    const std::string& pass = "done");

/** \brief Write \a output: every input point with its fields and the merged result in
 * \a field's field, in the inputs' coordinates. */
bool
mergeStep (const tiling::TilePlan& plan,
           TileMethod& method,
           ResultField& field,
           const std::string& workdir,
           const std::string& output);
} // namespace apps
} // namespace pcl_ext
