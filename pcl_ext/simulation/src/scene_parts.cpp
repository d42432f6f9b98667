/*
 * pcl_ext: building blocks shared by the scene builders (internal).
 */
#include "scene_parts.h"

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace simulation {
namespace detail {
PrismSegments
addPrism (SceneBuilder& builder,
          const std::vector<Vec2>& footprint,
          double z0,
          double height,
          std::uint32_t ground_segment,
          bool roof,
          std::uint32_t object,
          std::uint32_t wall_label,
          std::uint32_t roof_label,
          const Material& wall,
          const Material& roof_material,
          const WindowLayout* windows,
          const std::vector<bool>& windowed)
{
  PrismSegments out;
  const std::size_t n = footprint.size();
  const std::uint32_t none = SceneBuilder::kNoCurve;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = footprint[k], b = footprint[(k + 1) % n];
    const double length = (b - a).norm();
    const Vec2 dir = (b - a) / length;
    std::vector<std::vector<Vec2>> rings{
        {Vec2 (0, 0), Vec2 (length, 0), Vec2 (length, height), Vec2 (0, height)}};
    std::vector<std::vector<std::uint32_t>> neighbours{{none, none, none, none}};
    const bool with_windows =
        windows && (windowed.empty() || (k < windowed.size() && windowed[k]));
    if (with_windows) {
      const WindowLayout& w = *windows;
      const int columns = static_cast<int> (std::floor (
                              (length - 2.0 * w.margin - w.width) / w.spacing + 1e-9)) +
                          1;
      const int storeys = static_cast<int> (std::floor (height / w.storey + 1e-9));
      if (columns > 0 && length - 2.0 * w.margin >= w.width) {
        const double used = (columns - 1) * w.spacing;
        const double first = 0.5 * (length - used);
        for (int s = 0; s < storeys; ++s)
          for (int c = 0; c < columns; ++c) {
            const double x = first + c * w.spacing, z = s * w.storey + w.sill;
            if (z + w.height > height - 0.3)
              continue;
            rings.push_back ({Vec2 (x - 0.5 * w.width, z),
                              Vec2 (x + 0.5 * w.width, z),
                              Vec2 (x + 0.5 * w.width, z + w.height),
                              Vec2 (x - 0.5 * w.width, z + w.height)});
            neighbours.push_back ({0, 0, 0, 0}); // window rims are free edges
          }
      }
    }
    out.walls.push_back (builder.addPolygon (Vec3 (a.x(), a.y(), z0),
                                             Vec3 (dir.x(), dir.y(), 0),
                                             Vec3::UnitZ(),
                                             rings,
                                             object,
                                             wall_label,
                                             wall,
                                             neighbours));
  }
  if (roof) {
    std::vector<std::vector<std::uint32_t>> roof_neighbours{
        std::vector<std::uint32_t> (n, none)};
    out.roof = builder.addPolygon (Vec3 (0, 0, z0 + height),
                                   Vec3::UnitX(),
                                   Vec3::UnitY(),
                                   {footprint},
                                   object,
                                   roof_label,
                                   roof_material,
                                   roof_neighbours);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = footprint[k], b = footprint[(k + 1) % n];
    builder.addLine (
        Vec3 (a.x(), a.y(), z0), Vec3 (b.x(), b.y(), z0), out.walls[k], ground_segment);
    builder.addLine (Vec3 (a.x(), a.y(), z0 + height),
                     Vec3 (b.x(), b.y(), z0 + height),
                     out.walls[k],
                     out.roof);
    builder.addLine (Vec3 (b.x(), b.y(), z0),
                     Vec3 (b.x(), b.y(), z0 + height),
                     out.walls[k],
                     out.walls[(k + 1) % n]);
  }
  return out;
}

std::vector<std::uint32_t>
addPipeRun (SceneBuilder& builder,
            const std::vector<Vec3>& polyline,
            double radius,
            double bend,
            std::uint32_t object,
            std::uint32_t label,
            const Material& material,
            EndCondition first,
            EndCondition last)
{
  std::vector<std::uint32_t> segments;
  Vec3 start = polyline.front();
  for (std::size_t k = 1; k < polyline.size(); ++k) {
    const Vec3 corner = polyline[k];
    const Vec3 d1 = (corner - polyline[k - 1]).normalized();
    const bool is_last = k + 1 == polyline.size();
    Vec3 end = corner;
    double tangent = 0.0, theta = 0.0;
    Vec3 d2 = d1;
    if (!is_last) {
      d2 = (polyline[k + 1] - corner).normalized();
      theta = std::acos (std::clamp (d1.dot (d2), -1.0, 1.0));
      tangent = bend * std::tan (0.5 * theta);
      end = corner - tangent * d1;
    }
    const EndCondition a = k == 1 ? first : EndCondition::smooth();
    const EndCondition b = is_last ? last : EndCondition::smooth();
    segments.push_back (builder.addFrustum (start,
                                            d1,
                                            (end - start).norm(),
                                            radius,
                                            radius,
                                            object,
                                            label,
                                            material,
                                            a,
                                            b));
    if (!is_last && theta > 1e-9) {
      const Vec3 normal = (d2 - d2.dot (d1) * d1).normalized();
      const Vec3 centre = end + bend * normal;
      const Vec3 e1 = -normal;
      const Vec3 axis = e1.cross (d1);
      segments.push_back (builder.add (
          std::make_shared<TorusSection> (centre, axis, e1, bend, radius, theta),
          object,
          label,
          material));
      start = corner + tangent * d2;
    }
    else
      start = end;
  }
  return segments;
}

Eigen::Matrix3d
rotationYpr (double yaw, double pitch, double roll)
{
  return (Eigen::AngleAxisd (yaw, Vec3::UnitZ()) *
          Eigen::AngleAxisd (pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd (roll, Vec3::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d
randomRotation (RandomStream& rng)
{
  Eigen::Quaterniond q (rng.gaussian(), rng.gaussian(), rng.gaussian(), rng.gaussian());
  q.normalize();
  return q.toRotationMatrix();
}

double
signedArea (const std::vector<Vec2>& polygon)
{
  double area = 0.0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % n];
    area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * area;
}

bool
insidePolygon (const std::vector<Vec2>& polygon, const Vec2& q)
{
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

double
distanceToOutline (const std::vector<Vec2>& polygon, const Vec2& q)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Vec2 a = polygon[i], d = polygon[(i + 1) % n] - a;
    const double s = std::clamp ((q - a).dot (d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min (best, (q - (a + s * d)).norm());
  }
  return best;
}

Material
material (float r, float g, float b, float reflectance, float jitter)
{
  Material m;
  m.rgb = Eigen::Vector3f (r, g, b);
  m.reflectance = reflectance;
  m.rgb_jitter = jitter;
  return m;
}

std::vector<Eigen::Vector3d>
choosePositions (const std::vector<Eigen::Vector3d>& candidates,
                 int count,
                 int fallback)
{
  const int n = std::min<int> (count > 0 ? count : fallback,
                               static_cast<int> (candidates.size()));
  return std::vector<Eigen::Vector3d> (candidates.begin(), candidates.begin() + n);
}
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
