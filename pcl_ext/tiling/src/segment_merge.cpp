/*
 * pcl_ext: segments of tiles joined across their halos into global segment ids.
 */
#include <pcl_ext/tiling/segment_merge.h>

namespace pcl_ext {
namespace tiling {
std::uint32_t
SegmentMerge::element (Key key)
{
  const auto found = elements_.find (key);
  if (found != elements_.end())
    return found->second;
  const std::uint32_t e = sets_.add();
  elements_.emplace (key, e);
  return e;
}

void
SegmentMerge::join (Key owner, Key other)
{
  if (owner == kNoKey || other == kNoKey || owner == other)
    return;
  sets_.unite (element (owner), element (other));
}

std::uint32_t
SegmentMerge::number (Key owner)
{
  if (owner == kNoKey)
    return kNoSegment;
  const std::uint32_t root = sets_.find (element (owner));
  if (ids_.size() <= root)
    ids_.resize (sets_.size(), kNoSegment);
  if (ids_[root] == kNoSegment)
    ids_[root] = next_id_++;
  return ids_[root];
}
} // namespace tiling
} // namespace pcl_ext
