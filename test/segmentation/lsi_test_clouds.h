/*
 * Two half-planes meeting along a known line (a crease), or offset from each other (a
 * step), with segment labels and point classes for pcl_ext::LocalSurfaceIntersection
 * tests.
 */
#pragma once

#include <pcl_ext/point_types.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace lsi_test {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using LabelCloud = pcl::PointCloud<pcl::Label>;

/** Half-plane i (i = 0, 1) is origin + t * along + w * across[i] + offset[i], t in [0,
 * length], w in [0, width]; points nearer than \a band to the common line are edge
 * points. */
struct HalfPlanes {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::UnitX();
  Eigen::Vector3d across[2] = {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d offset[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double length = 1.0;
  double width = 0.5;
  double spacing_along = 0.02;
  double spacing_across = 0.02;
  double noise = 0.001; ///< Gaussian, along each half-plane's normal
  double band = 0.03;   ///< edge points within this distance of the line
  unsigned seed = 1;
};

struct Scene {
  Cloud::Ptr cloud{new Cloud};
  LabelCloud::Ptr segments{new LabelCloud}; ///< 1 and 2 for surface points, 0 for edges
  LabelCloud::Ptr classes{new LabelCloud};
  pcl::PointCloud<pcl::Normal>::Ptr normals{new pcl::PointCloud<pcl::Normal>};
  std::vector<std::uint32_t> truth;       ///< true segment of every point
  std::vector<Eigen::Vector3d> positions; ///< double-precision positions
};

inline Scene
makeHalfPlanes (const HalfPlanes& h)
{
  Scene s;
  std::mt19937 rng (h.seed);
  std::normal_distribution<double> noise (0.0, 1.0);
  std::uniform_real_distribution<double> jitter (-0.25, 0.25);
  const int nt = static_cast<int> (std::round (h.length / h.spacing_along));
  const int nw = static_cast<int> (std::round (h.width / h.spacing_across));
  for (int side = 0; side < 2; ++side) {
    const Eigen::Vector3d normal = h.along.cross (h.across[side]).normalized();
    for (int i = 0; i <= nt; ++i)
      for (int j = 0; j < nw; ++j) {
        // Jitter across only: positions along may need to stay on a float grid.
        const double w = (j + 0.5 + jitter (rng)) * h.spacing_across;
        const Eigen::Vector3d p = h.origin + i * h.spacing_along * h.along +
                                  w * h.across[side] + h.offset[side] +
                                  h.noise * noise (rng) * normal;
        s.positions.push_back (p);
        s.cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x()),
                                           static_cast<float> (p.y()),
                                           static_cast<float> (p.z())));
        const bool edge = w < h.band;
        pcl::Label c, l;
        c.label = static_cast<std::uint32_t> (edge ? pcl_ext::PointClass::Edge
                                                   : pcl_ext::PointClass::Surface);
        l.label = edge ? 0u : static_cast<std::uint32_t> (side + 1);
        s.classes->push_back (c);
        s.segments->push_back (l);
        s.truth.push_back (static_cast<std::uint32_t> (side + 1));
        s.normals->push_back (pcl::Normal (static_cast<float> (normal.x()),
                                           static_cast<float> (normal.y()),
                                           static_cast<float> (normal.z())));
      }
  }
  return s;
}

/** Distance from \a p to the line through \a origin along unit \a along. */
inline double
lineDistance (const Eigen::Vector3d& p,
              const Eigen::Vector3d& origin,
              const Eigen::Vector3d& along)
{
  const Eigen::Vector3d d = p - origin;
  return (d - d.dot (along) * along).norm();
}

inline double
median (std::vector<double> v)
{
  if (v.empty())
    return std::nan ("");
  auto mid = v.begin() + v.size() / 2;
  std::nth_element (v.begin(), mid, v.end());
  return *mid;
}
} // namespace lsi_test
