/*
 * pcl_ext_tiles segment_profiles: what runs on each part and what joins the parts.
 */
#include "profile_part_steps.h"

#include <pcl_ext/segmentation/profile_part_segmentation.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <numeric>

namespace pcl_ext {
namespace apps {
namespace {
std::string
gapsName (std::size_t stack)
{
  return "profiles_gaps_" + std::to_string (stack);
}

} // namespace

/** Part \a i's points and the segmentation set up for them as \a pass says. */
bool
setUpPart (const ProfileFrame& frame,
           const ProfileParts& parts,
           const ProfileOptions& options,
           const PartPass& pass,
           const std::string& workdir,
           unsigned int threads,
           std::size_t i,
           std::size_t& stack,
           std::vector<std::uint64_t>& indices,
           ProfilePartSegmentation<pcl::PointXYZ>& seg)
{
  std::size_t part;
  parts.locate (i, stack, part);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (!readProfilePart (
          profilePartPath (workdir, stack, part, "points"), indices, *cloud))
    return false;
  options.apply (seg, threads);
  if (pass.first_automatic) // AutoProfileSegmentation's first run
    seg.setProfileSegmentation (ProfileOptions::Segmentation::ProfileMethod::Proximity);
  seg.setLocalThreshold (pass.local_threshold);
  if (pass.local_threshold && !pass.mean_gaps.empty())
    seg.setStackMeanGaps ({pass.mean_gaps[stack]});
  seg.setMinClusterSize (1); // the sizes count over all parts, at the merge
  seg.setStackNormals ({frame.normals[stack]});
  if (frame.spacing > 0.0)
    seg.setPointSpacing (frame.spacing);
  seg.setCloudFrame (frame.centre, {frame.origins[stack]});
  seg.setInputCloud (cloud);
  return true;
}

bool
writePartFile (const std::string& path, const void* data, std::size_t bytes)
{
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen (partial.c_str(), "wb");
  const bool written =
      file && (bytes == 0 || std::fwrite (data, 1, bytes, file) == bytes);
  if (!file || std::fclose (file) != 0 || !written ||
      std::rename (partial.c_str(), path.c_str()) != 0) {
    std::cerr << "Error: cannot write " << path << " (disk full?).\n";
    std::remove (partial.c_str());
    return false;
  }
  return true;
}

bool
forEachPartLink (const std::string& path,
                 std::uint64_t points,
                 const std::function<void (std::uint64_t, std::uint64_t)>& visit)
{
  std::FILE* file = std::fopen (path.c_str(), "rb");
  if (!file) {
    std::cerr << "Error: " << path << " is missing: that part has not run.\n";
    return false;
  }
  // An even number of indices a read, so that a pair never straddles two.
  std::vector<std::uint64_t> buffer (1 << 16);
  std::size_t n;
  bool ok = true;
  while (ok && (n = std::fread (
                    buffer.data(), sizeof (std::uint64_t), buffer.size(), file)) > 0) {
    ok = n % 2 == 0;
    for (std::size_t k = 0; ok && k < n; k += 2) {
      ok = buffer[k] < points && buffer[k + 1] < points;
      if (ok)
        visit (buffer[k], buffer[k + 1]);
    }
  }
  ok = ok && !std::ferror (file);
  std::fclose (file);
  if (!ok)
    std::cerr << "Error: " << path << " is broken.\n";
  return ok;
}

bool
createGapFiles (const std::string& workdir, std::size_t stacks, std::uint64_t points)
{
  for (std::size_t s = 0; s < stacks; ++s)
    if (!tiling::TileResults::create (workdir, points, gapsName (s)))
      return false;
  return true;
}

bool
computePartGaps (const ProfileFrame& frame,
                 const ProfileParts& parts,
                 const ProfileOptions& options,
                 const PartPass& pass,
                 const std::string& workdir,
                 unsigned int threads,
                 std::size_t i)
{
  std::size_t stack;
  std::vector<std::uint64_t> indices;
  ProfilePartSegmentation<pcl::PointXYZ> seg;
  PartPass gaps_pass = pass;
  gaps_pass.local_threshold = true;
  gaps_pass.mean_gaps.clear();
  std::vector<std::vector<float>> gaps;
  if (!setUpPart (
          frame, parts, options, gaps_pass, workdir, threads, i, stack, indices, seg))
    return false;
  if (!seg.computeLocalGaps (gaps) || gaps.size() != 1) {
    std::cerr << "Error: the local gaps of part " << i << " failed (see the message "
              << "above).\n";
    return false;
  }
  std::vector<std::uint32_t> bits (indices.size());
  std::memcpy (bits.data(), gaps[0].data(), bits.size() * sizeof (float));
  if (!tiling::TileResults::write (workdir, indices, bits, gapsName (stack)))
    return false;
  std::size_t part;
  parts.locate (i, stack, part);
  const double longest = seg.getUsedMaxThreshold();
  return writePartFile (
      profilePartPath (workdir, stack, part, "gaps"), &longest, sizeof (longest));
}

bool
reduceGaps (const tiling::TilePlan& plan,
            const ProfileParts& parts,
            const std::string& workdir,
            std::vector<double>& mean_gaps)
{
  mean_gaps.assign (parts.firsts.size(), 0.0);
  const std::uint64_t total = plan.getTotalPoints();
  std::vector<std::uint32_t> bits;
  for (std::size_t s = 0; s < parts.firsts.size(); ++s) {
    double longest = 0.0;
    for (std::size_t p = 0; p < parts.firsts[s].size(); ++p) {
      const std::string path = profilePartPath (workdir, s, p, "gaps");
      std::ifstream in (path, std::ios::binary);
      double value = 0.0;
      if (!in.read (reinterpret_cast<char*> (&value), sizeof (value)) ||
          (p > 0 && value != longest)) {
        std::cerr << "Error: " << path << " is missing or broken: that part's gaps "
                  << "have not run.\n";
        return false;
      }
      longest = value;
    }
    // As runProfileSegmentation: the gaps at the longest threshold (no neighbour
    // within reach) left out; a point that is not finite has none (NaN).
    const float cap = static_cast<float> (longest);
    double sum = 0.0;
    std::uint64_t count = 0;
    for (std::uint64_t first = 0; first < total; first += 1 << 20) {
      const std::size_t n =
          static_cast<std::size_t> (std::min<std::uint64_t> (1 << 20, total - first));
      if (!tiling::TileResults::read (workdir, first, n, bits, gapsName (s)))
        return false;
      for (const std::uint32_t b : bits) {
        float g;
        std::memcpy (&g, &b, sizeof (g));
        if (g < cap) {
          sum += g;
          ++count;
        }
      }
    }
    mean_gaps[s] = count ? sum / static_cast<double> (count) : 0.0;
  }
  return true;
}

bool
segmentPart (const ProfileFrame& frame,
             const ProfileParts& parts,
             const ProfileOptions& options,
             const PartPass& pass,
             const std::string& workdir,
             unsigned int threads,
             std::size_t i)
{
  std::size_t stack, part;
  std::vector<std::uint64_t> indices;
  ProfilePartSegmentation<pcl::PointXYZ> seg;
  if (!setUpPart (
          frame, parts, options, pass, workdir, threads, i, stack, indices, seg))
    return false;
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  if (clusters.empty() && !indices.empty()) {
    std::cerr << "Error: part " << i << " (stack " << stack << ") failed (see the "
              << "message above).\n";
    return false;
  }
  std::vector<std::uint64_t> links;
  for (const auto& c : clusters)
    for (std::size_t k = 1; k < c.indices.size(); ++k) {
      links.push_back (indices[c.indices[k]]);
      links.push_back (indices[c.indices.front()]);
    }
  parts.locate (i, stack, part);
  return writePartFile (profilePartPath (workdir, stack, part, "links"),
                        links.data(),
                        links.size() * sizeof (std::uint64_t));
}

bool
markFinitePoints (const ProfileParts& parts,
                  const std::string& workdir,
                  std::vector<std::uint32_t>& flags)
{
  std::vector<std::uint64_t> indices;
  pcl::PointCloud<pcl::PointXYZ> unused;
  // Every finite point lies in one part of the first stack.
  for (std::size_t p = 0; p < parts.firsts[0].size(); ++p) {
    if (!readProfilePart (profilePartPath (workdir, 0, p, "points"), indices, unused))
      return false;
    for (const auto i : indices)
      flags[i] = 1;
  }
  return true;
}

bool
joinParts (const tiling::TilePlan& plan,
           const ProfileParts& parts,
           const std::string& workdir,
           JoinedParts& joined)
{
  const std::uint64_t total = plan.getTotalPoints();
  joined.sets = UnionFind (total);
  joined.size.assign (total, 0);
  joined.largest = 0;
  if (!markFinitePoints (parts, workdir, joined.size))
    return false;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::size_t s, p;
    parts.locate (i, s, p);
    if (!forEachPartLink (profilePartPath (workdir, s, p, "links"),
                          total,
                          [&joined] (std::uint64_t a, std::uint64_t b) {
                            joined.sets.unite (static_cast<std::uint32_t> (a),
                                               static_cast<std::uint32_t> (b));
                          }))
      return false;
  }
  countComponents (joined);
  return true;
}

void
countComponents (JoinedParts& joined)
{
  const std::uint64_t total = joined.sets.size();
  for (std::uint32_t i = 0; i < total; ++i)
    if (joined.size[i]) {
      const std::uint32_t root = joined.sets.find (i);
      if (root != i) { // the root, smaller, was counted before
        joined.size[root] += 1;
        joined.size[i] = 0;
      }
    }
  joined.largest = 0;
  for (const std::uint32_t s : joined.size)
    joined.largest = std::max (joined.largest, s);
}

bool
saveSegments (const std::string& workdir,
              std::uint64_t min_size,
              JoinedParts& joined,
              std::uint32_t& segments)
{
  const std::uint64_t total = joined.sets.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> kept; // (size, first point)
  for (std::uint32_t i = 0; i < total; ++i)
    if (joined.size[i] > 0 && joined.size[i] >= min_size)
      kept.emplace_back (joined.size[i], i);
  std::sort (kept.begin(), kept.end(), [] (const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  // size[] becomes each root's segment id: none for the points that are not finite
  // (their own roots) and for the segments dropped.
  std::vector<std::uint32_t>& id = joined.size;
  std::fill (id.begin(), id.end(), tiling::TileResults::kNoResult);
  for (std::size_t k = 0; k < kept.size(); ++k)
    id[kept[k].second] = static_cast<std::uint32_t> (k);
  segments = static_cast<std::uint32_t> (kept.size());
  if (!tiling::TileResults::create (workdir, total))
    return false;
  std::vector<std::uint64_t> indices;
  std::vector<std::uint32_t> values;
  for (std::uint64_t first = 0; first < total; first += 1 << 20) {
    const std::uint64_t end = std::min<std::uint64_t> (total, first + (1 << 20));
    indices.clear();
    values.clear();
    for (std::uint64_t i = first; i < end; ++i) {
      indices.push_back (i);
      values.push_back (id[joined.sets.find (static_cast<std::uint32_t> (i))]);
    }
    if (!tiling::TileResults::write (workdir, indices, values))
      return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
