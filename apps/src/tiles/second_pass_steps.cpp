/*
 * pcl_ext_tiles: the second pass over the tiles of a method that has one (Belton &
 * Lichti's section 4 after their segmentation): the tiles' segments joined and numbered
 * over the whole cloud, then each tile again with them.
 */
#include "second_pass_steps.h"
#include "tile_steps.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/tiling/merged_results.h>
#include <pcl_ext/tiling/segment_merge.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sys/stat.h>

namespace pcl_ext {
namespace apps {
namespace {
/** The mark of the segments joined and numbered for the second pass. */
std::string
joinedPath (const std::string& workdir)
{
  return workdir + "/segments.joined";
}
} // namespace

bool
joinStep (const tiling::TilePlan& plan, TileMethod& method, const std::string& workdir)
{
  struct stat st;
  if (!method.needsRefine() || ::stat (joinedPath (workdir).c_str(), &st) == 0)
    return true;
  const std::size_t tiles = plan.getGrid().size();
  const auto missing = tiling::findTilesNotDone (workdir, tiles);
  if (!missing.empty()) {
    reportTilesNotDone (workdir, missing);
    return false;
  }
  StageTimer timer ("Joining the segments of " + std::to_string (tiles) + " tiles");
  tiling::SegmentMerge merge;
  const std::uint64_t min_size =
      std::max<std::uint64_t> (method.getMinSegmentSize(), 1);
  if (!tiling::joinTileSegments (plan, workdir, true, min_size, merge))
    return false;
  if (merge.getNumberOfSegments() == 0) {
    std::cerr << "\nError: no segment of at least " << min_size << " points.\n";
    return false;
  }
  std::vector<tiling::SegmentSize> sizes;
  std::vector<std::uint32_t> ids;
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!tiling::loadSegmentSizes (workdir, t, sizes))
      return false;
    ids.clear();
    for (const auto& s : sizes) {
      if (ids.size() <= s.label)
        ids.resize (s.label + 1, tiling::SegmentMerge::kNoSegment);
      ids[s.label] = merge.number (
          tiling::SegmentMerge::key (static_cast<std::uint32_t> (t), s.label));
    }
    if (!tiling::saveSegmentIds (workdir, t, ids))
      return false;
  }
  if (!io::writeTextFile (joinedPath (workdir),
                          std::to_string (merge.getNumberOfSegments()) + " segments\n"))
    return false;
  timer.done (merge.getNumberOfSegments());
  return true;
}

bool
refineStep (const tiling::TilePlan& plan,
            TileMethod& method,
            const std::string& workdir,
            std::size_t tile,
            unsigned int threads)
{
  if (!method.needsRefine())
    return true;
  if (!joinStep (plan, method, workdir))
    return false;
  StageTimer timer ("Tile " + std::to_string (tile) + ", second pass");
  if (!tiling::markTileStarted (workdir, tile))
    return false;
  TileCloud cloud;
  method.setNumberOfThreads (threads);
  NeighbourhoodReach reach = method.getReach();
  reach.hops = 1;
  std::vector<std::uint32_t> owner_labels, segments, values, labels, ids;
  std::map<std::uint32_t, std::vector<std::uint32_t>> ids_of_tile;
  // Every tile's largest radius, rounded up to a float as saved, and the margin this
  // tile's first pass estimated for it.
  std::vector<float> tile_radii (plan.getGrid().size(), 0.0f), saved;
  double margin = 0.0;
  for (std::size_t t = 0; t < tile_radii.size(); ++t) {
    if (!tiling::loadTileValues (workdir, t, kRefineBounds, saved) ||
        saved.size() != 2) {
      std::cerr << "Error: the first pass of tile " << t << " in " << workdir
                << " left no bounds for the second (tile_" << t << "." << kRefineBounds
                << ").\n";
      return false;
    }
    tile_radii[t] = saved[0] > 0.0f ? std::nextafter (saved[0], INFINITY) : 0.0f;
    if (t == tile)
      margin = saved[1];
  }
  const auto refine = [&] (const TileCloud& c) {
    if (!tiling::TileResults::readAt (workdir, c.indices, owner_labels) ||
        !tiling::TileResults::readAt (workdir, c.indices, values, kRefineValues))
      return false;
    // Each point's segment as its owner numbered it, over the whole cloud.
    segments.assign (c.indices.size(), tiling::SegmentMerge::kNoSegment);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::uint32_t owner = c.owners[i];
      if (owner_labels[i] == tiling::TileResults::kNoResult)
        continue;
      auto found = ids_of_tile.find (owner);
      if (found == ids_of_tile.end()) {
        if (!tiling::loadSegmentIds (workdir, owner, ids))
          return false;
        found = ids_of_tile.emplace (owner, ids).first;
      }
      if (owner_labels[i] < found->second.size())
        segments[i] = found->second[owner_labels[i]];
    }
    return method.refine (c, segments, values, tile_radii, labels);
  };
  if (!computeOnTile (
          plan, workdir, tile, reach, threads, margin, method, refine, cloud))
    return false;
  std::vector<std::uint64_t> core_indices;
  std::vector<std::uint32_t> core_labels;
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (cloud.core[i]) {
      core_indices.push_back (cloud.indices[i]);
      core_labels.push_back (labels[i] == tiling::SegmentMerge::kNoSegment
                                 ? tiling::TileResults::kNoResult
                                 : labels[i]);
    }
  if (!tiling::TileResults::write (workdir, core_indices, core_labels, kRefined) ||
      !method.saveRefineOutputs (workdir, cloud) ||
      !tiling::markTileDone (workdir, tile, kRefined))
    return false;
  const double ms = timer.done (cloud.core_points);
  std::cout << "  " << cloud.indices.size() - cloud.core_points
            << " halo points, margin " << cloud.margin << " m, "
            << static_cast<long long> (cloud.core_points / std::max (ms, 1.0) * 1e3)
            << " points/s\n";
  return true;
}

std::string
lastPassOf (const TileMethod& method)
{
  return method.needsRefine() ? kRefined : "done";
}

} // namespace apps
} // namespace pcl_ext
