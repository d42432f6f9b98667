/*
 * Tests of the TLS scanner simulator on hand-built scenes.
 */
#include <pcl_ext/simulation/scene_builder.h>
#include <pcl_ext/simulation/tls_scanner.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <vector>

using namespace pcl_ext;
using namespace pcl_ext::simulation;

namespace {
constexpr double kDeg = 0.017453292519943295;

// A 200 x 200 m ground plane and, optionally, a floating 2 m box 6 m in front of the
// scanner.
SceneGeometry
groundAndBox (bool box, std::array<std::uint32_t, 6>* faces = nullptr)
{
  SceneBuilder builder;
  builder.addPolygon (Vec3 (-100, -100, 0),
                      Vec3::UnitX(),
                      Vec3::UnitY(),
                      {{Vec2 (0, 0), Vec2 (200, 0), Vec2 (200, 200), Vec2 (0, 200)}},
                      builder.newObject(),
                      1,
                      Material());
  if (box) {
    const auto f = builder.addBox (Vec3 (6, 0, 1.5),
                                   Eigen::Matrix3d::Identity(),
                                   Vec3 (1, 1, 1),
                                   builder.newObject(),
                                   2,
                                   Material());
    if (faces)
      *faces = f;
  }
  SceneGeometry geometry = std::move (builder.geometry());
  geometry.build();
  return geometry;
}

/** One noise-free scan of \a geometry from \a origin: 0.15 degree steps, elevations -45
 * to 10 degrees. */
pcl::PointCloud<SimulatedPoint>
scanFrom (const SceneGeometry& geometry, const Vec3& origin)
{
  TlsScanSimulation scanner;
  scanner.setScanPositions ({origin});
  scanner.setAngularStep (0.15);
  scanner.setElevationRange (-45.0, 10.0);
  scanner.setRangeNoise (0.0);
  pcl::PointCloud<SimulatedPoint> cloud;
  EXPECT_TRUE (scanner.scan (geometry, cloud));
  return cloud;
}
} // namespace

TEST (TlsScanSimulation, DeterministicForAnyThreadCount)
{
  const SceneGeometry geometry = groundAndBox (true);
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3 (0, 0, 1.7), Vec3 (2, 5, 1.5)});
  scanner.setAngularStep (0.5);
  scanner.setSeed (99);
  pcl::PointCloud<SimulatedPoint> one, two;
  scanner.setNumberOfThreads (1);
  ASSERT_TRUE (scanner.scan (geometry, one));
  scanner.setNumberOfThreads (2);
  ASSERT_TRUE (scanner.scan (geometry, two));
  ASSERT_GT (one.size(), 1000u);
  ASSERT_EQ (one.size(), two.size());
  // Field by field: the struct's padding bytes are not part of the point.
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ (0, std::memcmp (one[i].data, two[i].data, 3 * sizeof (float))) << i;
    ASSERT_EQ (one[i].rgba, two[i].rgba);
    ASSERT_EQ (0, std::memcmp (&one[i].intensity, &two[i].intensity, sizeof (float)));
    ASSERT_EQ (one[i].segment, two[i].segment);
    ASSERT_EQ (one[i].object, two[i].object);
    ASSERT_EQ (one[i].point_class, two[i].point_class);
    ASSERT_EQ (one[i].label, two[i].label);
  }
  scanner.setSeed (100);
  pcl::PointCloud<SimulatedPoint> other;
  ASSERT_TRUE (scanner.scan (geometry, other));
  EXPECT_NE (one[0].x, other[0].x); // a different seed, different noise
}

TEST (TlsScanSimulation, DensityFallsWithRange)
{
  const SceneGeometry geometry = groundAndBox (false);
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3 (0, 0, 1.7)});
  scanner.setAngularStep (0.2);
  pcl::PointCloud<SimulatedPoint> cloud;
  ASSERT_TRUE (scanner.scan (geometry, cloud));
  // Points per square metre in rings 2-4, 4-8, 8-16 and 16-32 m: strictly decreasing.
  const double edges[5] = {2, 4, 8, 16, 32};
  double density[4] = {0, 0, 0, 0};
  for (const auto& p : cloud) {
    const double r = std::hypot (p.x, p.y);
    for (int k = 0; k < 4; ++k)
      if (r >= edges[k] && r < edges[k + 1])
        density[k] += 1.0;
  }
  for (int k = 0; k < 4; ++k)
    density[k] /= M_PI * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k]);
  for (int k = 0; k + 1 < 4; ++k)
    EXPECT_GT (density[k], 1.5 * density[k + 1]) << "ring " << k;
}

TEST (TlsScanSimulation, OcclusionAndShadow)
{
  const SceneGeometry geometry = groundAndBox (true);
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3 (0, 0, 1.7)});
  scanner.setAngularStep (0.3);
  scanner.setRangeNoise (0.0);
  pcl::PointCloud<SimulatedPoint> cloud;
  ASSERT_TRUE (scanner.scan (geometry, cloud));
  std::size_t box_points = 0;
  for (const auto& p : cloud) {
    // The box hides the ground behind it: no ground point in its shadow, which starts
    // where rays pass below the box's front bottom edge (x = 5, z = 0.5), at 7.08 m.
    if (p.label == 1) {
      const double r = std::hypot (p.x, p.y);
      const bool behind = p.x > 7.3 && std::abs (p.y) < 0.5 * (p.x / 7.0) && r < 9.0;
      EXPECT_FALSE (behind) << p.x << " " << p.y;
    }
    else {
      ++box_points;
      EXPECT_LE (p.x, 5.0 + 1e-4); // only the front face (x = 5) or the top can be seen
      if (p.x < 5.0 - 1e-4)
        EXPECT_NEAR (p.z, 2.5, 1e-4);
    }
    // Nothing returns from behind a closer surface along the same ray.
    const Vec3 q (p.x, p.y, p.z), o (0, 0, 1.7);
    RayHit hit;
    ASSERT_TRUE (geometry.intersectBruteForce ({o, (q - o).normalized()}, 1e9, 0, hit));
    EXPECT_NEAR (hit.t, (q - o).norm(), 1e-4);
  }
  EXPECT_GT (box_points, 100u);
}

TEST (TlsScanSimulation, NoiseAlongTheRay)
{
  SceneBuilder builder;
  builder.addPolygon (Vec3 (8, -10, -5),
                      Vec3::UnitY(),
                      Vec3::UnitZ(),
                      {{Vec2 (0, 0), Vec2 (20, 0), Vec2 (20, 15), Vec2 (0, 15)}},
                      1,
                      1,
                      Material());
  SceneGeometry geometry = std::move (builder.geometry());
  geometry.build();
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3::Zero()});
  scanner.setAngularStep (0.25);
  scanner.setRangeNoise (0.01);
  pcl::PointCloud<SimulatedPoint> cloud;
  ASSERT_TRUE (scanner.scan (geometry, cloud));
  // Residual along the wall normal is noise * cos(incidence): compare its RMS with the
  // model.
  double sum_r2 = 0, sum_cos2 = 0;
  for (const auto& p : cloud) {
    const Vec3 d = Vec3 (p.x, p.y, p.z).normalized();
    sum_r2 += (p.x - 8.0) * (p.x - 8.0);
    sum_cos2 += d.x() * d.x();
  }
  const double rms = std::sqrt (sum_r2 / cloud.size());
  const double expected = 0.01 * std::sqrt (sum_cos2 / cloud.size());
  EXPECT_NEAR (rms, expected, 0.03 * expected);
}

TEST (TlsScanSimulation, EdgesOfABox)
{
  std::array<std::uint32_t, 6> faces{};
  const SceneGeometry geometry = groundAndBox (true, &faces);
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3 (0, 3, 3.0)});
  scanner.setAngularStep (0.15);
  scanner.setElevationRange (-45.0, 10.0);
  scanner.setRangeNoise (0.0);
  scanner.setEdgeDistance (0.05);
  scanner.setCoverageBoundaries (
      false); // the box's shadow: see ShadowBordersAreBoundaries
  pcl::PointCloud<SimulatedPoint> cloud;
  ASSERT_TRUE (scanner.scan (geometry, cloud));
  // Box [5, 7] x [-1, 1] x [0.5, 2.5]: distance of a face point to the nearest box
  // edge.
  const double lo[3] = {5, -1, 0.5}, hi[3] = {7, 1, 2.5};
  std::size_t edges = 0, boundaries = 0;
  for (const auto& p : cloud) {
    if (p.label != 2) {
      // The ground's only curves are its far borders.
      if (p.point_class == static_cast<std::uint32_t> (PointClass::Boundary))
        ++boundaries;
      else
        EXPECT_EQ (p.point_class, static_cast<std::uint32_t> (PointClass::Surface));
      continue;
    }
    const double c[3] = {p.x, p.y, p.z};
    // On a face one coordinate is at a bound; the distance to an edge is the smallest
    // distance of another coordinate to its bounds.
    int on = 0;
    double best = 1e9;
    for (int k = 0; k < 3; ++k)
      if (std::min (std::abs (c[k] - lo[k]), std::abs (c[k] - hi[k])) < 1e-4)
        on = k;
    for (int k = 0; k < 3; ++k)
      if (k != on)
        best = std::min (best,
                         std::min (std::abs (c[k] - lo[k]), std::abs (c[k] - hi[k])));
    const bool edge = p.point_class == static_cast<std::uint32_t> (PointClass::Edge);
    if (std::abs (best - 0.05) > 1e-4)
      EXPECT_EQ (edge, best < 0.05) << best;
    edges += edge;
  }
  EXPECT_GT (edges, 50u);
  EXPECT_EQ (boundaries,
             0u); // the ground's borders are 100 m away, out of sight of the box
}

// The ground behind the box is not scanned (its shadow); the ground points along the
// shadow's outline are boundaries of the scanned ground, as are the first row (the
// blind cone's border) and the last (the maximum incidence), and no other ground point
// is.
TEST (TlsScanSimulation, ShadowBordersAreBoundaries)
{
  const Vec3 o (0, 3, 3.0);
  const auto cloud = scanFrom (groundAndBox (true), o);
  const double step = 0.15 * M_PI / 180.0;
  std::size_t shadow = 0, blind_cone = 0, far = 0;
  for (const auto& p : cloud) {
    if (p.label != 1 ||
        p.point_class != static_cast<std::uint32_t> (PointClass::Boundary))
      continue;
    const Vec3 q (p.x, p.y, p.z);
    const Vec3 d = q - o;
    const double elevation = std::asin (d.z() / d.norm());
    if (elevation < -45.0 * M_PI / 180.0 + 1.5 * step) {
      ++blind_cone; // the lowest row: the border of the blind cone
      continue;
    }
    if (elevation > -2.0 * M_PI / 180.0 - 1.5 * step) {
      // The last row before the rays meet the ground beyond the maximum incidence (88
      // degrees from the normal, 2 degrees below the horizon) and return nothing: 80 m
      // away.
      EXPECT_GT (d.norm(), 75.0);
      ++far;
      continue;
    }
    // Otherwise the point lies behind the box, next to a ray that grazes the box: the
    // segment from the scanner to the point passes within two spacings of the box
    // [5,7]x[-1,1]x[0.5,2.5].
    EXPECT_GT (q.x(), 5.0);
    double nearest = 1e9;
    for (int t = 0; t <= 400; ++t) {
      const Vec3 r = o + (t / 400.0) * d;
      const Vec3 c (std::clamp (r.x(), 5.0, 7.0),
                    std::clamp (r.y(), -1.0, 1.0),
                    std::clamp (r.z(), 0.5, 2.5));
      nearest = std::min (nearest, (r - c).norm());
    }
    EXPECT_LT (nearest, 2.0 * d.norm() * step + 0.01) << q.transpose();
    ++shadow;
  }
  EXPECT_GT (shadow, 50u);
  EXPECT_GT (blind_cone, 50u);
  EXPECT_GT (far, 50u);
}

// A border of one scan that another scan covers is not a border of the scanned part:
// the box shadows the ground behind it from a scanner in front (x = 0), and a second
// scanner behind the box (x = 16) sees that ground. The first scan alone marks the
// shadow's outline there; with both, the returns of the second close the gap and the
// outline is surface.
TEST (TlsScanSimulation, BordersOfOneScanThatAnotherCoversAreSurface)
{
  const SceneGeometry geometry = groundAndBox (true);
  const auto outline = [] (const pcl::PointCloud<SimulatedPoint>& cloud) {
    std::size_t n = 0;
    for (const auto& p :
         cloud) // behind the box, away from both blind cones and the box
      n += p.label == 1 && p.x > 8.5 && p.x < 12.0 && std::abs (p.y) < 5.0 &&
           p.point_class == static_cast<std::uint32_t> (PointClass::Boundary);
    return n;
  };
  const auto one = scanFrom (geometry, Vec3 (0, 3, 3.0));
  TlsScanSimulation scanner;
  scanner.setScanPositions ({Vec3 (0, 3, 3.0), Vec3 (16, 0, 3.0)});
  scanner.setAngularStep (0.15);
  scanner.setElevationRange (-45.0, 10.0);
  scanner.setRangeNoise (0.0);
  pcl::PointCloud<SimulatedPoint> both;
  ASSERT_TRUE (scanner.scan (geometry, both));
  std::cout << "shadow outline points behind the box: one scan " << outline (one)
            << ", both scans " << outline (both) << "\n";
  EXPECT_GT (outline (one), 40u);
  EXPECT_EQ (outline (both), 0u);
}

namespace {
/** The box points of \a cloud within \a band of exactly one crease of the box of
 * groundAndBox, away from its corners, counted by whether the crease's other face is
 * one of \a seen (a face: axis * 2 + 0 for its lower side, + 1 for its upper) and by
 * their class. */
struct CreaseCounts {
  std::size_t two_sided = 0, two_sided_edges = 0;
  std::size_t one_sided = 0, one_sided_boundaries = 0;
};

CreaseCounts
countCreasePoints (const pcl::PointCloud<SimulatedPoint>& cloud,
                   const std::vector<int>& seen,
                   double band)
{
  const double lo[3] = {5, -1, 0.5}, hi[3] = {7, 1, 2.5};
  CreaseCounts counts;
  for (const auto& p : cloud) {
    if (p.label != 2)
      continue;
    const double c[3] = {p.x, p.y, p.z};
    int on = -1;
    for (int k = 0; k < 3; ++k)
      if (std::min (std::abs (c[k] - lo[k]), std::abs (c[k] - hi[k])) < 1e-4)
        on = k;
    int other = -1, near = 0;
    bool clear = true;
    for (int k = 0; k < 3; ++k) {
      if (k == on)
        continue;
      const double d_lo = std::abs (c[k] - lo[k]), d_hi = std::abs (c[k] - hi[k]);
      const double d = std::min (d_lo, d_hi);
      clear = clear && std::abs (d - band) > 1e-3;
      if (d < band) {
        ++near;
        other = 2 * k + (d_hi < d_lo);
      }
    }
    if (on < 0 || near != 1 || !clear)
      continue;
    const bool two_sided = std::find (seen.begin(), seen.end(), other) != seen.end();
    const auto cls = static_cast<PointClass> (p.point_class);
    if (two_sided) {
      ++counts.two_sided;
      counts.two_sided_edges += cls == PointClass::Edge;
    }
    else {
      ++counts.one_sided;
      counts.one_sided_boundaries += cls == PointClass::Boundary;
    }
  }
  return counts;
}
} // namespace

// A crease the scan saw from one side only is where the scanned part of a surface ends,
// as at a shadow: from (0, 5, 6) the box shows its front (x = 5), its near side (y = 1)
// and its top, each at 50-60 degrees of incidence, and the creases those faces share
// are edges, while where they meet the back, the far side or the bottom, which no ray
// reaches, their points are boundaries. A second scanner beside the far side (y = -1)
// sees it, and the creases the front and the top share with it are edges again; the
// bottom's stay boundaries.
TEST (TlsScanSimulation, CreasesSeenFromOneSideAreBoundaries)
{
  const SceneGeometry geometry = groundAndBox (true);
  const double band = 0.05;
  const auto scan = [&] (const std::vector<Vec3>& origins, bool coverage = true) {
    TlsScanSimulation scanner;
    scanner.setScanPositions (origins);
    scanner.setAngularStep (0.15);
    scanner.setElevationRange (-45.0, 10.0);
    scanner.setRangeNoise (0.0);
    scanner.setEdgeDistance (band);
    scanner.setCoverageBoundaries (coverage);
    pcl::PointCloud<SimulatedPoint> cloud;
    EXPECT_TRUE (scanner.scan (geometry, cloud));
    return cloud;
  };
  // Faces: axis * 2 + (0 lower, 1 upper).
  const auto one = countCreasePoints (scan ({Vec3 (0, 5, 6)}), {0, 3, 5}, band);
  EXPECT_GT (one.two_sided, 300u);
  EXPECT_GT (one.one_sided, 300u);
  EXPECT_EQ (one.two_sided_edges, one.two_sided);
  EXPECT_EQ (one.one_sided_boundaries, one.one_sided);

  const auto both =
      countCreasePoints (scan ({Vec3 (0, 5, 6), Vec3 (6, -6, 4)}), {0, 2, 3, 5}, band);
  EXPECT_GT (both.two_sided, one.two_sided + 300u);
  // The far side is seen from 5 m, the top from 9 m: a few far-side points at the far
  // end of the band have no return of the top within 4 of their (shorter) spacings.
  EXPECT_GE (both.two_sided_edges, 0.99 * both.two_sided);
  EXPECT_GT (both.one_sided, 300u);
  EXPECT_EQ (both.one_sided_boundaries, both.one_sided);

  // Without the coverage boundaries the truth is the scene's: every crease point an
  // edge.
  const auto geometric =
      countCreasePoints (scan ({Vec3 (0, 5, 6)}, false), {0, 1, 2, 3, 4, 5}, band);
  EXPECT_EQ (geometric.two_sided_edges, geometric.two_sided);
  EXPECT_GT (geometric.two_sided, one.two_sided + 300u);
}

// A vertical pipe standing on the ground in front of the scanner: its data end at its
// two silhouettes, where it turns away from the scanner, as they end at a shadow. The
// pipe points next to a silhouette (whose neighbouring ray passes the pipe) are
// boundaries; the ones facing the scanner, away from the silhouettes and the ends, are
// not.
TEST (TlsScanSimulation, SilhouettesOfASmoothSurfaceAreBoundaries)
{
  SceneBuilder builder;
  const std::uint32_t ground = builder.addPolygon (
      Vec3 (-100, -100, 0),
      Vec3::UnitX(),
      Vec3::UnitY(),
      {{Vec2 (0, 0), Vec2 (200, 0), Vec2 (200, 200), Vec2 (0, 200)}},
      builder.newObject(),
      1,
      Material());
  const double radius = 0.3;
  const Vec3 axis_base (6, 0, 0);
  builder.addFrustum (axis_base,
                      Vec3::UnitZ(),
                      2.0,
                      radius,
                      radius,
                      builder.newObject(),
                      2,
                      Material(),
                      EndCondition::joined (ground),
                      EndCondition::open());
  SceneGeometry geometry = std::move (builder.geometry());
  geometry.build();
  const Vec3 o (0, 0, 1.0);
  const auto cloud = scanFrom (geometry, o);
  const double step = 0.15 * M_PI / 180.0;
  std::size_t silhouette = 0, facing = 0, wrong = 0;
  for (const auto& p : cloud) {
    if (p.label != 2 || p.z < 0.3 || p.z > 1.7) // the pipe, away from its two ends
      continue;
    // How far inside the pipe's outline, seen from the scanner, the ray to the point
    // passes: the pipe's radius less the distance from its axis to the ray (0 on a
    // silhouette). The ray one step beside passes the pipe when this is under about one
    // spacing.
    const Vec2 q (p.x, p.y);
    const Vec2 ray = (q - o.head<2>()).normalized();
    const Vec2 to_axis = axis_base.head<2>() - o.head<2>();
    const double inside =
        radius - std::abs (ray.x() * to_axis.y() - ray.y() * to_axis.x());
    const double spacing = (q - o.head<2>()).norm() * step;
    const bool boundary =
        p.point_class == static_cast<std::uint32_t> (PointClass::Boundary);
    if (inside > 3.0 * spacing) {
      ++facing;
      wrong += boundary;
    }
    else if (inside < 0.5 * spacing) {
      ++silhouette;
      EXPECT_TRUE (boundary) << p.x << " " << p.y << " " << p.z;
    }
  }
  EXPECT_GT (silhouette, 20u);
  EXPECT_GT (facing, 1000u);
  EXPECT_EQ (wrong, 0u);
}

TEST (TlsScanSimulation, ConnectedSegmentsSplitASurfaceCutByAWall)
{
  // A 10 x 4 m floor, scanned from (2.5, 2) and (7.5, 2); with a 0.2 m thick, 3 m high
  // wall across it at x = 5 neither scanner sees the other half: the floor is two
  // visible pieces.
  for (const bool wall : {false, true}) {
    SceneBuilder builder;
    const std::uint32_t floor =
        builder.addPolygon (Vec3::Zero(),
                            Vec3::UnitX(),
                            Vec3::UnitY(),
                            {{Vec2 (0, 0), Vec2 (10, 0), Vec2 (10, 4), Vec2 (0, 4)}},
                            builder.newObject(),
                            1,
                            Material());
    if (wall)
      builder.addBox (Vec3 (5, 2, 1.5),
                      Eigen::Matrix3d::Identity(),
                      Vec3 (0.1, 2.5, 1.5),
                      builder.newObject(),
                      2,
                      Material(),
                      floor);
    SceneGeometry geometry = std::move (builder.geometry());
    geometry.build();
    TlsScanSimulation scanner;
    scanner.setScanPositions ({Vec3 (2.5, 2, 1.5), Vec3 (7.5, 2, 1.5)});
    scanner.setAngularStep (0.5);
    pcl::PointCloud<SimulatedPoint> pieces, surfaces;
    std::vector<std::uint32_t> surface_of_segment, identity;
    ASSERT_TRUE (scanner.scan (geometry, pieces, nullptr, &surface_of_segment));
    scanner.setConnectedSegments (false);
    ASSERT_TRUE (scanner.scan (geometry, surfaces, nullptr, &identity));
    ASSERT_EQ (pieces.size(), surfaces.size());
    ASSERT_GT (pieces.size(), 10000u);
    std::map<std::uint32_t, std::pair<double, double>>
        x_range; // floor piece -> x extent
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      // Only the segment ids differ, and each piece maps back to its surface.
      ASSERT_EQ (pieces[i].object, surfaces[i].object);
      ASSERT_EQ (pieces[i].point_class, surfaces[i].point_class);
      ASSERT_LT (pieces[i].segment, surface_of_segment.size());
      ASSERT_EQ (surface_of_segment[pieces[i].segment], surfaces[i].segment);
      ASSERT_EQ (identity[surfaces[i].segment], surfaces[i].segment);
      if (surfaces[i].segment != floor)
        continue;
      auto it = x_range.emplace (pieces[i].segment, std::make_pair (1e9, -1e9)).first;
      it->second.first = std::min<double> (it->second.first, pieces[i].x);
      it->second.second = std::max<double> (it->second.second, pieces[i].x);
    }
    if (!wall) {
      EXPECT_EQ (x_range.size(), 1u); // both scans overlap: one piece
      EXPECT_EQ (x_range.begin()->first, floor);
      continue;
    }
    ASSERT_EQ (x_range.size(), 2u);
    EXPECT_EQ (x_range.count (floor), 1u); // the larger piece keeps the surface's id
    for (const auto& [segment, range] : x_range)
      EXPECT_TRUE (range.second < 4.95 || range.first > 5.05) // the wall: 4.9 .. 5.1
          << segment << ": " << range.first << " .. " << range.second;
  }
}

TEST (TlsScanSimulation, BadParameters)
{
  const SceneGeometry geometry = groundAndBox (false);
  pcl::PointCloud<SimulatedPoint> cloud;
  TlsScanSimulation scanner;
  EXPECT_FALSE (scanner.scan (geometry, cloud)); // no position
  scanner.setScanPositions ({Vec3 (0, 0, 1.7)});
  scanner.setAngularStep (std::nan (""));
  EXPECT_FALSE (scanner.scan (geometry, cloud));
  scanner.setAngularStep (0.0);
  EXPECT_FALSE (scanner.scan (geometry, cloud));
  scanner.setAngularStep (1.0);
  scanner.setRangeNoise (-0.1);
  EXPECT_FALSE (scanner.scan (geometry, cloud));
  scanner.setRangeNoise (0.005);
  scanner.setEdgeDistance (std::nan (""));
  EXPECT_FALSE (scanner.scan (geometry, cloud));
  EXPECT_TRUE (cloud.empty());
  scanner.setEdgeDistance (0.0);
  EXPECT_TRUE (scanner.scan (geometry, cloud));
  EXPECT_FALSE (cloud.empty());
  EXPECT_EQ (scanner.stepForPointCount (geometry, 0), 0.0);
}
