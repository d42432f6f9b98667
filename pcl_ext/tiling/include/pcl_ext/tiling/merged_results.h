/*
 * pcl_ext: the inputs of a tiled run read back chunk by chunk with each point's merged
 * result.
 */
#pragma once

#include <pcl_ext/tiling/point_file_chunks.h>
#include <pcl_ext/tiling/segment_merge.h>
#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_results.h>

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief Join the segments of the tiles of \a plan in \a folder into \a merge: every
 * halo point's label in a tile with its owner's (SegmentMerge::join); with \a by_size,
 * the tiles' segment sizes added and the joined segments numbered largest first, those
 * under \a min_size points dropped (SegmentMerge::numberBySize). \a files: those of
 * the pass whose segments are joined (default: the tiles' own). \return false
 * (PCL_ERROR names it) when a tile was not run or a file is broken */
bool
joinTileSegments (const TilePlan& plan,
                  const std::string& folder,
                  bool by_size,
                  std::uint64_t min_size,
                  SegmentMerge& merge,
                  const SegmentPassFiles& files = SegmentPassFiles());

/** \brief The points of a tiled run's inputs, in chunks, with their results: what the
 * merge step writes out.
 *
 * For per-point results (classes) a point's result is what its owner tile wrote
 * (TileResults; kNoResult for a point no tile holds: not finite). For segments the
 * owners' labels are joined across the halos first (SegmentMerge over every tile's
 * halo labels), then numbered 0, 1, ... in the order of the segments' first points
 * (or largest first, setSegmentsBySize); SegmentMerge::kNoSegment for a point in no
 * segment. Either way the values depend
 * neither on the tile size, nor on the order or the number of the processes that ran
 * the tiles. */
class MergedResults {
public:
  enum class Kind { PerPoint, Segments };

  /** \brief For segments: number them largest first (ties by first point), as pcl_ext's
   * segmenters do, and drop those of fewer than \a min_size points, counted over the
   * whole cloud (the tiles' segment sizes joined); call before open(). Default:
   * numbered by first point, none dropped. */
  void
  setSegmentsBySize (std::uint64_t min_size)
  {
    by_size_ = true;
    min_size_ = min_size;
  }

  /** \brief For per-point results: read those named \a name (TileResults) rather than
   * the tiles' own results; call before open(). */
  void
  setResultsName (const std::string& name)
  {
    results_name_ = name;
  }

  /** \brief New segments grown by a later pass among the points the results leave
   * without one (the pass's \a files): a point whose result is none takes the group
   * its owner gave it there, the groups joined across the tiles and numbered largest
   * first from \a first_id, those under \a min_size points dropped; call before
   * open(). */
  void
  setGrownSegments (const SegmentPassFiles& files,
                    std::uint64_t min_size,
                    std::uint32_t first_id)
  {
    grown_ = true;
    grown_files_ = files;
    grown_min_size_ = min_size;
    grown_first_id_ = first_id;
  }

  /** \brief After open() with setSegmentsBySize: the number of segments kept. */
  std::uint32_t
  getNumberOfSegments () const
  {
    return merge_.getNumberOfSegments();
  }

  /** \brief Prepare to read the results of \a plan in \a folder. \return false
   * (PCL_ERROR names it) when a tile was not run (its halo labels are missing) or a
   * file is broken \throw io::ReadError naming an input that cannot be read */
  bool
  open (const TilePlan& plan, const std::string& folder, Kind kind);

  /** \brief The next chunk of at most \a max_points points of the inputs (fields of
   * io::loadPointFile, x y z relative to the plan's origin), its input's index in
   * \a input, and one value per point in \a values. \return the number of points, 0 at
   * the end or on error (see failed()) */
  std::size_t
  read (std::size_t max_points,
        pcl::PCLPointCloud2& chunk,
        std::size_t& input,
        std::vector<std::uint32_t>& values);

  /** \brief The global index of the first point the next read() returns (after a
   * read() of n points, that chunk began n before). */
  std::uint64_t
  getNextIndex () const
  {
    return next_index_;
  }

  /** \brief Whether reading stopped on an error (PCL_ERROR said which). */
  bool
  failed () const
  {
    return failed_;
  }

private:
  TilePlan plan_;
  TileGrid grid_;
  std::string folder_;
  Kind kind_ = Kind::PerPoint;
  SegmentMerge merge_;
  std::unique_ptr<PointFileChunks> file_;
  std::size_t input_ = 0;
  std::uint64_t next_index_ = 0;
  bool failed_ = false;
  bool by_size_ = false;
  std::uint64_t min_size_ = 1;
  std::string results_name_ = TileResults::kResults;
  bool grown_ = false;
  SegmentPassFiles grown_files_;
  SegmentMerge grown_merge_;
  std::uint64_t grown_min_size_ = 1;
  std::uint32_t grown_first_id_ = 0;
  std::vector<std::uint32_t> grown_values_;
};
} // namespace tiling
} // namespace pcl_ext
