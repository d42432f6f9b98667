/*
 * pcl_ext_tiles segment_profiles: the cylinder join over the whole cloud's segments.
 */
#include "profile_cylinder_join.h"

#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace pcl_ext {
namespace apps {
namespace {
constexpr std::uint64_t kChunk = 1 << 20;
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
  if (total > static_cast<std::uint64_t> (std::numeric_limits<pcl::index_t>::max())) {
    std::cerr << "Error: the cylinder join indexes a cloud of at most "
              << std::numeric_limits<pcl::index_t>::max()
              << " points (PCL's indices), not " << total << ".\n";
    return false;
  }
  // The whole cloud as the untiled tool holds it: every point at its global index,
  // those that are not finite (in no part) NaN.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->resize (total, pcl::PointXYZ (nan, nan, nan));
  cloud->is_dense = false;
  std::vector<std::uint64_t> indices;
  pcl::PointCloud<pcl::PointXYZ> points;
  for (std::size_t p = 0; p < parts.firsts[0].size(); ++p) {
    if (!readProfilePart (profilePartPath (workdir, 0, p, "points"), indices, points))
      return false;
    for (std::size_t k = 0; k < indices.size(); ++k)
      (*cloud)[indices[k]] = points[k];
  }
  // The segments, each point's index ascending, as the segmenter lists them.
  std::vector<pcl::PointIndices> clusters (segments);
  std::vector<std::uint32_t> ids;
  for (std::uint64_t first = 0; first < total; first += kChunk) {
    const auto n = static_cast<std::size_t> (std::min (kChunk, total - first));
    if (!tiling::TileResults::read (workdir, first, n, ids))
      return false;
    for (std::size_t k = 0; k < n; ++k) {
      if (ids[k] == tiling::TileResults::kNoResult)
        continue;
      if (ids[k] >= segments) {
        std::cerr << "Error: the segments in " << workdir << " are broken.\n";
        return false;
      }
      clusters[ids[k]].indices.push_back (static_cast<pcl::index_t> (first + k));
    }
  }
  CylinderSegmentJoin<pcl::PointXYZ> join = options.makeJoin();
  join.setInputCloud (cloud);
  join.setInputSegments (clusters);
  join.setNumberOfThreads (threads);
  join.join (clusters);
  if (clusters.empty()) {
    std::cerr << "Error: joining the cylinders failed (see the message above).\n";
    return false;
  }
  for (const auto& c : join.getCylinders())
    cylinders += c.output_segment >= 0;
  cloud.reset();
  ids.assign (total, tiling::TileResults::kNoResult);
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const auto i : clusters[c].indices)
      ids[static_cast<std::size_t> (i)] = static_cast<std::uint32_t> (c);
  segments = static_cast<std::uint32_t> (clusters.size());
  clusters.clear();
  for (std::uint64_t first = 0; first < total; first += kChunk) {
    const std::uint64_t end = std::min (total, first + kChunk);
    indices.clear();
    std::vector<std::uint32_t> values;
    values.reserve (static_cast<std::size_t> (end - first));
    for (std::uint64_t i = first; i < end; ++i) {
      indices.push_back (i);
      values.push_back (ids[static_cast<std::size_t> (i)]);
    }
    if (!tiling::TileResults::write (workdir, indices, values))
      return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
