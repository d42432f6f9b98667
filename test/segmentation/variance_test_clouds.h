/*
 * Clouds and labels shared by the tests of the Belton & Lichti region growing: a cube's
 * faces, uniform classes, two patches side by side.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace test {
/** Which face of the cube [0, size]^3 a point lies on (1..6); points on an edge of the
 * cube get the face of the coordinate closest to a face plane. */
inline std::vector<std::uint32_t>
cubeFaces (const pcl::PointCloud<pcl::PointXYZ>& cloud, double size)
{
  std::vector<std::uint32_t> faces;
  for (const auto& p : cloud) {
    const double c[3] = {p.x, p.y, p.z};
    int best = 0;
    double best_d = 1e30;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        const double d = std::abs (c[axis] - side * size);
        if (d < best_d) {
          best_d = d;
          best = 2 * axis + side + 1;
        }
      }
    faces.push_back (static_cast<std::uint32_t> (best));
  }
  return faces;
}

inline pcl::PointCloud<pcl::Label>::Ptr
uniformClasses (std::size_t n, std::uint32_t c)
{
  pcl::PointCloud<pcl::Label>::Ptr labels (new pcl::PointCloud<pcl::Label>);
  labels->resize (n);
  for (auto& l : *labels)
    l.label = c;
  return labels;
}

/** Two unit squares side by side in z = 0 with a gap between them (spacing 0.05). */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
twoPatches (double gap)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (int patch = 0; patch < 2; ++patch)
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j)
        cloud->push_back (
            pcl::PointXYZ (static_cast<float> (patch * (1.0 + gap) + 0.05 * i),
                           static_cast<float> (0.05 * j),
                           0.f));
  return cloud;
}
} // namespace test
} // namespace pcl_ext
