/*
 * pcl_ext: what the tiles of a run computed, as files of its work folder.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief The result of every point of a tiled run, one UINT32 per global point index
 * in `results.bin` of the work folder (machine byte order).
 *
 * Each tile writes the results of its core points, at their indices: tiles own disjoint
 * points, so any number of processes write the one file at once. A point no tile wrote
 * (not finite, or its tile not run yet) reads as kNoResult. A method that keeps more
 * than one value per point (the classes beside the segments, the segments after a
 * second pass) keeps each in a file of its own name, `<name>.bin`. */
class TileResults {
public:
  static constexpr std::uint32_t kNoResult = 0xFFFFFFFFu;
  /** \brief The name of the results the merge writes out by default. */
  static constexpr const char* kResults = "results";

  /** \brief The file of the results named \a name in \a folder. */
  static std::string
  pathIn (const std::string& folder, const std::string& name = kResults);

  /** \brief Make the file for \a points points, every result kNoResult. \return false
   * (PCL_ERROR) when it cannot be written */
  static bool
  create (const std::string& folder,
          std::uint64_t points,
          const std::string& name = kResults);

  /** \brief Write \a values at the global indices \a indices (ascending). \return false
   * (PCL_ERROR) when the file is missing or shorter, or the disk is full */
  static bool
  write (const std::string& folder,
         const std::vector<std::uint64_t>& indices,
         const std::vector<std::uint32_t>& values,
         const std::string& name = kResults);

  /** \brief Read the results of the points \a indices (any order) into \a values, the
   * file opened once. \return false (PCL_ERROR) when the file is missing or shorter */
  static bool
  readAt (const std::string& folder,
          const std::vector<std::uint64_t>& indices,
          std::vector<std::uint32_t>& values,
          const std::string& name = kResults);

  /** \brief Read the results of the points [first, first + count) into \a values.
   * \return false (PCL_ERROR) when the file is missing or shorter */
  static bool
  read (const std::string& folder,
        std::uint64_t first,
        std::size_t count,
        std::vector<std::uint32_t>& values,
        const std::string& name = kResults);
};

/** \brief A halo point's label in a tile that does not own it: what the merge of
 * segments joins (see SegmentMerge). */
struct HaloLabel {
  std::uint64_t index = 0; ///< global point index
  std::uint32_t owner = 0; ///< the tile whose core holds the point
  std::uint32_t label = 0; ///< the segment the tile gave it
};

/** \brief The files of a pass over the tiles that labels segments: the core points'
 * labels (TileResults of name \a results), each tile's halo labels
 * (`tile_<tile>.<halo>`) and segment sizes (`tile_<tile>.<sizes>`). The default is the
 * tiles' own pass; a later pass that groups points anew (the new segments among the
 * points left out) has files of its own name. */
struct SegmentPassFiles {
  std::string results = TileResults::kResults;
  std::string halo = "halo";
  std::string sizes = "sizes";

  /** \brief The files of the pass named \a pass: `<pass>.bin`, `tile_<t>.<pass>_halo`,
   * `tile_<t>.<pass>_sizes`. */
  static SegmentPassFiles
  named (const std::string& pass)
  {
    return {pass, pass + "_halo", pass + "_sizes"};
  }
};

/** \brief Write the halo labels of tile \a tile (`tile_<tile>.<name>`, replaced
 * atomically). \return false (PCL_ERROR) when it cannot be written */
bool
saveHaloLabels (const std::string& folder,
                std::size_t tile,
                const std::vector<HaloLabel>& labels,
                const std::string& name = "halo");

/** \brief Read the halo labels of tile \a tile. \return false (PCL_ERROR names the
 * file) when it is missing (the tile was not run) or not a whole number of records */
bool
loadHaloLabels (const std::string& folder,
                std::size_t tile,
                std::vector<HaloLabel>& labels,
                const std::string& name = "halo");
/** \brief A segment of a tile as the tile's core holds it: how many of its points the
 * tile owns and the smallest global index among them (what numbers and drops the
 * joined segments, see SegmentMerge::numberBySize). */
struct SegmentSize {
  std::uint32_t label = 0;  ///< the segment in the tile
  std::uint64_t points = 0; ///< its points in the tile's core
  std::uint64_t first = 0;  ///< the smallest global index of those
};

/** \brief Write the sizes of tile \a tile's segments (`tile_<tile>.<name>`, replaced
 * atomically). \return false (PCL_ERROR) when it cannot be written */
bool
saveSegmentSizes (const std::string& folder,
                  std::size_t tile,
                  const std::vector<SegmentSize>& sizes,
                  const std::string& name = "sizes");

/** \brief Read the sizes of tile \a tile's segments. \return false (PCL_ERROR names the
 * file) when it is missing (the tile was not run) or not a whole number of records */
bool
loadSegmentSizes (const std::string& folder,
                  std::size_t tile,
                  std::vector<SegmentSize>& sizes,
                  const std::string& name = "sizes");

/** \brief Write the global segment ids of tile \a tile's segments, one per label of the
 * tile (`tile_<tile>.ids`, replaced atomically; SegmentMerge::kNoSegment for a label
 * the tile's core does not hold or whose segment was dropped): what a second pass over
 * the tiles reads to know every point's segment. \return false (PCL_ERROR) when it
 * cannot be written */
bool
saveSegmentIds (const std::string& folder,
                std::size_t tile,
                const std::vector<std::uint32_t>& ids);

/** \brief Read what saveSegmentIds wrote for tile \a tile. \return false (PCL_ERROR
 * names the file) when it is missing or broken */
bool
loadSegmentIds (const std::string& folder,
                std::size_t tile,
                std::vector<std::uint32_t>& ids);

/** \brief Record that a process started tile \a tile (`tile_<tile>.running`: which
 * process, on which host, when), so that a tile whose process died can be named.
 * \return false (PCL_ERROR) when it cannot be written */
bool
markTileStarted (const std::string& folder, std::size_t tile);

/** \brief What markTileStarted recorded for \a tile ("process 1234 on host h at
 * 2026-11-27 09:00:00 UTC"), or empty when the tile was not started or finished. */
std::string
describeTileStart (const std::string& folder, std::size_t tile);

/** \brief Record that tile \a tile wrote all its results of pass \a pass
 * (`tile_<tile>.<pass>`: "done" the tiles' pass, "refined" a second one; its start
 * record is removed). \return false (PCL_ERROR) when it cannot be written */
bool
markTileDone (const std::string& folder,
              std::size_t tile,
              const std::string& pass = "done");

/** \brief The tiles among 0 .. \a tiles - 1 of \a folder that have not been marked
 * done with pass \a pass, ascending. */
std::vector<std::size_t>
findTilesNotDone (const std::string& folder,
                  std::size_t tiles,
                  const std::string& pass = "done");

/** \brief Save \a values (one per core point of tile \a tile, any order) as the tile's
 * `tile_<tile>.<name>` file: the material of a statistic of the whole cloud that a
 * method estimates before the tiles run (e.g. a median curvature). \return false
 * (PCL_ERROR) when it cannot be written */
bool
saveTileValues (const std::string& folder,
                std::size_t tile,
                const std::string& name,
                const std::vector<float>& values);

/** \brief The values saved by saveTileValues for tile \a tile under \a name, all of
 * them (non-finite ones too), in their order. \return false (PCL_ERROR names the file)
 * when the file is missing or broken */
bool
loadTileValues (const std::string& folder,
                std::size_t tile,
                const std::string& name,
                std::vector<float>& values);

} // namespace tiling
} // namespace pcl_ext
