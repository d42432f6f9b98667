/*
 * pcl_ext_tiles: the output of a run, every input point with its merged result.
 */
#pragma once

#include <pcl_ext/apps/output.h>
#include <pcl_ext/tiling/merged_results.h>
#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_results.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief What the merge reads for each point and how it writes it. */
struct MergeReading {
  /** \brief Per point (a class, or a segment numbered over the whole cloud already) or
   * the tiles' segments, joined across the halos. */
  tiling::MergedResults::Kind kind = tiling::MergedResults::Kind::PerPoint;
  /** \brief The values are segments, 0, 1, ...: written 1, 2, ..., 0 for none. */
  bool segments = false;
  /** \brief With kind Segments: numbered largest first, those under this size dropped
   * (0: numbered by first point). */
  std::uint64_t min_size = 0;
  /** \brief The per-point results read (tiling::TileResults of this name). */
  std::string results_name = tiling::TileResults::kResults;
  /** \brief New segments of a grouping pass, numbered from \a grown_first_id, those
   * under \a grown_min_size dropped (MergedResults::setGrownSegments). */
  bool grown = false;
  std::uint32_t grown_first_id = 0;
  std::uint64_t grown_min_size = 1;
  /** \brief The method's float per point, written to this field (none when empty). */
  std::string extra_field;
  /** \brief With -asprs: the values replaced by their ASPRS codes (false: none). */
  std::function<bool (std::vector<std::uint32_t>&)> to_asprs;
};

/** \brief Write \a output: every input point of \a plan with its fields and its merged
 * result (read from \a workdir as \a reading says) in \a field's field, in the inputs'
 * coordinates; one LAS file per tile of the plan when \a output names a pattern
 * (TileOutputs). \return false (message printed) on error */
bool
writeMergedOutput (const tiling::TilePlan& plan,
                   ResultField& field,
                   const std::string& workdir,
                   const std::string& output,
                   const MergeReading& reading);
} // namespace apps
} // namespace pcl_ext
