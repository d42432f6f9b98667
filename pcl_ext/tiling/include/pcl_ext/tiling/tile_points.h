/*
 * pcl_ext: the points of each tile (core and halo) as files of a work folder.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief A point as a tile holds it: its index in the whole input (the inputs one
 * after another, each in file order), its coordinates relative to the run's origin as
 * the reader gave them (float, so that a tile computes on the very values an untiled
 * run does) and the tile whose core holds it (its owner: the tile itself for a core
 * point, a neighbour for a halo point). */
struct TilePoint {
  std::uint64_t index = 0;
  float x = 0.0f, y = 0.0f, z = 0.0f;
  std::uint32_t owner = 0;
};

/** \brief The file of tile \a tile in \a folder: `tile_<tile>.points`. */
std::string
tilePointsPath (const std::string& folder, std::size_t tile);

/** \brief The file of the attributes of tile \a tile's points in \a folder:
 * `tile_<tile>.attributes`. */
std::string
tileAttributesPath (const std::string& folder, std::size_t tile);

/** \brief Sorts points into the files of their tiles in a work folder, a bounded buffer
 * per tile: one pass over inputs of any size holds at most the buffers.
 *
 * Each file is a sequence of 24-byte records (index UINT64, x y z FLOAT32, owner
 * UINT32, in the machine's byte order: the files are for the processes of one run).
 * Points must be added in ascending index order so that each tile's file is in that
 * order too. With attributes (values a method reads beside x y z, e.g. colour), each
 * tile also gets a file of that many FLOAT32 per point, in the same order. */
class TilePointWriter {
public:
  /** \brief Files for \a tiles tiles in \a folder, which must exist; existing tile
   * files are replaced. \a buffer_points per tile are kept before they are appended;
   * \a attributes values per point go to the attribute files (0: none). */
  TilePointWriter (std::string folder,
                   std::size_t tiles,
                   std::size_t buffer_points = 4096,
                   std::size_t attributes = 0);
  ~TilePointWriter();
  TilePointWriter (const TilePointWriter&) = delete;
  TilePointWriter&
  operator= (const TilePointWriter&) = delete;

  /** \brief Add \a point to tile \a tile, with its \a attributes (as many as the
   * constructor said; ignored when 0). \return false (PCL_ERROR names the file) when
   * a buffer cannot be written (e.g. the disk is full); the writer then stays failed */
  bool
  add (std::size_t tile, const TilePoint& point, const float* attributes = nullptr);

  /** \brief Write what the buffers hold; \return false as add(). Every tile has a file
   * afterwards (empty when no point came). */
  bool
  finish ();

  /** \brief Points added to \a tile so far. */
  std::uint64_t
  getCount (std::size_t tile) const
  {
    return counts_[tile];
  }

private:
  bool
  flush (std::size_t tile);

  bool
  append (const std::string& path, bool started, const std::vector<char>& bytes);

  std::string folder_;
  std::size_t buffer_points_;
  std::size_t attributes_;
  std::vector<std::vector<TilePoint>> buffers_;
  std::vector<std::vector<float>> attribute_buffers_;
  std::vector<std::uint64_t> counts_;
  std::vector<bool> started_;
  bool failed_ = false;
};

/** \brief Read the points of tile \a tile from \a folder into \a points. \return false
 * (PCL_ERROR names the file) when the file is missing, is not a whole number of records
 * or its indices are not ascending */
bool
readTilePoints (const std::string& folder,
                std::size_t tile,
                std::vector<TilePoint>& points);
/** \brief Read the \a attributes values per point of tile \a tile from \a folder into
 * \a values (point after point, in the order of readTilePoints). \return false
 * (PCL_ERROR names the file) when the file is missing or not a whole number of points
 */
bool
readTileAttributes (const std::string& folder,
                    std::size_t tile,
                    std::size_t attributes,
                    std::vector<float>& values);
} // namespace tiling
} // namespace pcl_ext
