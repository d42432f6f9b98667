/*
 * A synthetic classified airborne cloud for the roof outline tests: two box buildings
 * with rough flat roofs on labelled ground, one of them cut by the cloud's edge, with
 * the true walls.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace pcl_ext {
namespace test {
inline constexpr std::uint32_t kGround = 2, kBuilding = 6;

struct Box {
  double x0, y0, x1, y1, height;
  bool
  contains (double x, double y) const
  {
    return x >= x0 && x <= x1 && y >= y0 && y <= y1;
  }
};

// A true wall: the vertical plane n . (x, y) = d with horizontal unit normal n, from a
// to b.
struct Wall {
  Eigen::Vector2d a, b;
  double
  distance (const Eigen::Vector2d& p) const
  {
    const Eigen::Vector2d t = (b - a).normalized();
    return std::abs (t.x() * (p.y() - a.y()) - t.y() * (p.x() - a.x()));
  }
  Eigen::Vector2d
  normal () const
  {
    const Eigen::Vector2d t = (b - a).normalized();
    return Eigen::Vector2d (-t.y(), t.x());
  }
};

// The cloud covers x in [-10, 30], y in [-10, 25]: building A, [0, 10] x [0, 8], 6 m
// high; building B, [18, 34] x [5, 15], 9 m high, cut by the cloud's edge at x = 30.
// Roofs every 0.25 m (AHN3's spacing), ground every 0.5 m, both jittered by up to 3 cm
// in plan, so no two neighbourhoods are alike; the ground by 1 cm in height, the roofs
// by 20 cm (gutters, eaves, noise: the edge of a flat, noiseless roof is a line,
// through which no plane is found).
struct Scene {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Label>::Ptr labels{new pcl::PointCloud<pcl::Label>};
  std::vector<Wall>
      walls; // the walls a map would have inside the cloud, except the cut one
};

inline Scene
twoBuildings ()
{
  Scene s;
  const Box a{0, 0, 10, 8, 6}, b{18, 5, 34, 15, 9};
  const double cut = 30.0;
  std::mt19937 rng (7);
  std::uniform_real_distribution<float> jitter (-0.03f, 0.03f), dz (-0.01f, 0.01f),
      roof_dz (-0.2f, 0.2f);
  const auto add = [&] (double x, double y, double z, std::uint32_t label) {
    const float h = label == kBuilding ? roof_dz (rng) : dz (rng);
    s.cloud->emplace_back (static_cast<float> (x) + jitter (rng),
                           static_cast<float> (y) + jitter (rng),
                           static_cast<float> (z) + h);
    s.labels->push_back (pcl::Label{label});
  };
  for (double x = -10.0; x <= cut; x += 0.5)
    for (double y = -10.0; y <= 25.0; y += 0.5)
      if (!a.contains (x, y) && !b.contains (x, y))
        add (x, y, 0.0, kGround);
  for (const Box& box : {a, b})
    for (double x = box.x0 + 0.125; x < std::min (box.x1, cut); x += 0.25)
      for (double y = box.y0 + 0.125; y < box.y1; y += 0.25)
        add (x, y, box.height, kBuilding);
  s.walls = {{{0, 0}, {10, 0}},
             {{10, 0}, {10, 8}},
             {{10, 8}, {0, 8}},
             {{0, 8}, {0, 0}},
             {{18, 5}, {30, 5}},
             {{30, 15}, {18, 15}},
             {{18, 15}, {18, 5}}};
  return s;
}

/** The footprints of the two buildings as WKT (map coordinates = cloud coordinates). */
inline const char*
twoBuildingsWkt ()
{
  return "MULTIPOLYGON(((0 0, 10 0, 10 8, 0 8, 0 0)), ((18 5, 34 5, 34 15, 18 15, 18 "
         "5)))";
}
} // namespace test
} // namespace pcl_ext
