/*
 * pcl_ext: the plan of a tiled run (inputs, origin, tile grid, settings), kept as text
 * in its work folder.
 */
#pragma once

#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/tiling/tile_grid.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief What every step of a tiled run (plan, tile, merge; any process) must agree
 * on.
 *
 * The points of the inputs are numbered one input after another, each in file order:
 * point i of input f has the global index sum(counts[0..f)) + i. Coordinates are
 * handed to the methods relative to \a origin (the origin io::loadPointFile gives the
 * first input), the tiles are laid in the inputs' own (double) coordinates. */
struct TilePlan {
  std::vector<std::string> inputs;                  ///< absolute paths (planTiles)
  std::vector<std::uint64_t> counts;                ///< points per input
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< of every chunk's x y z
  Eigen::Vector2d min = Eigen::Vector2d::Zero();    ///< box of the points (x, y)
  Eigen::Vector2d max = Eigen::Vector2d::Zero();
  double tile_size = 0.0;
  double halo = 0.0;
  /** The method, its options and the parameters estimated for the whole cloud: text
   * values that the steps read back (e.g. "method" -> "classify_variance"). */
  std::map<std::string, std::string> settings;

  /** \brief The tile grid of the plan (invalid when the plan is). */
  TileGrid
  getGrid () const
  {
    return TileGrid (min, max, tile_size, halo);
  }

  /** \brief Points of all inputs. */
  std::uint64_t
  getTotalPoints () const;

  /** \brief Global index of the first point of input \a input. */
  std::uint64_t
  getFirstIndex (std::size_t input) const;
};

/** \brief Write \a plan to \a path (text, one `key value` line each; atomically).
 * \return false (PCL_ERROR) when it cannot be written */
bool
saveTilePlan (const std::string& path, const TilePlan& plan);

/** \brief Read a plan written by saveTilePlan. \return false (PCL_ERROR names the file
 * and line) when it is missing, malformed, or describes no valid grid */
bool
loadTilePlan (const std::string& path, TilePlan& plan);

/** \brief The plan of the inputs: counts, origin and box (each input opened through
 * PointFileChunks: LAS / LAZ headers only, other formats read), the grid of
 * \a tile_size with \a halo; the inputs are kept as absolute paths, so that any
 * step finds them from any working folder. \throw io::ReadError naming an input that
 * cannot be read; \return false (PCL_ERROR) when there is no point with finite
 * coordinates, the tile size or halo is not valid, or the inputs are more than 1e6 m
 * apart */
bool
planTiles (const std::vector<std::string>& inputs,
           double tile_size,
           double halo,
           TilePlan& plan);

/** \brief A tile size for \a points points over the plan's box such that a tile holds
 * about \a points_per_tile of them (a uniform density assumed), rounded up to 1, 2 or 5
 * times a power of ten. */
double
suggestTileSize (const Eigen::Vector2d& min,
                 const Eigen::Vector2d& max,
                 std::uint64_t points,
                 std::uint64_t points_per_tile);

/** \brief The largest tile size whose densest tile (tiles laid on multiples of the
 * size) holds at most \a max_points_per_tile of the points of \a plan's inputs,
 * counted from the points themselves (one pass over the inputs in chunks): a scan's
 * density varies by orders of magnitude with the range, where suggestTileSize assumes
 * it uniform. The size is a whole multiple (1 to 64) of a cell of 1, 2 or 5 times a
 * power of ten near a sixteenth of suggestTileSize's; the cell itself when even that
 * holds more. \a plan needs its inputs, counts, origin and box (planTiles).
 * \throw io::ReadError naming an input that cannot be read */
double
fitTileSize (const TilePlan& plan, std::uint64_t max_points_per_tile);

/** \brief Values a method reads beside x y z, per point of a chunk of an input (\a
 * input names it): \a values gets the chunk's points' values one point after another.
 * \return false (message printed) when the chunk does not have them */
using ChunkAttributes = std::function<bool (const pcl::PCLPointCloud2& chunk,
                                            const std::string& input,
                                            std::vector<float>& values)>;

/** \brief Sort the points of every input into the files of the tiles of \a plan in
 * \a folder (tile_<t>.points: each point of a tile's core or halo, see
 * TilePointWriter), reading the inputs in chunks. Points that are not finite go to no
 * tile. With \a attribute_count > 0, \a attributes gives that many values per point,
 * saved beside (tile_<t>.attributes). With \a sample_cut, every finite point's
 * noiseSampleKeyOf (of its coordinates relative to the plan's origin, as the tiles hold
 * them) is added to it: the whole cloud's noise sample is then known before any tile
 * runs. \throw io::ReadError naming an input that cannot be read \return false
 * (PCL_ERROR) when a point lies outside the plan's box (an input changed since the
 * plan, or a LAS header whose box lies), the attributes cannot be read, a file cannot
 * be written, or the tile size is far too small for the data (more than max(1,000,
 * points / 100) tiles would hold points) */
bool
writeTiles (const TilePlan& plan,
            const std::string& folder,
            std::size_t attribute_count = 0,
            const ChunkAttributes& attributes = {},
            NoiseSampleCut* sample_cut = nullptr);
} // namespace tiling
} // namespace pcl_ext
