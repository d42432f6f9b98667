/*
 * pcl_ext: segments of tiles joined across their halos into global segment ids.
 */
#include <pcl_ext/tiling/segment_merge.h>

#include <algorithm>

namespace pcl_ext {
namespace tiling {
namespace {
constexpr std::uint64_t kNoFirst = ~std::uint64_t (0);
} // namespace

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

void
SegmentMerge::addPoints (Key key, std::uint64_t points, std::uint64_t first)
{
  if (key == kNoKey)
    return;
  const std::uint32_t e = element (key);
  if (points_.size() <= e) {
    points_.resize (sets_.size(), 0);
    first_.resize (sets_.size(), kNoFirst);
  }
  points_[e] += points;
  first_[e] = std::min (first_[e], first);
}

void
SegmentMerge::numberBySize (std::uint64_t min_size)
{
  const std::size_t n = sets_.size();
  points_.resize (n, 0);
  first_.resize (n, kNoFirst);
  // Each element's points to its root; then the roots ranked.
  for (std::uint32_t e = 0; e < n; ++e) {
    const std::uint32_t root = sets_.find (e);
    if (root == e)
      continue;
    points_[root] += points_[e];
    first_[root] = std::min (first_[root], first_[e]);
    points_[e] = 0;
  }
  std::vector<std::uint32_t> kept;
  for (std::uint32_t e = 0; e < n; ++e)
    if (points_[e] > 0 && points_[e] >= min_size)
      kept.push_back (e);
  std::sort (kept.begin(), kept.end(), [this] (std::uint32_t a, std::uint32_t b) {
    return points_[a] != points_[b] ? points_[a] > points_[b] : first_[a] < first_[b];
  });
  ids_.assign (n, kNoSegment);
  for (std::size_t i = 0; i < kept.size(); ++i)
    ids_[kept[i]] = static_cast<std::uint32_t> (i);
  next_id_ = static_cast<std::uint32_t> (kept.size());
  by_size_ = true;
}

std::uint32_t
SegmentMerge::number (Key owner)
{
  if (owner == kNoKey)
    return kNoSegment;
  if (by_size_) {
    const auto found = elements_.find (owner);
    return found == elements_.end() ? kNoSegment : ids_[sets_.find (found->second)];
  }
  const std::uint32_t root = sets_.find (element (owner));
  if (ids_.size() <= root)
    ids_.resize (sets_.size(), kNoSegment);
  if (ids_[root] == kNoSegment)
    ids_[root] = next_id_++;
  return ids_[root];
}
} // namespace tiling
} // namespace pcl_ext
