/*
 * pcl_ext: any point file read in chunks, with coordinates relative to a chosen origin.
 */
#pragma once

#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace pcl_ext {
namespace tiling {
/** \brief The points of a file in chunks, whatever its format: LAS, LAZ and COPC
 * through io::LasReader, a chunk at a time (the file is never held whole); the other
 * formats through io::loadPointFile, whole, handed out in chunks.
 *
 * Chunks have the fields of io::loadPointFile (x y z FLOAT32 first, relative to
 * getOrigin(), then every field of the file). The origin is the one io::loadPointFile
 * gives the file, so a tiled run computes on the same float coordinates as an untiled
 * one; setOrigin() chooses another (the first file's, for the files of one project). */
class PointFileChunks {
public:
  PointFileChunks();
  ~PointFileChunks();
  PointFileChunks (const PointFileChunks&) = delete;
  PointFileChunks&
  operator= (const PointFileChunks&) = delete;

  /** \brief Open \a path (LAS / LAZ: its header; other formats: the whole file).
   * \throw io::ReadError naming the file when it cannot be read (see loadPointFile) */
  void
  open (const std::string& path);

  /** \brief Use \a origin for the chunks read from now on (finite). */
  void
  setOrigin (const Eigen::Vector3d& origin);

  const Eigen::Vector3d&
  getOrigin () const
  {
    return origin_;
  }

  /** \brief The file's points. */
  std::uint64_t
  getPointCount () const
  {
    return count_;
  }

  /** \brief The bounding box of the points, in the file's coordinates: LAS / LAZ from
   * the header (which may lie: a tiled run refuses points outside the box it planned
   * for), other formats from the finite points (an empty box, min > max, when none
   * is). */
  void
  getBounds (Eigen::Vector3d& min, Eigen::Vector3d& max) const
  {
    min = min_;
    max = max_;
  }

  /** \brief The file as loadPointFile would describe it, without its points: format,
   * LAS header, scan stations; what savePointFile needs to write like it. */
  const io::PointFile&
  getDescription () const
  {
    return description_;
  }

  /** \brief Up to \a max_points further points into \a chunk (its content replaced).
   * \return the number read, 0 at the end \throw io::ReadError naming the file when the
   * points are truncated or corrupt */
  std::size_t
  read (std::size_t max_points, pcl::PCLPointCloud2& chunk);

  /** \brief Start again from the first point. */
  void
  rewind ();

private:
  std::string path_;
  std::unique_ptr<io::LasReader> las_;
  io::PointFile description_;
  pcl::PCLPointCloud2 whole_; ///< the points of a file that is not LAS / LAZ
  Eigen::Vector3d file_origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d min_, max_;
  std::uint64_t count_ = 0, next_ = 0;
};

/** \brief Byte offset of the x y z of a chunk's points (three consecutive FLOAT32
 * fields, as io::loadPointFile and io::LasReader give them). \throw
 * std::invalid_argument when the chunk has none */
std::size_t
xyzOffset (const pcl::PCLPointCloud2& chunk);
} // namespace tiling
} // namespace pcl_ext
