/*
 * pcl_ext: segments of tiles joined across their halos into global segment ids.
 */
#pragma once

#include <pcl_ext/common/union_find.h>

#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace pcl_ext {
namespace tiling {
/** \brief Joins the segments that tiles found into segments of the whole cloud.
 *
 * Each tile segments its core and halo points and numbers its segments from 0. A point
 * has one owner, the tile whose core holds it; other tiles may label it too, in their
 * halos. The owner's label is the point's label; a halo label only joins: when tile A
 * calls a point segment a and its owner B calls it b, a and b are one segment
 * (union-find). So a wall across the corner of four tiles is one segment, and a segment
 * that a tile saw only in its halo adds no segment of its own.
 *
 * Global ids are numbered from 0 in the order of the segments' first points (the
 * smallest global point index of each), so they depend neither on the order tiles were
 * run or joined in, nor on the number of processes: the ids of an untiled run
 * renumbered the same way are the same.
 *
 * \code
 * pcl_ext::tiling::SegmentMerge merge;
 * for (each point labelled in a halo)  // any order
 *   merge.join (SegmentMerge::key (owner, owner_label), SegmentMerge::key (tile,
 * label)); for (std::uint64_t i = 0; i < n; ++i) // point order id[i] = merge.number
 * (SegmentMerge::key (owner_of[i], owner_label[i])); \endcode
 */
class SegmentMerge {
public:
  using Key = std::uint64_t;
  static constexpr Key kNoKey = std::numeric_limits<Key>::max();
  static constexpr std::uint32_t kNoSegment = std::numeric_limits<std::uint32_t>::max();

  /** \brief The key of segment \a label of tile \a tile; kNoKey for kNoSegment (a point
   * no segment holds). */
  static Key
  key (std::uint32_t tile, std::uint32_t label)
  {
    return label == kNoSegment ? kNoKey : (static_cast<Key> (tile) << 32) | label;
  }

  /** \brief One point labelled \a owner by its owner tile and \a other by another tile:
   * the two segments are one. A kNoKey on either side joins nothing. */
  void
  join (Key owner, Key other);

  /** \brief Whether \a key is known: joined, or given points. */
  bool
  contains (Key key) const
  {
    return elements_.count (key) > 0;
  }

  /** \brief Segment \a key of a tile has \a points points in the tile's core, the
   * smallest global index among them \a first (what numberBySize() counts). */
  void
  addPoints (Key key, std::uint64_t points, std::uint64_t first);

  /** \brief Number the joined segments largest first, ties by their first points (the
   * order of pcl_ext's segmenters), and drop those of fewer than \a min_size points:
   * the sizes are the sums of addPoints() over the tiles' segments each joins. Call
   * after every join() and addPoints(); number() then gives these ids, in any order of
   * the points, and kNoSegment for a dropped segment. */
  void
  numberBySize (std::uint64_t min_size);

  /** \brief The global id of the point that its owner labelled \a owner, for the points
   * in ascending global order (each segment is numbered when its first point comes,
   * unless numberBySize() numbered them); kNoSegment for kNoKey. */
  std::uint32_t
  number (Key owner);

  /** \brief Segments numbered so far. */
  std::uint32_t
  getNumberOfSegments () const
  {
    return next_id_;
  }

private:
  std::uint32_t
  element (Key key);

  std::unordered_map<Key, std::uint32_t> elements_;
  UnionFind sets_;
  std::vector<std::uint32_t> ids_; ///< per root element, kNoSegment until numbered
  std::vector<std::uint64_t> points_, first_; ///< per element, from addPoints()
  std::uint32_t next_id_ = 0;
  bool by_size_ = false;
};
} // namespace tiling
} // namespace pcl_ext
