/*
 * pcl_ext: adaptive super-voxel over-segmentation (Lim & Suter 2008, section 3.1).
 */
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/supervoxel_set.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcl_ext {
std::size_t
SupervoxelSet::countOverlappingPoints() const
{
  std::size_t count = 0;
  for (std::size_t i = 0; i + 1 < membership_offsets.size(); ++i)
    count += membership_offsets[i + 1] - membership_offsets[i] > 1;
  return count;
}

namespace {
// Candidates evaluated together; fixed so that results do not depend on the thread
// count.
constexpr std::size_t kBatch = 64;

void
buildMembership (std::size_t num_points, SupervoxelSet& set)
{
  std::vector<std::size_t> counts (num_points + 1, 0);
  for (const auto& sv : set.supervoxels)
    for (const auto i : sv.members)
      ++counts[static_cast<std::size_t> (i) + 1];
  std::partial_sum (counts.begin(), counts.end(), counts.begin());
  set.membership_offsets = counts;
  set.membership.resize (counts.back());
  std::vector<std::size_t> fill (counts.begin(), counts.end() - 1);
  for (std::size_t v = 0; v < set.supervoxels.size(); ++v)
    for (const auto i : set.supervoxels[v].members)
      set.membership[fill[static_cast<std::size_t> (i)]++] =
          static_cast<std::uint32_t> (v);
}

void
buildAdjacency (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                int l,
                int threads,
                SupervoxelSet& set)
{
  const std::size_t n = set.supervoxels.size();
  set.adjacency.assign (n, {});
  if (l <= 0 || n < 2)
    return;
  std::vector<float> xyz;
  std::vector<pcl::index_t> ids (n);
  xyz.reserve (3 * n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto& p = cloud[static_cast<std::size_t> (set.supervoxels[v].seed)];
    xyz.insert (xyz.end(), {p.x, p.y, p.z});
    ids[v] = static_cast<pcl::index_t> (v);
  }
  search::KdTree3f tree;
  tree.build (xyz, ids);
  const std::size_t k = std::min<std::size_t> (static_cast<std::size_t> (l) + 1, n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t v = 0; v < static_cast<std::ptrdiff_t> (n); ++v) {
    pcl::Indices nn (k);
    std::vector<float> d2 (k);
    const std::size_t found =
        tree.nearestKSearch (&xyz[3 * v], k, nn.data(), d2.data());
    for (std::size_t j = 0; j < found; ++j)
      if (nn[j] != v && set.adjacency[v].size() < static_cast<std::size_t> (l))
        set.adjacency[v].push_back (static_cast<std::uint32_t> (nn[j]));
  }
}
} // namespace

bool
computeAdaptiveSupervoxels (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                            const std::vector<Eigen::Vector3f>& colours,
                            const SupervoxelParameters& parameters,
                            SupervoxelSet& result,
                            AdaptiveRadiusEstimator* estimator_out)
{
  result.clear();
  if (!cloud || cloud->empty()) {
    PCL_ERROR ("[pcl_ext::computeAdaptiveSupervoxels] Empty input cloud.\n");
    return false;
  }
  if (parameters.adjacency < 0) {
    PCL_ERROR ("[pcl_ext::computeAdaptiveSupervoxels] The number of regional "
               "neighbours l must "
               "be >= 0 (got %d).\n",
               parameters.adjacency);
    return false;
  }
  AdaptiveRadiusEstimator local_estimator;
  AdaptiveRadiusEstimator& estimator = estimator_out ? *estimator_out : local_estimator;
  if (!estimator.initialize (cloud, colours, parameters.radius))
    return false;

  // The order in which points are offered as mid-points: by a seeded hash of each
  // point's coordinates (ties, coincident points, by index). A random permutation, but
  // one that belongs to the points: any part of the cloud (a tile with its halo) offers
  // its points in the same relative order as the whole cloud, so its super-voxels away
  // from its edge are the whole cloud's.
  std::vector<std::pair<std::uint64_t, pcl::index_t>> keyed;
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const auto& p = (*cloud)[i];
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      keyed.emplace_back (hashPosition (p.x, p.y, p.z, parameters.seed),
                          static_cast<pcl::index_t> (i));
  }
  std::sort (keyed.begin(), keyed.end());
  std::vector<pcl::index_t> order (keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i)
    order[i] = keyed[i].second;
  keyed = {};

  std::vector<char> assigned (cloud->size(), 0);
  const int threads = static_cast<int> (resolveThreadCount (parameters.threads));
  std::vector<Supervoxel> batch;
  std::size_t next = 0;
  while (next < order.size()) {
    batch.clear();
    for (; next < order.size() && batch.size() < kBatch; ++next)
      if (!assigned[static_cast<std::size_t> (order[next])]) {
        batch.emplace_back();
        batch.back().seed = order[next];
      }
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t> (batch.size()); ++b) {
      Supervoxel& sv = batch[b];
      sv.radius = estimator.estimate (sv.seed, &sv.steps);
      estimator.neighbours (sv.seed, sv.radius, sv.members);
    }
    // Accept in draw order: a candidate that an earlier one in this batch already
    // covers is dropped, exactly as if the candidates had been processed one by one.
    for (auto& sv : batch) {
      if (assigned[static_cast<std::size_t> (sv.seed)])
        continue;
      for (const auto i : sv.members)
        assigned[static_cast<std::size_t> (i)] = 1;
      result.supervoxels.push_back (std::move (sv));
    }
  }
  buildMembership (cloud->size(), result);
  buildAdjacency (*cloud, parameters.adjacency, threads, result);
  return true;
}
} // namespace pcl_ext
