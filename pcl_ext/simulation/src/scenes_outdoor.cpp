/*
 * pcl_ext: a tree (Sithole & Mapurisa figure 14) and a street (Lim & Suter figures
 * 6-8).
 */
#include "scene_parts.h"

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace simulation {
using detail::material;

namespace {
constexpr double kPi = 3.141592653589793;
constexpr std::uint32_t kVegetation =
    static_cast<std::uint32_t> (OutdoorLabel::Vegetation);
constexpr std::uint32_t kTrunk = static_cast<std::uint32_t> (OutdoorLabel::Trunk);
constexpr std::uint32_t kManMade = static_cast<std::uint32_t> (OutdoorLabel::ManMade);
constexpr std::uint32_t kPathway = static_cast<std::uint32_t> (OutdoorLabel::Pathway);
constexpr std::uint32_t kTerrain = static_cast<std::uint32_t> (OutdoorLabel::Terrain);

const std::vector<std::string> kOutdoorLabelNames{
    "none", "vegetation", "trunk", "man-made", "pathway", "terrain"};

Material
leaves ()
{
  Material m = material (70, 125, 45, 0.45, 18.f);
  m.intensity_jitter = 0.08f;
  return m;
}
} // namespace

std::uint32_t
detail::addTree (SceneBuilder& builder,
                 RandomStream& rng,
                 const Vec3& base,
                 const Primitive& ground,
                 std::uint32_t ground_segment,
                 double height,
                 int branches)
{
  const std::uint32_t object = builder.newObject();
  const Material bark = material (95, 75, 55, 0.3, 8.f);
  const double lean = 0.05 * rng.uniform(), lean_dir = 2.0 * kPi * rng.uniform();
  const Vec3 axis = Vec3 (std::sin (lean) * std::cos (lean_dir),
                          std::sin (lean) * std::sin (lean_dir),
                          std::cos (lean));
  const double r0 = 0.03 * height + 0.02, r1 = 0.25 * r0;
  const Vec3 start = base - 0.5 * axis; // below the ground: the visible foot is traced
  auto trunk = std::make_shared<ConeFrustum> (start, axis, height + 0.5, r0, r1);
  const std::uint32_t trunk_segment = builder.add (trunk, object, kTrunk, bark);
  const Vec3 top = start + (height + 0.5) * axis;
  const std::uint32_t cap = builder.add (
      std::make_shared<Annulus> (top, axis, 0.0, r1), object, kTrunk, bark);
  builder.addCircle (top, axis, r1, trunk_segment, cap);
  builder.addIntersection (*trunk, trunk_segment, ground, ground_segment);

  const Material leaf = leaves();
  auto add_cluster = [&] (const Vec3& centre, double size) {
    const Vec3 radii = size * Vec3 (1.0 + 0.3 * rng.uniform(),
                                    0.8 + 0.3 * rng.uniform(),
                                    0.6 + 0.2 * rng.uniform());
    auto cluster = std::make_shared<Ellipsoid> (
        centre,
        detail::rotationYpr (
            2.0 * kPi * rng.uniform(), 0.3 * (rng.uniform() - 0.5), 0.0),
        radii);
    cluster->porosity = 0.55;
    cluster->roughness = 0.03;
    builder.add (cluster, object, kVegetation, leaf);
  };
  const double golden = kPi * (3.0 - std::sqrt (5.0));
  for (int b = 0; b < branches; ++b) {
    const double rel =
        0.4 + 0.45 * (b + rng.uniform()) / branches; // height on the trunk
    const double s = 0.5 + rel * height;
    const double azimuth = b * golden + 0.4 * (rng.uniform() - 0.5);
    const double elevation = (25.0 + 30.0 * rng.uniform()) * kPi / 180.0;
    const Vec3 dir (std::cos (elevation) * std::cos (azimuth),
                    std::cos (elevation) * std::sin (azimuth),
                    std::sin (elevation));
    const double length = (0.45 - 0.25 * rel) * height * (0.8 + 0.4 * rng.uniform());
    const double rb = 0.55 * trunk->radiusAt (s);
    // The branch starts on the trunk axis; its visible part begins where it leaves the
    // trunk.
    auto branch =
        std::make_shared<ConeFrustum> (start + s * axis, dir, length, rb, 0.3 * rb);
    const std::uint32_t seg = builder.add (branch, object, kTrunk, bark);
    builder.addIntersection (*branch, seg, *trunk, trunk_segment);
    const Vec3 tip = start + s * axis + length * dir;
    const std::uint32_t tip_cap = builder.add (
        std::make_shared<Annulus> (tip, dir, 0.0, 0.3 * rb), object, kTrunk, bark);
    builder.addCircle (tip, dir, 0.3 * rb, seg, tip_cap);
    add_cluster (tip + 0.2 * length * dir, 0.25 * height * (0.5 + 0.3 * rng.uniform()));
  }
  add_cluster (top + 0.05 * height * axis, 0.18 * height);
  return object;
}

void
describeTreeScene (const SceneParameters& parameters, SceneDescription& d)
{
  SceneBuilder builder;
  RandomStream rng = detail::layoutStream (parameters.seed, 0x7ee0ULL);
  auto ground = std::make_shared<Annulus> (Vec3::Zero(), Vec3::UnitZ(), 0.0, 6.0);
  const std::uint32_t ground_segment = builder.add (
      ground, builder.newObject(), kTerrain, material (90, 140, 60, 0.35, 12.f));
  builder.addCircle (Vec3::Zero(), Vec3::UnitZ(), 6.0, ground_segment, 0);
  detail::addTree (builder, rng, Vec3::Zero(), *ground, ground_segment, 8.0, 8);
  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions (
      {Vec3 (7.0, 0.0, 1.5), Vec3 (-3.5, 6.1, 1.5), Vec3 (-3.5, -6.1, 1.5)},
      parameters.num_scanners,
      3);
  d.angular_step_deg = 0.25;
  d.max_range = 60.0;
  d.has_rgb = d.has_intensity = d.has_label = true;
  d.label_names = kOutdoorLabelNames;
}

void
describeStreetScene (const SceneParameters& parameters, SceneDescription& d)
{
  SceneBuilder builder;
  RandomStream rng = detail::layoutStream (parameters.seed, 0x57ee7ULL);

  // Terrain: flat road, walkways and northern lawns; undulating grass south of y = -7.
  const double x0 = -40.0, y0 = -26.0, cell = 0.5;
  const int nx = 160, ny = 104;
  const double p1 = 2.0 * kPi * rng.uniform(), p2 = 2.0 * kPi * rng.uniform();
  std::vector<double> heights (static_cast<std::size_t> (nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + i * cell, y = y0 + j * cell;
      const double w = std::clamp ((-7.0 - y) / 5.0, 0.0, 1.0);
      const double smooth = w * w * (3.0 - 2.0 * w);
      heights[static_cast<std::size_t> (j) * (nx + 1) + i] =
          smooth * (0.35 * std::sin (0.23 * x + p1) +
                    0.25 * std::sin (0.31 * y + 0.11 * x + p2) + 0.03 * (-7.0 - y));
    }
  auto terrain = std::make_shared<HeightField> (x0, y0, cell, nx, ny, heights);
  const std::uint32_t ground_object = builder.newObject();
  std::vector<SurfaceInfo> regions{
      builder.newSurface (
          ground_object, kPathway, material (70, 70, 75, 0.15, 5.f)), // road
      builder.newSurface (
          ground_object, kPathway, material (175, 170, 160, 0.4, 8.f)), // walkway N
      builder.newSurface (
          ground_object, kPathway, material (175, 170, 160, 0.4, 8.f)), // walkway S
      builder.newSurface (
          ground_object, kTerrain, material (85, 140, 55, 0.35, 14.f)), // grass N
      builder.newSurface (
          ground_object, kTerrain, material (85, 140, 55, 0.35, 14.f))}; // grass S
  auto region_of = [] (double, double y) {
    if (std::abs (y) < 3.5)
      return 0;
    if (std::abs (y) < 6.0)
      return y > 0 ? 1 : 2;
    return y > 0 ? 3 : 4;
  };
  terrain->setRegions (region_of, regions);
  terrain->info = regions[0];
  builder.geometry().addPrimitive (terrain);
  // Free edges of the terrain, cell by cell (the mesh is straight between grid
  // vertices).
  auto border = [&] (const Vec3& a, const Vec3& b) {
    const Vec3 mid = 0.5 * (a + b);
    builder.addLine (a, b, regions[region_of (mid.x(), mid.y())].segment, 0);
  };
  for (int i = 0; i < nx; ++i)
    for (const double y : {y0, terrain->y1()}) {
      const double xa = x0 + i * cell, xb = xa + cell;
      border (Vec3 (xa, y, terrain->height (xa, y)),
              Vec3 (xb, y, terrain->height (xb, y)));
    }
  for (int j = 0; j < ny; ++j)
    for (const double x : {x0, terrain->x1()}) {
      const double ya = y0 + j * cell, yb = ya + cell;
      border (Vec3 (x, ya, terrain->height (x, ya)),
              Vec3 (x, yb, terrain->height (x, yb)));
    }

  // Facades north of the street.
  detail::WindowLayout windows;
  const double blocks[3][3] = {
      {-34.0, -13.0, 9.0}, {-10.0, 9.0, 12.5}, {12.0, 33.0, 7.5}};
  const Material walls[3] = {material (165, 85, 65, 0.5, 10.f),
                             material (225, 215, 195, 0.65),
                             material (150, 150, 155, 0.55)};
  const Material roof = material (90, 60, 50, 0.3);
  for (int b = 0; b < 3; ++b) {
    const double xa = blocks[b][0], xb = blocks[b][1];
    detail::addPrism (
        builder,
        {Vec2 (xa, 8.0), Vec2 (xb, 8.0), Vec2 (xb, 20.0), Vec2 (xa, 20.0)},
        0.0,
        blocks[b][2],
        regions[3].segment,
        true,
        builder.newObject(),
        kManMade,
        kManMade,
        walls[b],
        roof,
        &windows,
        {true, false, false, false});
  }

  // Poles on the southern walkway and sagging wires between them.
  const Material metal = material (130, 130, 135, 0.55);
  Material wire_material = material (30, 30, 30, 0.1, 3.f);
  const double pole_x[5] = {-30.0, -15.0, 0.0, 15.0, 30.0};
  const double pole_r = 0.1, pole_h = 7.0, wire_z = 6.8;
  for (const double x : pole_x)
    builder.addFrustum (Vec3 (x, -5.0, 0.0),
                        Vec3::UnitZ(),
                        pole_h,
                        pole_r,
                        pole_r,
                        builder.newObject(),
                        kManMade,
                        metal,
                        EndCondition::joined (regions[2].segment),
                        EndCondition::capped());
  for (int k = 0; k + 1 < 5; ++k) {
    const SurfaceInfo wire =
        builder.newSurface (builder.newObject(), kManMade, wire_material);
    const double xa = pole_x[k] + pole_r, xb = pole_x[k + 1] - pole_r, sag = 0.5;
    const int pieces = 16;
    auto point = [&] (int i) {
      const double u = static_cast<double> (i) / pieces;
      return Vec3 (xa + u * (xb - xa), -5.0, wire_z - 4.0 * sag * u * (1.0 - u));
    };
    for (int i = 0; i < pieces; ++i) {
      const Vec3 a = point (i), b = point (i + 1);
      builder.addPart (
          std::make_shared<ConeFrustum> (a, b - a, (b - a).norm(), 0.012, 0.012), wire);
    }
  }

  // Trees and shrubs on the southern grass.
  for (int t = 0; t < 5; ++t) {
    const double x = -28.0 + 13.0 * t + 3.0 * (rng.uniform() - 0.5);
    const double y = -11.0 - 5.0 * rng.uniform();
    detail::addTree (builder,
                     rng,
                     Vec3 (x, y, terrain->height (x, y)),
                     *terrain,
                     regions[4].segment,
                     6.0 + 3.0 * rng.uniform(),
                     6);
  }
  for (int s = 0; s < 10; ++s) {
    const double x = -36.0 + 7.5 * s + 2.0 * rng.uniform();
    const double y = -8.5 - 12.0 * rng.uniform();
    const Vec3 radii (0.8 + 0.7 * rng.uniform(),
                      0.6 + 0.6 * rng.uniform(),
                      0.6 + 0.4 * rng.uniform());
    auto shrub =
        std::make_shared<Ellipsoid> (Vec3 (x, y, terrain->height (x, y) + 0.3),
                                     detail::rotationYpr (kPi * rng.uniform(), 0, 0),
                                     radii);
    shrub->porosity = 0.3;
    shrub->roughness = 0.04;
    builder.add (shrub, builder.newObject(), kVegetation, leaves());
  }

  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions ({Vec3 (-18.0, -1.5, 1.8),
                                               Vec3 (4.0, 1.5, 1.8),
                                               Vec3 (24.0, -1.0, 1.8),
                                               Vec3 (-4.0, -12.0, 1.8)},
                                              parameters.num_scanners,
                                              3);
  d.angular_step_deg = 0.3;
  d.max_range = 120.0;
  d.has_rgb = d.has_intensity = d.has_label = true;
  d.label_names = kOutdoorLabelNames;
}
} // namespace simulation
} // namespace pcl_ext
