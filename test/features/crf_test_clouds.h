/*
 * Test clouds for the tests of Lim & Suter's method: super-voxels, saliency features,
 * CRF.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace crf_test {
/** A horizontal floor (z = 0, 4 x 4 m) meeting a vertical wall (x = 0), grid spacing
 * \a step, Gaussian noise \a sigma along the normal. Labels: floor 1, wall 2. */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
floorAndWall (double step,
              double sigma,
              std::vector<std::uint32_t>* labels = nullptr,
              std::uint64_t seed = 7)
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<float> noise (0.f, static_cast<float> (sigma));
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const int n = static_cast<int> (std::round (4.0 / step));
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      cloud->push_back (pcl::PointXYZ (
          static_cast<float> (i * step), static_cast<float> (j * step), noise (rng)));
      if (labels)
        labels->push_back (1);
    }
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      cloud->push_back (pcl::PointXYZ (
          noise (rng), static_cast<float> (j * step), static_cast<float> (i * step)));
      if (labels)
        labels->push_back (2);
    }
  return cloud;
}
} // namespace crf_test
