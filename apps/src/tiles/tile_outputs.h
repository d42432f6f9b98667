/*
 * pcl_ext_tiles: one output file per tile, with an index of the files.
 */
#pragma once

#include <pcl_ext/io/las_header.h>
#include <pcl_ext/io/las_writer.h>
#include <pcl_ext/tiling/tile_grid.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The points each tile owns (its half-open core box), written to a LAS file of
 * its own, with every field of the chunks, in the inputs' frame; then an index of the
 * files: a CSV table with one row per file, its tile's core box as numbers and as WKT
 * (a GIS opens it as a layer of polygons; pcl_ext::io::loadFootprints reads it too).
 *
 * The files are named by a pattern with a '#' (as PDAL's writers split their output):
 * `out_#.las` gives `out_0.las`, `out_1.las`, ... by the tile's number in the plan (the
 * I of `pcl_ext_tiles tile I`), and the index `out_index.csv`. A tile that owns no
 * point has no file. Nothing is visible at any path before close() succeeds; a
 * TileOutputs destroyed before, or whose writing failed, leaves none of its files
 * behind. */
class TileOutputs {
public:
  /** \brief How many files one process may hold open besides its own few: the soft
   * limit, raised to the hard one first. */
  static std::size_t
  openFilesAllowed ();

  /** \brief Whether \a output names one file per tile (holds a '#'). */
  static bool
  isPattern (const std::string& output);

  /** \brief The file of \a tile: the pattern's first '#' replaced by the number. */
  static std::string
  pathOf (const std::string& pattern, std::size_t tile);

  /** \brief The index: the pattern's '#' replaced by "index", its extension by csv. */
  static std::string
  indexPathOf (const std::string& pattern);

  /** \brief Files of \a pattern for the tiles of \a grid, whose points come in chunks
   * with coordinates relative to \a origin; \a like as for io::LasWriter::open. */
  TileOutputs (const std::string& pattern,
               const tiling::TileGrid& grid,
               const Eigen::Vector3d& origin,
               const io::LasFileInfo* like);
  ~TileOutputs();

  /** \brief Append the points of \a chunk owned by the tiles [\a first_tile,
   * \a end_tile) to their files (opened on their first point; all chunks have the
   * fields of the first). Points without finite coordinates are in no tile: they are
   * counted (getPointsInNoTile), not written. \return false (PCL_ERROR says why) when
   * a file cannot be written */
  bool
  write (const pcl::PCLPointCloud2& chunk,
         std::size_t first_tile,
         std::size_t end_tile);

  /** \brief Finish every file opened since the last call, keeping them for the index;
   * called after each pass over the inputs, so that only a pass's files are open at
   * once. \return false (PCL_ERROR) when one cannot be finished */
  bool
  finishPass ();

  /** \brief Write the index and keep the files. \return false (PCL_ERROR; no file left)
   * when it cannot be written */
  bool
  close ();

  /** \brief Points of the chunks that lie in no tile (coordinates not finite). */
  std::uint64_t
  getPointsInNoTile () const
  {
    return points_in_no_tile_;
  }

  /** \brief The files written (after close()). */
  std::size_t
  getNumberOfFiles () const
  {
    return done_.size();
  }

private:
  struct Done {
    std::size_t tile;
    std::uint64_t points;
  };

  void
  removeWritten ();

  std::string pattern_;
  tiling::TileGrid grid_;
  Eigen::Vector3d origin_;
  const io::LasFileInfo* like_;
  std::map<std::size_t, std::unique_ptr<io::LasWriter>> open_;
  std::vector<Done> done_;
  std::vector<std::uint32_t> owner_;
  std::uint64_t points_in_no_tile_ = 0;
  bool closed_ = false;
};
} // namespace apps
} // namespace pcl_ext
