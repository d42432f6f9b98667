/*
 * pcl_ext: a polyhedral building for pointcloud-to-map registration (Khoshelham & Gorte
 * 2009).
 */
#include "scene_parts.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcl_ext {
namespace simulation {
using detail::material;

namespace {
enum : std::uint32_t {
  WallLabel = 1,
  GroundLabel,
  RoofLabel,
  Superfluous,
  VegetationLabel
};

// The Logistics building of the paper is H-shaped: 40 x 30 m with two 16 m wide
// courtyards. Their depths differ (10 and 8 m) so that the plan has no rotational
// symmetry: a symmetric plan would make any registration to the map ambiguous.
std::vector<Vec2>
hShape ()
{
  return {Vec2 (0, 0),
          Vec2 (12, 0),
          Vec2 (12, 10),
          Vec2 (28, 10),
          Vec2 (28, 0),
          Vec2 (40, 0),
          Vec2 (40, 30),
          Vec2 (28, 30),
          Vec2 (28, 22),
          Vec2 (12, 22),
          Vec2 (12, 30),
          Vec2 (0, 30)};
}
} // namespace

void
describeBuildingScene (const SceneParameters& parameters, SceneDescription& d)
{
  SceneBuilder builder;
  std::vector<Vec2> footprint =
      parameters.footprint.empty() ? hShape() : parameters.footprint;
  if (detail::signedArea (footprint) < 0.0)
    std::reverse (footprint.begin(), footprint.end());
  const std::size_t n = footprint.size();
  const double height = parameters.building_height;
  Eigen::AlignedBox2d box;
  for (const auto& q : footprint)
    box.extend (q);
  const Vec2 centre = box.center();
  const double radius = 0.5 * box.diagonal().norm();

  const double margin = 40.0;
  const std::uint32_t ground =
      builder.addPolygon (Vec3::Zero(),
                          Vec3::UnitX(),
                          Vec3::UnitY(),
                          {{Vec2 (box.min().x() - margin, box.min().y() - margin),
                            Vec2 (box.max().x() + margin, box.min().y() - margin),
                            Vec2 (box.max().x() + margin, box.max().y() + margin),
                            Vec2 (box.min().x() - margin, box.max().y() + margin)}},
                          builder.newObject(),
                          GroundLabel,
                          material (120, 125, 110, 0.35, 10.f));
  detail::WindowLayout windows;
  detail::addPrism (builder,
                    footprint,
                    0.0,
                    height,
                    ground,
                    true,
                    builder.newObject(),
                    WallLabel,
                    RoofLabel,
                    material (185, 110, 80, 0.55, 10.f),
                    material (80, 80, 85, 0.3),
                    &windows);

  auto outward = [&] (std::size_t k) {
    const Vec2 e = footprint[(k + 1) % n] - footprint[k];
    return Vec2 (e.y(), -e.x()).normalized();
  };

  // Superfluous planes: neighbouring buildings (even k) and interior walls seen through
  // the windows (odd k), none of which is in the map.
  const double golden = 3.141592653589793 * (3.0 - std::sqrt (5.0));
  for (int k = 0; k < parameters.superfluous_planes; ++k) {
    if (k % 2 == 0) {
      const double angle = 0.7 + k * golden;
      const Vec2 c =
          centre + (radius + 30.0) * Vec2 (std::cos (angle), std::sin (angle));
      const Vec2 u (std::cos (angle + 0.3), std::sin (angle + 0.3)), v (-u.y(), u.x());
      detail::addPrism (builder,
                        {c - 4.0 * u - 3.0 * v,
                         c + 4.0 * u - 3.0 * v,
                         c + 4.0 * u + 3.0 * v,
                         c - 4.0 * u + 3.0 * v},
                        0.0,
                        6.0 + (k % 3),
                        ground,
                        true,
                        builder.newObject(),
                        Superfluous,
                        Superfluous,
                        material (200, 200, 190, 0.6),
                        material (80, 80, 85, 0.3),
                        nullptr);
    }
    else {
      const std::size_t w = (static_cast<std::size_t> (k) * 5) % n;
      const Vec2 a = footprint[w], b = footprint[(w + 1) % n];
      const Vec2 pa = a + 0.2 * (b - a) - 2.5 * outward (w),
                 pb = a + 0.8 * (b - a) - 2.5 * outward (w);
      if (!detail::insidePolygon (footprint, 0.5 * (pa + pb)))
        continue;
      const Vec2 dir = (pb - pa).normalized();
      builder.addPolygon (
          Vec3 (pa.x(), pa.y(), 0.0),
          Vec3 (dir.x(), dir.y(), 0),
          Vec3::UnitZ(),
          {{Vec2 (0, 0),
            Vec2 ((pb - pa).norm(), 0),
            Vec2 ((pb - pa).norm(), 0.8 * height),
            Vec2 (0, 0.8 * height)}},
          builder.newObject(),
          Superfluous,
          material (230, 230, 225, 0.7),
          {{ground, 0, 0, 0}}); // stands on the ground; other edges are free
    }
  }

  // Missing walls: the longest walls disappear behind a row of dense trees 2.5 m in
  // front.
  std::vector<std::size_t> by_length (n);
  std::iota (by_length.begin(), by_length.end(), 0);
  std::stable_sort (
      by_length.begin(), by_length.end(), [&] (std::size_t i, std::size_t j) {
        return (footprint[(i + 1) % n] - footprint[i]).norm() >
               (footprint[(j + 1) % n] - footprint[j]).norm();
      });
  Material hedge = material (60, 110, 40, 0.4, 15.f);
  for (int m = 0; m < std::min<int> (parameters.missing_walls, static_cast<int> (n));
       ++m) {
    const std::size_t w = by_length[m];
    const Vec2 a = footprint[w], b = footprint[(w + 1) % n];
    const double length = (b - a).norm();
    const int count = std::max (1, static_cast<int> (std::ceil (length / 2.5)));
    const std::uint32_t object = builder.newObject();
    const Vec2 dir = (b - a) / length;
    for (int i = 0; i < count; ++i) {
      const Vec2 q = a + (i + 0.5) * (length / count) * dir + 2.5 * outward (w);
      auto crown = std::make_shared<Ellipsoid> (
          Vec3 (q.x(), q.y(), 0.5 * height),
          detail::rotationYpr (std::atan2 (dir.y(), dir.x()), 0, 0),
          Vec3 (0.75 * length / count + 0.5, 1.5, 0.5 * height + 1.0));
      crown->roughness = 0.05;
      builder.add (crown, object, VegetationLabel, hedge);
    }
  }

  // Scan positions 12 m out from the middle of the walls, spread by farthest-point
  // order. All of them by default: the central ones, in front of the courtyards, are
  // the only ones that see the courtyard walls, and without those two hidden parallel
  // walls (missing_walls = 2) would leave one horizontal direction to the vegetation in
  // front of them.
  std::vector<Vec2> candidates;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 q = 0.5 * (footprint[k] + footprint[(k + 1) % n]) + 12.0 * outward (k);
    if (!detail::insidePolygon (footprint, q) &&
        detail::distanceToOutline (footprint, q) > 8.0)
      candidates.push_back (q);
  }
  std::vector<Eigen::Vector3d> ordered;
  std::vector<bool> used (candidates.size(), false);
  for (std::size_t step = 0; step < candidates.size(); ++step) {
    std::size_t best = 0;
    double best_distance = -1.0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (used[c])
        continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& o : ordered)
        nearest = std::min (nearest, (candidates[c] - o.head<2>()).norm());
      if (nearest > best_distance + 1e-9) {
        best_distance = nearest;
        best = c;
      }
    }
    used[best] = true;
    ordered.emplace_back (candidates[best].x(), candidates[best].y(), 1.7);
  }
  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions (
      ordered, parameters.num_scanners, static_cast<int> (ordered.size()));
  d.footprint = footprint;
  d.angular_step_deg = 0.4;
  d.max_range = 150.0;
  d.has_rgb = d.has_intensity = d.has_label = true;
  d.label_names = {"none", "wall", "ground", "roof", "superfluous", "vegetation"};
}
} // namespace simulation
} // namespace pcl_ext
