/*
 * Analytic test clouds with exact ground truth: planes, boxes and cylinders whose edges
 * and borders are known in closed form.
 */
#pragma once

#include <pcl_ext/point_types.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace pcl_ext {
namespace test {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** A sampled shape and, per point, its distance to the nearest crease and to the
 * nearest open border (infinity when it has none). */
struct AnalyticCloud {
  Cloud::Ptr cloud{new Cloud};
  std::vector<double> crease_distance;
  std::vector<double> border_distance;
  double spacing = 0.0;

  void
  add (double x, double y, double z, double crease, double border)
  {
    cloud->push_back (pcl::PointXYZ (
        static_cast<float> (x), static_cast<float> (y), static_cast<float> (z)));
    crease_distance.push_back (crease);
    border_distance.push_back (border);
  }

  /** Ground-truth classes: edge within \a band of a crease, else boundary within \a
   * band of a border, else surface. */
  std::vector<std::uint32_t>
  truth (double band) const
  {
    std::vector<std::uint32_t> t (cloud->size());
    for (std::size_t i = 0; i < t.size(); ++i)
      t[i] = static_cast<std::uint32_t> (crease_distance[i] <= band ? PointClass::Edge
                                         : border_distance[i] <= band
                                             ? PointClass::Boundary
                                             : PointClass::Surface);
    return t;
  }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

/** Square [0, size]^2 at z = 0 on a grid of \a spacing, each point jittered in the
 * plane by up to \a jitter spacings (uniform) and in z by Gaussian \a noise; borders on
 * all sides. */
inline AnalyticCloud
makePlane (double size,
           double spacing,
           double jitter = 0.0,
           double noise = 0.0,
           unsigned seed = 1)
{
  AnalyticCloud a;
  a.spacing = spacing;
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (-0.5 * jitter * spacing,
                                            0.5 * jitter * spacing);
  std::normal_distribution<double> g (0.0, noise > 0 ? noise : 1.0);
  const int n = static_cast<int> (std::round (size / spacing));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = std::clamp (i * spacing + u (rng), 0.0, size);
      const double y = std::clamp (j * spacing + u (rng), 0.0, size);
      const double z = noise > 0 ? g (rng) : 0.0;
      const double border = std::min (std::min (x, size - x), std::min (y, size - y));
      a.add (x, y, z, kInf, border);
    }
  a.cloud->width = static_cast<std::uint32_t> (a.cloud->size());
  a.cloud->height = 1;
  a.cloud->is_dense = true;
  return a;
}

/** Closed cube [0, size]^3: each face a grid of \a spacing (shared edge rows once),
 * Gaussian noise along the face normal. Creases on the 12 edges; no border. */
inline AnalyticCloud
makeCube (double size, double spacing, double noise = 0.0, unsigned seed = 1)
{
  AnalyticCloud a;
  a.spacing = spacing;
  std::mt19937 rng (seed);
  std::normal_distribution<double> g (0.0, noise > 0 ? noise : 1.0);
  const int n = static_cast<int> (std::round (size / spacing));
  const double h = size / n;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const int on_faces =
            (i == 0 || i == n) + (j == 0 || j == n) + (k == 0 || k == n);
        if (on_faces == 0)
          continue;
        double p[3] = {i * h, j * h, k * h};
        // Noise along the normal of one face the point lies on (creases stay creases).
        if (noise > 0 && on_faces == 1) {
          const int axis = (i == 0 || i == n) ? 0 : (j == 0 || j == n) ? 1 : 2;
          p[axis] += g (rng);
        }
        // Distance to the nearest cube edge: for a face point, to the face's border.
        double crease = kInf;
        for (int axis = 0; axis < 3; ++axis) {
          const double c = p[axis];
          const bool on_face = c <= 0.5 * h || c >= size - 0.5 * h;
          if (!on_face)
            continue;
          for (int other = 0; other < 3; ++other)
            if (other != axis)
              crease = std::min (crease, std::min (p[other], size - p[other]));
        }
        a.add (p[0], p[1], p[2], std::max (0.0, crease), kInf);
      }
  a.cloud->width = static_cast<std::uint32_t> (a.cloud->size());
  a.cloud->height = 1;
  a.cloud->is_dense = true;
  return a;
}

/** Open cylinder of \a radius about the z axis, z in [0, height], sampled on a grid
 * with \a spacing along the circumference and the axis; Gaussian radial noise. Borders
 * at the two open ends; no crease. */
inline AnalyticCloud
makeCylinder (
    double radius, double height, double spacing, double noise = 0.0, unsigned seed = 1)
{
  AnalyticCloud a;
  a.spacing = spacing;
  std::mt19937 rng (seed);
  std::normal_distribution<double> g (0.0, noise > 0 ? noise : 1.0);
  const int around = static_cast<int> (std::round (2 * M_PI * radius / spacing));
  const int along = static_cast<int> (std::round (height / spacing));
  for (int i = 0; i <= along; ++i)
    for (int j = 0; j < around; ++j) {
      const double t = 2 * M_PI * j / around, z = height * i / along;
      const double r = radius + (noise > 0 ? g (rng) : 0.0);
      a.add (r * std::cos (t), r * std::sin (t), z, kInf, std::min (z, height - z));
    }
  a.cloud->width = static_cast<std::uint32_t> (a.cloud->size());
  a.cloud->height = 1;
  a.cloud->is_dense = true;
  return a;
}
} // namespace test
} // namespace pcl_ext
