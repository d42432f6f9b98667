/*
 * Analytic test clouds for the profile segmentation tests: surfaces sampled on jittered
 * grids with a known segment label per point.
 */
#pragma once

#include <pcl_ext/evaluation/segmentation_metrics.h>

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace profile_test {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct LabelledCloud {
  Cloud::Ptr cloud{new Cloud};
  std::vector<std::uint32_t> labels;

  void
  add (const Eigen::Vector3d& p, std::uint32_t label)
  {
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x()),
                                     static_cast<float> (p.y()),
                                     static_cast<float> (p.z())));
    labels.push_back (label);
  }
};

/** Points on a rectangle origin + a*e1 + b*e2, a in [0, la], b in [0, lb], grid step s
 * jittered by 0.3 s, plus Gaussian noise along the normal. */
inline void
addRectangle (LabelledCloud& out,
              const Eigen::Vector3d& origin,
              const Eigen::Vector3d& e1,
              const Eigen::Vector3d& e2,
              double la,
              double lb,
              double s,
              std::uint32_t label,
              std::mt19937& rng,
              double noise = 0.0)
{
  std::uniform_real_distribution<double> jitter (-0.15 * s, 0.15 * s);
  std::normal_distribution<double> gauss (0.0, noise > 0 ? noise : 1.0);
  const Eigen::Vector3d n = e1.cross (e2).normalized();
  for (double a = 0.5 * s; a < la; a += s)
    for (double b = 0.5 * s; b < lb; b += s)
      out.add (origin + (a + jitter (rng)) * e1 + (b + jitter (rng)) * e2 +
                   (noise > 0 ? gauss (rng) : 0.0) * n,
               label);
}

/** The six faces of a cube of side \a size, rotated by \a rotation, all with one label.
 */
inline void
addCube (LabelledCloud& out,
         const Eigen::Vector3d& centre,
         const Eigen::Matrix3d& rotation,
         double size,
         double s,
         std::uint32_t label,
         std::mt19937& rng)
{
  const double h = 0.5 * size;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      const Eigen::Vector3d n = sign * Eigen::Vector3d::Unit (axis);
      const Eigen::Vector3d e1 = Eigen::Vector3d::Unit ((axis + 1) % 3);
      const Eigen::Vector3d e2 = Eigen::Vector3d::Unit ((axis + 2) % 3);
      const Eigen::Vector3d corner = h * n - h * e1 - h * e2;
      addRectangle (out,
                    centre + rotation * corner,
                    rotation * e1,
                    rotation * e2,
                    size,
                    size,
                    s,
                    label,
                    rng);
    }
}

/** A sphere sampled by a Fibonacci lattice with spacing about \a s. */
inline void
addSphere (LabelledCloud& out,
           const Eigen::Vector3d& centre,
           double radius,
           double s,
           std::uint32_t label)
{
  const int n = static_cast<int> (4.0 * M_PI * radius * radius / (s * s));
  const double golden = M_PI * (3.0 - std::sqrt (5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / n;
    const double r = std::sqrt (1.0 - z * z);
    out.add (centre + radius * Eigen::Vector3d (r * std::cos (golden * k),
                                                r * std::sin (golden * k),
                                                z),
             label);
  }
}

/** A cylinder surface along x from x0 to x1, radius r, centred on the x axis. */
inline void
addCylinderX (LabelledCloud& out,
              double x0,
              double x1,
              double r,
              double s,
              std::uint32_t label,
              std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter (-0.15 * s, 0.15 * s);
  const int around = static_cast<int> (2 * M_PI * r / s);
  for (double x = x0 + 0.5 * s; x < x1; x += s)
    for (int k = 0; k < around; ++k) {
      const double a =
          2 * M_PI * (k + 0.5 + (x - x0) / s * 0.5) / around + jitter (rng) / r;
      out.add (Eigen::Vector3d (x + jitter (rng), r * std::cos (a), r * std::sin (a)),
               label);
    }
}

/** An annulus in the plane x = x0 between radii r0 and r1. */
inline void
addAnnulusX (LabelledCloud& out,
             double x0,
             double r0,
             double r1,
             double s,
             std::uint32_t label,
             std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter (-0.15 * s, 0.15 * s);
  for (double r = r0 + 0.5 * s; r < r1; r += s) {
    const int around = static_cast<int> (2 * M_PI * r / s);
    for (int k = 0; k < around; ++k) {
      const double a = 2 * M_PI * (k + 0.5) / around;
      const double rr = r + jitter (rng);
      out.add (Eigen::Vector3d (x0, rr * std::cos (a), rr * std::sin (a)), label);
    }
  }
}

/** A pipe of radius 0.2 inside a coaxial pipe of radius 0.4 closed by an annular step
 * at x = 1: three surfaces that touch along two creases (the paper's figures 9 and 13),
 * sampled every \a spacing. */
inline LabelledCloud
coaxialPipes (double spacing = 0.015)
{
  LabelledCloud scene;
  std::mt19937 rng (2);
  addCylinderX (scene, -1.0, 1.0, 0.4, spacing, 1, rng);
  addAnnulusX (scene, 1.0, 0.2, 0.4, spacing, 2, rng);
  addCylinderX (scene, 1.0, 2.5, 0.2, spacing, 3, rng);
  return scene;
}

/** The coaxial pipes sampled coarsely enough (about 8,000 points) for the determinism
 * tests to stay short in the sanitized build, where curve fitting runs many times
 * slower. */
inline LabelledCloud
coarseCoaxialPipes ()
{
  return coaxialPipes (0.03);
}
/** Segmentation metrics of \a clusters against the labels of \a scene. */
inline pcl_ext::SegmentationMetrics
evaluate (const std::vector<pcl::PointIndices>& clusters, const LabelledCloud& scene)
{
  pcl_ext::SegmentationMetrics metrics;
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (clusters, scene.labels, metrics));
  return metrics;
}

/** Three cubes on a 2 cm grid, a metre or more apart, labels 1 to 3, with edges of
 * \a sizes. */
inline LabelledCloud
threeCubes (const std::array<double, 3>& sizes = {1.0, 0.6, 0.8}, unsigned seed = 1)
{
  LabelledCloud scene;
  std::mt19937 rng (seed);
  addCube (scene, {0, 0, 0}, Eigen::Matrix3d::Identity(), sizes[0], 0.02, 1, rng);
  addCube (scene,
           {2.0, 0.3, 0.2},
           Eigen::AngleAxisd (0.5, Eigen::Vector3d (1, 1, 0).normalized())
               .toRotationMatrix(),
           sizes[1],
           0.02,
           2,
           rng);
  addCube (scene,
           {0.5, 2.0, -0.3},
           Eigen::AngleAxisd (1.1, Eigen::Vector3d (0, 1, 2).normalized())
               .toRotationMatrix(),
           sizes[2],
           0.02,
           3,
           rng);
  return scene;
}
} // namespace profile_test
