/*
 * pcl_ext: the inputs of a tiled run read back chunk by chunk with each point's merged
 * result.
 */
#include <pcl_ext/tiling/merged_results.h>
#include <pcl_ext/tiling/tile_results.h>

#include <pcl/console/print.h>

#include <cmath>
#include <cstring>

namespace pcl_ext {
namespace tiling {
static_assert (TileResults::kNoResult == SegmentMerge::kNoSegment,
               "a point without a result is a point without a segment");

bool
joinTileSegments (const TilePlan& plan,
                  const std::string& folder,
                  bool by_size,
                  std::uint64_t min_size,
                  SegmentMerge& merge,
                  const SegmentPassFiles& files)
{
  const std::size_t tiles = plan.getGrid().size();
  // The owners' labels of every halo point, read a tile at a time.
  std::vector<HaloLabel> halo;
  std::vector<std::uint64_t> indices;
  std::vector<std::uint32_t> owner_labels;
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!loadHaloLabels (folder, t, halo, files.halo))
      return false;
    indices.resize (halo.size());
    for (std::size_t i = 0; i < halo.size(); ++i)
      indices[i] = halo[i].index;
    if (!TileResults::readAt (folder, indices, owner_labels, files.results))
      return false;
    for (std::size_t i = 0; i < halo.size(); ++i)
      if (owner_labels[i] != TileResults::kNoResult)
        merge.join (SegmentMerge::key (halo[i].owner, owner_labels[i]),
                    SegmentMerge::key (static_cast<std::uint32_t> (t), halo[i].label));
  }
  if (!by_size)
    return true;
  std::vector<SegmentSize> sizes;
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!loadSegmentSizes (folder, t, sizes, files.sizes))
      return false;
    for (const auto& s : sizes) {
      const SegmentMerge::Key key =
          SegmentMerge::key (static_cast<std::uint32_t> (t), s.label);
      // A segment no halo joins keeps its own size: under min_size it is dropped
      // whatever happens, so it is not kept at all (number() gives kNoSegment for a
      // key it does not know). A scan's many small groups cost no memory then.
      if (s.points < min_size && !merge.contains (key))
        continue;
      merge.addPoints (key, s.points, s.first);
    }
  }
  merge.numberBySize (min_size);
  return true;
}

bool
MergedResults::open (const TilePlan& plan, const std::string& folder, Kind kind)
{
  plan_ = plan;
  grid_ = plan.getGrid();
  folder_ = folder;
  kind_ = kind;
  merge_ = SegmentMerge();
  grown_merge_ = SegmentMerge();
  file_.reset();
  input_ = 0;
  next_index_ = 0;
  failed_ = false;
  return (kind_ != Kind::Segments ||
          joinTileSegments (plan_, folder_, by_size_, min_size_, merge_)) &&
         (!grown_ ||
          joinTileSegments (
              plan_, folder_, true, grown_min_size_, grown_merge_, grown_files_));
}

std::size_t
MergedResults::read (std::size_t max_points,
                     pcl::PCLPointCloud2& chunk,
                     std::size_t& input,
                     std::vector<std::uint32_t>& values)
{
  values.clear();
  while (!failed_ && input_ < plan_.inputs.size()) {
    if (!file_) {
      file_ = std::make_unique<PointFileChunks>();
      file_->open (plan_.inputs[input_]);
      file_->setOrigin (plan_.origin);
    }
    const std::size_t n = file_->read (max_points, chunk);
    if (n == 0) {
      file_.reset();
      ++input_;
      continue;
    }
    input = input_;
    if (!TileResults::read (folder_, next_index_, n, values, results_name_)) {
      failed_ = true;
      return 0;
    }
    if (grown_ && !TileResults::read (
                      folder_, next_index_, n, grown_values_, grown_files_.results)) {
      failed_ = true;
      return 0;
    }
    if (kind_ == Kind::Segments || grown_) {
      const std::uint8_t* xyz = chunk.data.data() + xyzOffset (chunk);
      for (std::size_t i = 0; i < n; ++i) {
        float p[3];
        std::memcpy (p, xyz + i * chunk.point_step, sizeof (p));
        const std::size_t owner =
            grid_.getTile (plan_.origin.x() + p[0], plan_.origin.y() + p[1]);
        if (owner == TileGrid::kNoTile) {
          values[i] = SegmentMerge::kNoSegment;
          continue;
        }
        const auto tile = static_cast<std::uint32_t> (owner);
        if (kind_ == Kind::Segments && values[i] != TileResults::kNoResult)
          values[i] = merge_.number (SegmentMerge::key (tile, values[i]));
        // No segment (kNoResult is kNoSegment): the group a later pass grew, if any.
        if (grown_ && values[i] == SegmentMerge::kNoSegment &&
            grown_values_[i] != TileResults::kNoResult) {
          const std::uint32_t id =
              grown_merge_.number (SegmentMerge::key (tile, grown_values_[i]));
          if (id != SegmentMerge::kNoSegment)
            values[i] = grown_first_id_ + id;
        }
      }
    }
    next_index_ += n;
    return n;
  }
  return 0;
}
} // namespace tiling
} // namespace pcl_ext
