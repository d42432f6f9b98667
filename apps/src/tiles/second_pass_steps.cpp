/*
 * pcl_ext_tiles: the passes over the tiles after the first, for a method that has them:
 * the tiles' segments joined and numbered over the whole cloud, then each tile again
 * with them (Belton & Lichti's section 4 after their segmentation), and a pass that
 * groups the points left without a segment (new segments among them).
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
#include <fstream>
#include <iomanip>
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

/** Each point of \a c's segment as its owner numbered it, over the whole cloud
 * (kNoSegment for none), its owners' ids read once into \a ids_of_tile. */
bool
readJoinedSegments (const std::string& workdir,
                    const TileCloud& c,
                    std::map<std::uint32_t, std::vector<std::uint32_t>>& ids_of_tile,
                    std::vector<std::uint32_t>& segments)
{
  std::vector<std::uint32_t> owner_labels, ids;
  if (!tiling::TileResults::readAt (workdir, c.indices, owner_labels))
    return false;
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
  return true;
}

/** The tiles of \a workdir that have not finished the passes before \a pass (named and
 * how to run them printed). \return whether every one has */
bool
passesBeforeDone (const TileMethod& method,
                  const std::string& workdir,
                  std::size_t tiles,
                  const std::string& pass)
{
  for (const auto& p : passesOf (method)) {
    if (p == pass)
      break;
    const auto missing = tiling::findTilesNotDone (workdir, tiles, p);
    if (!missing.empty()) {
      reportTilesNotDone (workdir, missing, p);
      return false;
    }
  }
  return true;
}

/** The points/s line of a pass over \a cloud that took \a ms milliseconds. */
void
reportPass (const TileCloud& cloud, double ms)
{
  std::cout << "  " << cloud.indices.size() - cloud.core_points
            << " halo points, margin " << std::defaultfloat << std::setprecision (3)
            << cloud.margin << " m, "
            << static_cast<long long> (cloud.core_points / std::max (ms, 1.0) * 1e3)
            << " points/s\n";
}
} // namespace

bool
joinStep (const tiling::TilePlan& plan, TileMethod& method, const std::string& workdir)
{
  struct stat st;
  if ((!method.needsRefine() && !method.needsGrow()) ||
      ::stat (joinedPath (workdir).c_str(), &st) == 0)
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
loadJoinedSegmentCount (const std::string& workdir, std::uint32_t& count)
{
  std::ifstream in (joinedPath (workdir));
  unsigned long long n = 0;
  if (!(in >> n) || n > tiling::SegmentMerge::kNoSegment) {
    std::cerr << "Error: the segments of " << workdir << " were not joined ("
              << joinedPath (workdir) << " missing or broken).\n";
    return false;
  }
  count = static_cast<std::uint32_t> (n);
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
  std::vector<std::uint32_t> segments, values, labels;
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
    if (!readJoinedSegments (workdir, c, ids_of_tile, segments) ||
        !tiling::TileResults::readAt (workdir, c.indices, values, kRefineValues))
      return false;
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
  reportPass (cloud, timer.done (cloud.core_points));
  return true;
}

bool
growStep (const tiling::TilePlan& plan,
          TileMethod& method,
          const std::string& workdir,
          std::size_t tile,
          unsigned int threads)
{
  if (!method.needsGrow())
    return true;
  const std::size_t tiles = plan.getGrid().size();
  if (!joinStep (plan, method, workdir) ||
      !passesBeforeDone (method, workdir, tiles, kGrown))
    return false;
  StageTimer timer ("Tile " + std::to_string (tile) + ", points left out grouped");
  if (!tiling::markTileStarted (workdir, tile))
    return false;
  TileCloud cloud;
  method.setNumberOfThreads (threads);
  std::vector<std::uint32_t> segments, labels;
  std::map<std::uint32_t, std::vector<std::uint32_t>> ids_of_tile;
  const bool refined = method.needsRefine();
  // The segments after the last pass: the second's, numbered over the whole cloud
  // already, or the tiles' own joined. Only the points without one are grouped, so
  // only theirs are the neighbourhoods searched.
  const auto select = [&] (const TileCloud& c, std::vector<char>& query) {
    if (refined ? !tiling::TileResults::readAt (workdir, c.indices, segments, kRefined)
                : !readJoinedSegments (workdir, c, ids_of_tile, segments))
      return false;
    query.resize (segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i)
      query[i] = segments[i] == tiling::SegmentMerge::kNoSegment;
    return true;
  };
  const auto grow = [&] (const TileCloud& c) {
    return method.grow (c, segments, labels);
  };
  if (!computeOnTile (plan,
                      workdir,
                      tile,
                      method.getGrowReach(),
                      threads,
                      0.0,
                      method,
                      grow,
                      cloud,
                      select))
    return false;
  std::vector<std::uint64_t> core_indices;
  std::vector<std::uint32_t> core_labels;
  std::vector<tiling::HaloLabel> halo;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (cloud.core[i]) {
      core_indices.push_back (cloud.indices[i]);
      core_labels.push_back (labels[i]); // kNoSegment is kNoResult
    }
    else if (labels[i] != tiling::SegmentMerge::kNoSegment)
      halo.push_back ({cloud.indices[i], cloud.owners[i], labels[i]});
  }
  const auto files = tiling::SegmentPassFiles::named (kGrown);
  if (!tiling::TileResults::write (workdir, core_indices, core_labels, files.results) ||
      !tiling::saveHaloLabels (workdir, tile, halo, files.halo) ||
      !tiling::saveSegmentSizes (
          workdir, tile, segmentSizes (cloud, labels), files.sizes) ||
      !tiling::markTileDone (workdir, tile, kGrown))
    return false;
  reportPass (cloud, timer.done (cloud.core_points));
  return true;
}

std::vector<std::string>
passesOf (const TileMethod& method)
{
  std::vector<std::string> passes{"done"};
  if (method.needsRefine())
    passes.push_back (kRefined);
  if (method.needsGrow())
    passes.push_back (kGrown);
  return passes;
}

std::string
stepOfPass (const std::string& pass)
{
  return pass == kRefined ? "refine" : pass == kGrown ? "grow" : "tile";
}

} // namespace apps
} // namespace pcl_ext
