/*
 * pcl_ext: estimateCloudNoise.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/search/cloud_noise.h>
#include <pcl_ext/search/kdtree_3f.h>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

template <typename PointT>
pcl_ext::NoiseEstimate
pcl_ext::estimateCloudNoise (const pcl::PointCloud<PointT>& cloud,
                             int k,
                             unsigned int threads)
{
  NoiseEstimate none;
  std::vector<float> xyz;
  std::vector<pcl::index_t> ids;
  std::vector<std::uint64_t> keys;
  NoiseSampleCut cut;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const PointT& p = cloud[i];
    if (!pcl::isFinite (p))
      continue;
    xyz.insert (xyz.end(), {p.x, p.y, p.z});
    ids.push_back (static_cast<pcl::index_t> (i));
    keys.push_back (noiseSampleKeyOf (p.x, p.y, p.z));
    cut.add (keys.back());
  }
  if (k < 4 || ids.size() < static_cast<std::size_t> (k)) {
    none.reason = "fewer than " + std::to_string (std::max (k, 4)) + " finite points";
    return none;
  }
  // The sample (key at most the cut), copies of one position next to each other: the
  // key is a hash of the position, so all copies of a point are in the sample or none
  // is, and they have the same neighbours (the k of smallest index among equals), so
  // each position is searched once (a stack of m copies would cost m searches of m).
  struct Sampled {
    std::uint64_t key;
    pcl::index_t index;
  };
  std::vector<Sampled> sample;
  for (std::size_t j = 0; j < ids.size(); ++j)
    if (keys[j] <= cut.get())
      sample.push_back ({keys[j], ids[j]});
  const auto position = [&cloud] (pcl::index_t i) {
    const PointT& p = cloud[static_cast<std::size_t> (i)];
    return std::make_tuple (p.x, p.y, p.z);
  };
  std::sort (sample.begin(), sample.end(), [&] (const Sampled& a, const Sampled& b) {
    return std::make_tuple (a.key, position (a.index), a.index) <
           std::make_tuple (b.key, position (b.index), b.index);
  });
  std::vector<std::size_t> first_of_position;
  for (std::size_t s = 0; s < sample.size(); ++s)
    if (s == 0 || sample[s].key != sample[s - 1].key ||
        position (sample[s].index) != position (sample[s - 1].index))
      first_of_position.push_back (s);
  const unsigned int used_threads = resolveThreadCount (threads);
  search::KdTree3f tree;
  tree.build (std::move (xyz), std::move (ids), 24, used_threads);
  std::vector<KeyedSpread> spreads (sample.size());
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (first_of_position.size());
  const std::size_t kk = static_cast<std::size_t> (k);
#pragma omp parallel num_threads(used_threads) default(none)                           \
    shared(cloud, sample, first_of_position, spreads, count, kk, tree)
  {
    std::vector<pcl::index_t> nn (kk);
    std::vector<float> d2 (kk);
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t f = 0; f < count; ++f) {
      const std::size_t s = first_of_position[static_cast<std::size_t> (f)];
      const std::size_t end =
          static_cast<std::size_t> (f) + 1 < first_of_position.size()
              ? first_of_position[static_cast<std::size_t> (f) + 1]
              : sample.size();
      const PointT& p = cloud[static_cast<std::size_t> (sample[s].index)];
      const float q[3] = {p.x, p.y, p.z};
      const std::size_t found = tree.nearestKSearch (q, kk, nn.data(), d2.data());
      Eigen::Matrix3d covariance;
      Eigen::Vector3d centroid;
      EigenDecomposition eigen;
      KeyedSpread spread;
      spread.key = sample[s].key;
      if (computeLocalCovariance (
              cloud, nn.begin(), nn.begin() + found, covariance, centroid) >= 4 &&
          computeEigenDecomposition (covariance, eigen)) {
        spread.spread.values = eigen.values;
        spread.spread.size = found;
      } // else an empty spread: not usable
      std::fill (spreads.begin() + s, spreads.begin() + end, spread);
    }
  }
  return estimateNoiseFromSample (std::move (spreads));
}

#define PCL_EXT_INSTANTIATE_estimateCloudNoise(T)                                      \
  template pcl_ext::NoiseEstimate pcl_ext::estimateCloudNoise<T> (                     \
      const pcl::PointCloud<T>&, int, unsigned int);
