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
  NoiseSampleCut cut;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const PointT& p = cloud[i];
    if (!pcl::isFinite (p))
      continue;
    xyz.insert (xyz.end(), {p.x, p.y, p.z});
    ids.push_back (static_cast<pcl::index_t> (i));
    cut.add (noiseSampleKeyOf (p.x, p.y, p.z));
  }
  if (k < 4 || ids.size() < static_cast<std::size_t> (k)) {
    none.reason = "fewer than " + std::to_string (std::max (k, 4)) + " finite points";
    return none;
  }
  std::vector<pcl::index_t> sample;
  for (const auto i : ids) {
    const PointT& p = cloud[static_cast<std::size_t> (i)];
    if (noiseSampleKeyOf (p.x, p.y, p.z) <= cut.get())
      sample.push_back (i);
  }
  const unsigned int used_threads = resolveThreadCount (threads);
  search::KdTree3f tree;
  tree.build (std::move (xyz), std::move (ids), 24, used_threads);
  std::vector<KeyedSpread> spreads (sample.size());
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (sample.size());
  const std::size_t kk = static_cast<std::size_t> (k);
#pragma omp parallel num_threads(used_threads) default(none)                           \
    shared(cloud, sample, spreads, count, kk, tree)
  {
    std::vector<pcl::index_t> nn (kk);
    std::vector<float> d2 (kk);
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t s = 0; s < count; ++s) {
      const PointT& p = cloud[static_cast<std::size_t> (sample[s])];
      const float q[3] = {p.x, p.y, p.z};
      const std::size_t found = tree.nearestKSearch (q, kk, nn.data(), d2.data());
      Eigen::Matrix3d covariance;
      Eigen::Vector3d centroid;
      EigenDecomposition eigen;
      KeyedSpread& out = spreads[static_cast<std::size_t> (s)];
      out.key = noiseSampleKeyOf (p.x, p.y, p.z);
      if (computeLocalCovariance (
              cloud, nn.begin(), nn.begin() + found, covariance, centroid) < 4 ||
          !computeEigenDecomposition (covariance, eigen))
        continue; // an empty spread: not usable
      out.spread.values = eigen.values;
      out.spread.size = found;
    }
  }
  return estimateNoiseFromSample (std::move (spreads));
}

#define PCL_EXT_INSTANTIATE_estimateCloudNoise(T)                                      \
  template pcl_ext::NoiseEstimate pcl_ext::estimateCloudNoise<T> (                     \
      const pcl::PointCloud<T>&, int, unsigned int);
