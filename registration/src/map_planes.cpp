/*
 * pcl_ext: wall and floor planes from footprints.
 */
#include <pcl_ext/registration/map_planes.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace {
double
cross2 (const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

bool
segmentsIntersect (const Eigen::Vector2d& p1,
                   const Eigen::Vector2d& p2,
                   const Eigen::Vector2d& q1,
                   const Eigen::Vector2d& q2)
{
  const double d1 = cross2 (q2 - q1, p1 - q1), d2 = cross2 (q2 - q1, p2 - q1);
  const double d3 = cross2 (p2 - p1, q1 - p1), d4 = cross2 (p2 - p1, q2 - p1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
      ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Collinear touching: a vertex of one segment on the other.
  auto on = [] (const Eigen::Vector2d& a,
                const Eigen::Vector2d& b,
                const Eigen::Vector2d& p,
                double c) {
    return c == 0.0 && std::min (a.x(), b.x()) <= p.x() &&
           p.x() <= std::max (a.x(), b.x()) && std::min (a.y(), b.y()) <= p.y() &&
           p.y() <= std::max (a.y(), b.y());
  };
  return on (q1, q2, p1, d1) || on (q1, q2, p2, d2) || on (p1, p2, q1, d3) ||
         on (p1, p2, q2, d4);
}

bool
checkParameters (const MapPlaneParameters& p)
{
  if (!p.origin.allFinite() || !std::isfinite (p.floor_height) ||
      !(p.wall_height > 0.0) || !std::isfinite (p.wall_height) ||
      !(p.min_edge_length >= 0.0)) {
    PCL_ERROR ("[pcl_ext::computeMapPlanes] Invalid parameters: origin and floor "
               "height must be "
               "finite, wall height > 0, minimum edge length >= 0.\n");
    return false;
  }
  return true;
}

// Walls of one ring, appended to planes.
bool
addRing (const io::Ring2d& ring,
         int polygon,
         int ring_index,
         const MapPlaneParameters& p,
         std::vector<MapPlane>& planes)
{
  if (ring.size() < 3) {
    PCL_ERROR (
        "[pcl_ext::computeMapPlanes] Polygon %d ring %d has %zu vertices (at least 3 "
        "needed).\n",
        polygon,
        ring_index,
        ring.size());
    return false;
  }
  for (const auto& v : ring)
    if (!v.allFinite()) {
      PCL_ERROR (
          "[pcl_ext::computeMapPlanes] Polygon %d ring %d has a non-finite vertex.\n",
          polygon,
          ring_index);
      return false;
    }
  if (isSelfIntersecting (ring)) {
    PCL_ERROR ("[pcl_ext::computeMapPlanes] Polygon %d ring %d intersects itself.\n",
               polygon,
               ring_index);
    return false;
  }
  const Eigen::Vector2d origin = p.origin.head<2>();
  const double z0 = p.floor_height - p.origin.z();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    // Subtract the origin first: eq. 2 on raw RD or UTM coordinates cancels digits.
    const Eigen::Vector2d a = ring[i] - origin,
                          b = ring[(i + 1) % ring.size()] - origin;
    const Eigen::Vector2d l = b - a;
    const double length = l.norm();
    if (length < p.min_edge_length || length == 0.0)
      continue;
    MapPlane wall;
    wall.normal = Eigen::Vector3d (l.y() / length, -l.x() / length, 0.0); // eq. 1
    wall.d = -cross2 (a, b) / length; // eq. 2, signed, as n . x + d = 0
    wall.start = a;
    wall.end = b;
    const Eigen::Vector2d mid = 0.5 * (a + b);
    wall.centroid = Eigen::Vector3d (mid.x(), mid.y(), z0 + 0.5 * p.wall_height);
    wall.extent.setEmpty();
    wall.extent.extend (Eigen::Vector3d (a.x(), a.y(), z0));
    wall.extent.extend (Eigen::Vector3d (b.x(), b.y(), z0 + p.wall_height));
    wall.polygon = polygon;
    wall.ring = ring_index;
    wall.edge = static_cast<int> (i);
    planes.push_back (wall);
  }
  return true;
}
} // namespace

bool
isSelfIntersecting (const io::Ring2d& ring)
{
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      // Adjacent edges share a vertex: they only intersect if they fold back on each
      // other.
      const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
      const Eigen::Vector2d &p1 = ring[i], &p2 = ring[(i + 1) % n];
      const Eigen::Vector2d &q1 = ring[j], &q2 = ring[(j + 1) % n];
      if (adjacent) {
        const Eigen::Vector2d shared = (j == i + 1) ? p2 : p1;
        const Eigen::Vector2d u = ((j == i + 1) ? p1 : p2) - shared;
        const Eigen::Vector2d v = ((j == i + 1) ? q2 : q1) - shared;
        if (cross2 (u, v) == 0.0 && u.dot (v) > 0.0)
          return true;
        continue;
      }
      if (segmentsIntersect (p1, p2, q1, q2))
        return true;
    }
  return false;
}

bool
chooseLocalOrigin (const std::vector<io::Footprint>& footprints,
                   Eigen::Vector3d& origin)
{
  Eigen::AlignedBox2d box;
  for (const auto& f : footprints)
    for (const auto& polygon : f.polygons)
      for (const auto& v : polygon.outer)
        if (v.allFinite())
          box.extend (v);
  if (box.isEmpty())
    return false;
  const Eigen::Vector2d c = box.center();
  origin = Eigen::Vector3d (std::round (c.x()), std::round (c.y()), 0.0);
  return true;
}

bool
computeMapPlanes (const std::vector<io::Footprint>& footprints,
                  const MapPlaneParameters& parameters,
                  std::vector<MapPlane>& planes)
{
  planes.clear();
  if (!checkParameters (parameters))
    return false;
  std::vector<MapPlane> result;
  if (parameters.add_floor) {
    MapPlane floor;
    floor.normal = Eigen::Vector3d::UnitZ();
    floor.d = parameters.origin.z() - parameters.floor_height;
    result.push_back (floor);
  }
  int polygon = 0;
  for (const auto& footprint : footprints)
    for (const auto& part : footprint.polygons) {
      // Outer rings counter-clockwise, holes clockwise: eq. 1 then points out of the
      // building.
      io::Ring2d outer = part.outer;
      if (io::signedArea (outer) < 0.0)
        std::reverse (outer.begin(), outer.end());
      if (!addRing (outer, polygon, 0, parameters, result))
        return false;
      for (std::size_t h = 0; h < part.holes.size(); ++h) {
        io::Ring2d hole = part.holes[h];
        if (io::signedArea (hole) > 0.0)
          std::reverse (hole.begin(), hole.end());
        if (!addRing (hole, polygon, static_cast<int> (h) + 1, parameters, result))
          return false;
      }
      ++polygon;
    }
  if (result.size() == (parameters.add_floor ? 1u : 0u)) {
    PCL_ERROR ("[pcl_ext::computeMapPlanes] No footprint polygon with an edge longer "
               "than %g m.\n",
               parameters.min_edge_length);
    return false;
  }
  // The floor's extent covers the walls.
  if (parameters.add_floor) {
    for (std::size_t i = 1; i < result.size(); ++i)
      result[0].extent.extend (result[i].extent.min());
    for (std::size_t i = 1; i < result.size(); ++i)
      result[0].extent.extend (Eigen::Vector3d (result[i].extent.max().x(),
                                                result[i].extent.max().y(),
                                                result[0].extent.min().z()));
    result[0].centroid = result[0].extent.center();
  }
  planes = std::move (result);
  return true;
}

bool
computeMapPlanes (const io::Ring2d& ring,
                  const MapPlaneParameters& parameters,
                  std::vector<MapPlane>& planes)
{
  io::Footprint footprint;
  footprint.polygons.resize (1);
  footprint.polygons[0].outer = ring;
  return computeMapPlanes (std::vector<io::Footprint>{footprint}, parameters, planes);
}

bool
selectFootprintsNearScan (const std::vector<io::Footprint>& footprints,
                          const Eigen::AlignedBox3d& scan_box,
                          double margin,
                          std::vector<io::Footprint>& near)
{
  std::vector<io::Footprint> kept;
  if (!scan_box.isEmpty() && margin >= 0.0) {
    Eigen::AlignedBox2d box (scan_box.min().head<2>(), scan_box.max().head<2>());
    box.min().array() -= margin;
    box.max().array() += margin;
    for (const auto& footprint : footprints) {
      Eigen::AlignedBox2d extent;
      for (const auto& polygon : footprint.polygons)
        for (const auto& q : polygon.outer)
          extent.extend (q);
      if (!extent.isEmpty() && box.intersects (extent))
        kept.push_back (footprint);
    }
  }
  if (kept.empty()) {
    near = footprints;
    return false;
  }
  near.swap (kept);
  return true;
}
} // namespace pcl_ext
