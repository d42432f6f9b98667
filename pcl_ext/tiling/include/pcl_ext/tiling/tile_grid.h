/*
 * pcl_ext: the square tiles of a large cloud, each a half-open core box plus a halo.
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief Square tiles in the horizontal plane that cover a cloud's bounding box, each
 * with a half-open core box and a halo around it: the partition under every tiled run
 * (pcl_ext_tiles).
 *
 * The tile borders lie on multiples of the tile size (in the coordinates given, e.g. a
 * file's georeferenced ones), so the same tile size gives the same tiles whatever part
 * of a project is run. Tile (c, r) has the core box [x0 + c s, x0 + (c + 1) s) x [y0 +
 * r s, y0 + (r + 1) s): every finite point belongs to exactly one core (getTile), and
 * to the halos of the tiles whose core box, widened by the halo distance, holds it
 * (getTilesNear). Tiles are numbered row by row: index = r * columns + c. Points that
 * are not finite belong to no tile (kNoTile): the methods label them unknown.
 */
class TileGrid {
public:
  static constexpr std::size_t kNoTile = std::numeric_limits<std::size_t>::max();

  TileGrid() = default;

  /** \brief Tiles of size \a tile_size with halo \a halo over the box [min, max] of the
   * points (x and y; z is not tiled). An invalid grid (isValid() false, no tile) when
   * the box is not finite or empty (min > max), the tile size is not finite and > 0,
   * the halo not finite and >= 0, or more than 2^32 tiles would be needed. */
  TileGrid (const Eigen::Vector2d& min,
            const Eigen::Vector2d& max,
            double tile_size,
            double halo);

  bool
  isValid () const
  {
    return columns_ > 0;
  }

  std::size_t
  size () const
  {
    return columns_ * rows_;
  }

  std::size_t
  getColumns () const
  {
    return columns_;
  }

  std::size_t
  getRows () const
  {
    return rows_;
  }

  double
  getTileSize () const
  {
    return size_;
  }

  double
  getHalo () const
  {
    return halo_;
  }

  /** \brief Lower corner of tile 0's core box. */
  const Eigen::Vector2d&
  getOrigin () const
  {
    return origin_;
  }

  /** \brief The tile whose core holds (x, y); kNoTile when a coordinate is not finite
   * or the point lies outside the grid's box. */
  std::size_t
  getTile (double x, double y) const;

  /** \brief Core box of \a tile: min inclusive, max exclusive. */
  void
  getCoreBox (std::size_t tile, Eigen::Vector2d& min, Eigen::Vector2d& max) const;

  /** \brief The tiles whose halo holds (x, y) (core widened by the halo; the point's
   * own tile included), ascending. */
  void
  getTilesNear (double x, double y, std::vector<std::size_t>& tiles) const;

  /** \brief How far (x, y), a point of \a tile's core or halo, is from the edge of the
   * data \a tile holds: the sides of its core box widened by \a margin (negative: the
   * halo; a tile can hold a wider margin by reading the points of the tiles around),
   * sides beyond the grid's outer border excepted (no data lies there). Infinity when
   * no side is left. A neighbourhood search around the point is complete within those
   * points when its radius is at most this distance. */
  double
  getReach (std::size_t tile, double x, double y, double margin = -1.0) const;

  /** \brief Whether (x, y) lies within \a tile's core box widened by \a margin. */
  bool
  isWithin (std::size_t tile, double x, double y, double margin) const;

  /** \brief The tiles within \a rings rings around \a tile (itself included),
   * ascending. */
  void
  getTilesAround (std::size_t tile,
                  std::size_t rings,
                  std::vector<std::size_t>& tiles) const;

private:
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double size_ = 0.0, halo_ = 0.0;
  std::size_t columns_ = 0, rows_ = 0;
};
} // namespace tiling
} // namespace pcl_ext
