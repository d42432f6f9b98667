/*
 * pcl_ext: assembling scene geometry with consistent ids and ground-truth curves.
 */
#include <pcl_ext/simulation/scene_builder.h>

#include <cmath>

namespace pcl_ext {
namespace simulation {
std::uint32_t
SceneBuilder::add (const Primitive::Ptr& primitive,
                   std::uint32_t object,
                   std::uint32_t label,
                   const Material& material)
{
  primitive->info = newSurface (object, label, material);
  geometry_.addPrimitive (primitive);
  return primitive->info.segment;
}

std::uint32_t
SceneBuilder::addPolygon (const Vec3& origin,
                          const Vec3& u,
                          const Vec3& v,
                          const std::vector<std::vector<Vec2>>& rings,
                          std::uint32_t object,
                          std::uint32_t label,
                          const Material& material,
                          const std::vector<std::vector<std::uint32_t>>& neighbours)
{
  auto polygon = std::make_shared<PlanarPolygon> (origin, u, v, rings);
  const std::uint32_t segment = add (polygon, object, label, material);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    for (std::size_t k = 0; k < ring.size(); ++k) {
      std::uint32_t other = 0;
      if (r < neighbours.size() && k < neighbours[r].size())
        other = neighbours[r][k];
      if (other == kNoCurve)
        continue;
      addLine (polygon->toWorld (ring[k]),
               polygon->toWorld (ring[(k + 1) % ring.size()]),
               segment,
               other);
    }
  }
  return segment;
}

std::array<std::uint32_t, 6>
SceneBuilder::addBox (const Vec3& centre,
                      const Eigen::Matrix3d& rotation,
                      const Vec3& half,
                      std::uint32_t object,
                      std::uint32_t label,
                      const Material& material,
                      std::uint32_t ground_segment)
{
  std::array<std::uint32_t, 6> faces{};
  for (int f = 0; f < 6; ++f) {
    if (f == 4 && ground_segment != 0)
      continue;
    const int a = f / 2;
    const double sign = (f % 2) ? 1.0 : -1.0;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const Vec3 origin = centre + sign * half[a] * rotation.col (a);
    const std::vector<std::vector<Vec2>> rings{{Vec2 (-half[b], -half[c]),
                                                Vec2 (half[b], -half[c]),
                                                Vec2 (half[b], half[c]),
                                                Vec2 (-half[b], half[c])}};
    // Edges are added below, once per pair of faces.
    faces[f] = addPolygon (origin,
                           rotation.col (b),
                           rotation.col (c),
                           rings,
                           object,
                           label,
                           material,
                           {{kNoCurve, kNoCurve, kNoCurve, kNoCurve}});
  }
  for (int f = 0; f < 6; ++f)
    for (int g = f + 1; g < 6; ++g) {
      const int a = f / 2, b = g / 2;
      if (a == b)
        continue;
      const int c = 3 - a - b;
      const double sa = (f % 2) ? 1.0 : -1.0, sb = (g % 2) ? 1.0 : -1.0;
      const Vec3 mid =
          centre + sa * half[a] * rotation.col (a) + sb * half[b] * rotation.col (b);
      const Vec3 along = half[c] * rotation.col (c);
      std::uint32_t s1 = faces[f], s2 = faces[g];
      if (s1 == 0)
        s1 = ground_segment;
      if (s2 == 0)
        s2 = ground_segment;
      addLine (mid - along, mid + along, s1, s2);
    }
  return faces;
}

std::uint32_t
SceneBuilder::addFrustum (const Vec3& base,
                          const Vec3& axis_in,
                          double length,
                          double r0,
                          double r1,
                          std::uint32_t object,
                          std::uint32_t label,
                          const Material& material,
                          EndCondition base_end,
                          EndCondition top_end)
{
  const Vec3 axis = axis_in.normalized();
  const std::uint32_t lateral =
      add (std::make_shared<ConeFrustum> (base, axis, length, r0, r1),
           object,
           label,
           material);
  const Vec3 centres[2] = {base, base + length * axis};
  const double radii[2] = {r0, r1};
  const EndCondition ends[2] = {base_end, top_end};
  for (int e = 0; e < 2; ++e) {
    if (radii[e] <= 0.0)
      continue; // a cone apex has no rim
    switch (ends[e].kind) {
    case EndCondition::Kind::Open:
      addCircle (centres[e], axis, radii[e], lateral, 0);
      break;
    case EndCondition::Kind::Capped: {
      const std::uint32_t cap =
          add (std::make_shared<Annulus> (centres[e], axis, 0.0, radii[e]),
               object,
               label,
               material);
      addCircle (centres[e], axis, radii[e], lateral, cap);
      break;
    }
    case EndCondition::Kind::Joined:
      addCircle (centres[e], axis, radii[e], lateral, ends[e].segment);
      break;
    case EndCondition::Kind::Smooth:
      break;
    }
  }
  return lateral;
}

void
SceneBuilder::addLine (const Vec3& a,
                       const Vec3& b,
                       std::uint32_t segment_a,
                       std::uint32_t segment_b)
{
  GroundTruthCurve curve;
  curve.kind =
      segment_b != 0 ? GroundTruthCurve::Kind::Crease : GroundTruthCurve::Kind::Border;
  curve.shape = GroundTruthCurve::Shape::LineSegment;
  curve.a = a;
  curve.b = b;
  curve.segment_a = segment_a;
  curve.segment_b = segment_b;
  geometry_.addCurve (curve);
}

void
SceneBuilder::addCircle (const Vec3& centre,
                         const Vec3& normal,
                         double radius,
                         std::uint32_t segment_a,
                         std::uint32_t segment_b)
{
  GroundTruthCurve curve;
  curve.kind =
      segment_b != 0 ? GroundTruthCurve::Kind::Crease : GroundTruthCurve::Kind::Border;
  curve.shape = GroundTruthCurve::Shape::Circle;
  curve.a = centre;
  curve.b = normal.normalized();
  curve.radius = radius;
  curve.segment_a = segment_a;
  curve.segment_b = segment_b;
  geometry_.addCurve (curve);
}

void
SceneBuilder::addIntersection (const ConeFrustum& f,
                               std::uint32_t segment_f,
                               const Primitive& other,
                               std::uint32_t segment_other,
                               int samples)
{
  Vec3 u, v;
  orthonormalFrame (f.axis(), u, v);
  std::vector<Vec3> points (static_cast<std::size_t> (samples));
  std::vector<bool> valid (static_cast<std::size_t> (samples), false);
  const int steps = 256;
  for (int k = 0; k < samples; ++k) {
    const double phi = 6.283185307179586 * k / samples;
    const Vec3 radial = std::cos (phi) * u + std::sin (phi) * v;
    auto at = [&] (double s) {
      return Vec3 (f.base() + s * f.axis() + f.radiusAt (s) * radial);
    };
    double prev_s = 0.0, prev_f = other.implicit (at (0.0));
    for (int i = 1; i <= steps; ++i) {
      const double s = f.length() * i / steps;
      const double fs = other.implicit (at (s));
      if (prev_f < 0.0 && fs >= 0.0) {
        double lo = prev_s, hi = s;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (other.implicit (at (mid)) < 0.0 ? lo : hi) = mid;
        }
        points[k] = at (0.5 * (lo + hi));
        valid[k] = true;
        break;
      }
      prev_s = s;
      prev_f = fs;
    }
  }
  for (int k = 0; k < samples; ++k) {
    const int n = (k + 1) % samples;
    if (valid[k] && valid[n])
      addLine (points[k], points[n], segment_f, segment_other);
  }
}
} // namespace simulation
} // namespace pcl_ext
