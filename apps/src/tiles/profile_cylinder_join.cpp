/*
 * pcl_ext_tiles segment_profiles: the cylinder join over the whole cloud's segments,
 * read one segment at a time.
 */
#include "profile_cylinder_join.h"

#include "segment_points_file.h"

#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <numeric>

namespace pcl_ext {
namespace apps {
namespace {
constexpr std::uint64_t kChunk = 1 << 20;
constexpr std::uint32_t kNone = tiling::TileResults::kNoResult;

/** The spacing the join's lengths follow: CylinderSegmentJoin's estimate over the
 * segments' points (profiles::estimatePointSpacing), which it holds while it estimates
 * (12 bytes a point, and 8 more while they are sorted along an axis); -1 when a file
 * cannot be read. */
double
estimateSpacing (const SegmentPointsFile& points)
{
  std::vector<Eigen::Vector3f> xyz;
  std::size_t total = 0;
  for (std::size_t s = 0; s < points.size(); ++s)
    total += points.pointCount (s);
  xyz.reserve (total);
  std::vector<Eigen::Vector3d> segment;
  for (std::size_t s = 0; s < points.size(); ++s) {
    if (!points.load (s, segment))
      return -1.0;
    for (const auto& p : segment)
      xyz.push_back (p.cast<float>());
  }
  return profiles::estimatePointSpacing (xyz);
}

/** The points that move with their pieces alone (their segment does not move whole):
 * global index and label, by index. */
bool
movedInliers (const SegmentPointsFile& points,
              const cylinder_join::SegmentJoin& join,
              std::vector<std::pair<std::uint64_t, std::uint32_t>>& moved)
{
  moved.clear();
  std::vector<std::uint64_t> indices;
  std::size_t loaded = std::numeric_limits<std::size_t>::max();
  for (const auto& piece : join.pieces) {
    if (piece.joined == cylinder_join::kNoSegment ||
        join.whole[piece.segment] != cylinder_join::kNoSegment)
      continue;
    if (piece.segment != loaded && !points.loadIndices (piece.segment, indices))
      return false;
    loaded = piece.segment;
    for (const auto i : piece.cylinder.inliers)
      moved.emplace_back (indices[i], piece.joined);
  }
  std::sort (moved.begin(), moved.end());
  return true;
}

/** Each point's label after the join, a chunk of the results at a time: \a visit
 * (first index, labels; kNone where the point is in no segment). */
template <typename Visit>
bool
forEachJoinedChunk (const std::string& workdir,
                    std::uint64_t total,
                    const cylinder_join::SegmentJoin& join,
                    const std::vector<std::pair<std::uint64_t, std::uint32_t>>& moved,
                    Visit visit)
{
  std::vector<std::uint32_t> ids;
  auto next_move = moved.begin();
  for (std::uint64_t first = 0; first < total; first += kChunk) {
    const auto n = static_cast<std::size_t> (std::min (kChunk, total - first));
    if (!tiling::TileResults::read (workdir, first, n, ids))
      return false;
    for (std::size_t k = 0; k < n; ++k) {
      if (ids[k] == kNone)
        continue;
      const std::uint64_t index = first + k;
      while (next_move != moved.end() && next_move->first < index)
        ++next_move;
      if (next_move != moved.end() && next_move->first == index)
        ids[k] = next_move->second;
      else if (join.whole[ids[k]] != cylinder_join::kNoSegment)
        ids[k] = join.whole[ids[k]];
    }
    visit (first, ids);
  }
  return true;
}
} // namespace

bool
joinProfileCylinders (const tiling::TilePlan& plan,
                      const ProfileParts& parts,
                      const ProfileOptions& options,
                      const std::string& workdir,
                      unsigned int threads,
                      std::uint32_t& segments,
                      std::size_t& cylinders)
{
  cylinders = 0;
  const std::uint64_t total = plan.getTotalPoints();
  std::vector<std::string> point_files;
  for (std::size_t p = 0; p < parts.firsts[0].size(); ++p)
    point_files.push_back (profilePartPath (workdir, 0, p, "points"));
  SegmentPointsFile points;
  if (!points.build (workdir, point_files, segments, total))
    return false;
  for (std::size_t s = 0; s < points.size(); ++s)
    if (points.pointCount (s) >
        static_cast<std::size_t> (std::numeric_limits<pcl::index_t>::max())) {
      std::cerr << "Error: the cylinder join fits segments of at most "
                << std::numeric_limits<pcl::index_t>::max()
                << " points (PCL's indices); segment " << s << " holds "
                << points.pointCount (s) << ".\n";
      return false;
    }

  // The settings as CylinderSegmentJoin resolves them.
  CylinderSegmentJoin<pcl::PointXYZ> settings = options.makeJoin();
  settings.setNumberOfThreads (threads);
  const double spacing =
      settings.getLengthsFollowSpacing() ? estimateSpacing (points) : 0.0;
  if (spacing < 0.0)
    return false;
  if (settings.getLengthsFollowSpacing() && !(spacing > 0.0)) {
    std::cerr << "Error: the point spacing of the segments cannot be estimated (fewer "
                 "than 7 distinct points); give the cylinder join's lengths.\n";
    return false;
  }
  const cylinder_join::JoinParameters parameters = settings.getParameters (spacing);
  if (!cylinder_join::validParameters (parameters)) {
    std::cerr << "Error: invalid cylinder join settings.\n";
    return false;
  }
  cylinder_join::SegmentJoin join;
  if (!cylinder_join::joinSegments (points, parameters, join)) {
    std::cerr << "Error: joining the cylinders failed.\n";
    return false;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> moved;
  if (!movedInliers (points, join, moved))
    return false;
  for (const auto& piece : join.pieces)
    cylinders += piece.joined != cylinder_join::kNoSegment;

  // The joined segments numbered as CylinderSegmentJoin numbers them: largest first,
  // ties by their first point.
  std::vector<std::uint64_t> sizes (join.labels, 0),
      firsts (join.labels, std::numeric_limits<std::uint64_t>::max());
  if (!forEachJoinedChunk (
          workdir,
          total,
          join,
          moved,
          [&] (std::uint64_t first, const std::vector<std::uint32_t>& labels) {
            for (std::size_t k = 0; k < labels.size(); ++k)
              if (labels[k] != kNone) {
                ++sizes[labels[k]];
                firsts[labels[k]] = std::min (firsts[labels[k]], first + k);
              }
          }))
    return false;
  std::vector<std::uint32_t> order;
  for (std::uint32_t label = 0; label < join.labels; ++label)
    if (sizes[label] > 0)
      order.push_back (label);
  std::sort (order.begin(), order.end(), [&] (std::uint32_t a, std::uint32_t b) {
    return sizes[a] != sizes[b] ? sizes[a] > sizes[b] : firsts[a] < firsts[b];
  });
  std::vector<std::uint32_t> rank (join.labels, kNone);
  for (std::size_t k = 0; k < order.size(); ++k)
    rank[order[k]] = static_cast<std::uint32_t> (k);
  segments = static_cast<std::uint32_t> (order.size());

  std::vector<std::uint64_t> indices;
  std::vector<std::uint32_t> values;
  bool written = true;
  if (!forEachJoinedChunk (
          workdir,
          total,
          join,
          moved,
          [&] (std::uint64_t first, const std::vector<std::uint32_t>& labels) {
            indices.resize (labels.size());
            std::iota (indices.begin(), indices.end(), first);
            values.resize (labels.size());
            for (std::size_t k = 0; k < labels.size(); ++k)
              values[k] = labels[k] == kNone ? kNone : rank[labels[k]];
            written = written && tiling::TileResults::write (workdir, indices, values);
          }))
    return false;
  return written;
}
} // namespace apps
} // namespace pcl_ext
