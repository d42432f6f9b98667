/*
 * pcl_ext: indoor rooms (Belton & Lichti figures 2-6) and a pipe rack (Sithole &
 * Mapurisa figure 12).
 */
#include "scene_parts.h"

#include <cmath>

namespace pcl_ext {
namespace simulation {
using detail::material;

namespace {
constexpr double kDeg = 0.017453292519943295;
}

void
describeIndoorScene (const SceneParameters& parameters, SceneDescription& d)
{
  enum : std::uint32_t { Wall = 1, Floor, Ceiling, Box, Column, Pipe };
  SceneBuilder builder;
  const std::uint32_t none = SceneBuilder::kNoCurve;
  const Material plaster = material (225, 220, 210, 0.7);
  const Material concrete = material (150, 150, 145, 0.45);
  const Material wood = material (165, 120, 75, 0.5, 10.f);
  const Material steel = material (120, 125, 135, 0.55);
  const double length = 14.0, width = 6.0, height = 3.0;
  const double xa = 7.9, xb = 8.1; // faces of the interior wall
  const double door0 = 2.5, door1 = 3.4, door_h = 2.1;

  const std::uint32_t shell = builder.newObject();
  const std::vector<Vec2> rect{
      Vec2 (0, 0), Vec2 (length, 0), Vec2 (length, width), Vec2 (0, width)};
  const std::uint32_t floor = builder.addPolygon (Vec3::Zero(),
                                                  Vec3::UnitX(),
                                                  Vec3::UnitY(),
                                                  {rect},
                                                  shell,
                                                  Floor,
                                                  concrete,
                                                  {{none, none, none, none}});
  detail::WindowLayout windows;
  windows.width = 1.0;
  windows.height = 1.2;
  windows.spacing = 3.5;
  windows.storey = height;
  windows.sill = 0.9;
  windows.margin = 1.0;
  // Walls: 0 (y = 0), 1 (x = 14), 2 (y = 6), 3 (x = 0); the last has no windows.
  const detail::PrismSegments prism = detail::addPrism (builder,
                                                        rect,
                                                        0.0,
                                                        height,
                                                        floor,
                                                        true,
                                                        shell,
                                                        Wall,
                                                        Ceiling,
                                                        plaster,
                                                        plaster,
                                                        &windows,
                                                        {true, true, true, false});
  const std::uint32_t ceiling = prism.roof;

  // The interior wall, 0.2 m thick, with a door: two faces, two jambs and a lintel.
  const std::vector<Vec2> face_ring{Vec2 (0, 0),
                                    Vec2 (door0, 0),
                                    Vec2 (door0, door_h),
                                    Vec2 (door1, door_h),
                                    Vec2 (door1, 0),
                                    Vec2 (width, 0),
                                    Vec2 (width, height),
                                    Vec2 (0, height)};
  const std::vector<std::uint32_t> no_curves (face_ring.size(), none);
  std::uint32_t faces[2];
  const double face_x[2] = {xa, xb};
  for (int f = 0; f < 2; ++f)
    faces[f] = builder.addPolygon (Vec3 (face_x[f], 0, 0),
                                   Vec3::UnitY(),
                                   Vec3::UnitZ(),
                                   {face_ring},
                                   shell,
                                   Wall,
                                   plaster,
                                   {no_curves});
  const double t = xb - xa;
  const std::vector<std::uint32_t> four (4, none);
  const std::uint32_t jamb0 = builder.addPolygon (
      Vec3 (xa, door0, 0),
      Vec3::UnitX(),
      Vec3::UnitZ(),
      {{Vec2 (0, 0), Vec2 (t, 0), Vec2 (t, door_h), Vec2 (0, door_h)}},
      shell,
      Wall,
      plaster,
      {four});
  const std::uint32_t jamb1 = builder.addPolygon (
      Vec3 (xa, door1, 0),
      Vec3::UnitX(),
      Vec3::UnitZ(),
      {{Vec2 (0, 0), Vec2 (t, 0), Vec2 (t, door_h), Vec2 (0, door_h)}},
      shell,
      Wall,
      plaster,
      {four});
  const std::uint32_t lintel = builder.addPolygon (
      Vec3 (xa, door0, door_h),
      Vec3::UnitX(),
      Vec3::UnitY(),
      {{Vec2 (0, 0), Vec2 (t, 0), Vec2 (t, door1 - door0), Vec2 (0, door1 - door0)}},
      shell,
      Wall,
      plaster,
      {four});
  for (int f = 0; f < 2; ++f) {
    const double x = face_x[f];
    const std::uint32_t s = faces[f];
    builder.addLine (Vec3 (x, 0, 0), Vec3 (x, door0, 0), s, floor);
    builder.addLine (Vec3 (x, door1, 0), Vec3 (x, width, 0), s, floor);
    builder.addLine (Vec3 (x, 0, height), Vec3 (x, width, height), s, ceiling);
    builder.addLine (Vec3 (x, 0, 0), Vec3 (x, 0, height), s, prism.walls[0]);
    builder.addLine (Vec3 (x, width, 0), Vec3 (x, width, height), s, prism.walls[2]);
    builder.addLine (Vec3 (x, door0, 0), Vec3 (x, door0, door_h), s, jamb0);
    builder.addLine (Vec3 (x, door1, 0), Vec3 (x, door1, door_h), s, jamb1);
    builder.addLine (Vec3 (x, door0, door_h), Vec3 (x, door1, door_h), s, lintel);
  }
  for (const auto& [y, jamb] :
       {std::pair<double, std::uint32_t> (door0, jamb0), {door1, jamb1}}) {
    builder.addLine (Vec3 (xa, y, 0), Vec3 (xb, y, 0), jamb, floor);
    builder.addLine (Vec3 (xa, y, door_h), Vec3 (xb, y, door_h), jamb, lintel);
  }

  // Furniture: crates on the floor, a column, pipes along the ceiling.
  builder.addBox (Vec3 (2.0, 4.6, 0.45),
                  detail::rotationYpr (20 * kDeg, 0, 0),
                  Vec3 (0.6, 0.4, 0.45),
                  builder.newObject(),
                  Box,
                  wood,
                  floor);
  builder.addBox (Vec3 (12.5, 1.3, 0.6),
                  detail::rotationYpr (-10 * kDeg, 0, 0),
                  Vec3 (0.5, 0.5, 0.6),
                  builder.newObject(),
                  Box,
                  wood,
                  floor);
  builder.addBox (Vec3 (6.6, 0.8, 0.3),
                  detail::rotationYpr (45 * kDeg, 0, 0),
                  Vec3 (0.3, 0.3, 0.3),
                  builder.newObject(),
                  Box,
                  wood,
                  floor);
  builder.addFrustum (Vec3 (5.5, 3.2, 0),
                      Vec3::UnitZ(),
                      height,
                      0.25,
                      0.25,
                      builder.newObject(),
                      Column,
                      concrete,
                      EndCondition::joined (floor),
                      EndCondition::joined (ceiling));
  builder.addFrustum (Vec3 (10.0, 0, 2.6),
                      Vec3::UnitY(),
                      width,
                      0.08,
                      0.08,
                      builder.newObject(),
                      Pipe,
                      steel,
                      EndCondition::joined (prism.walls[0]),
                      EndCondition::joined (prism.walls[2]));
  detail::addPipeRun (builder,
                      {Vec3 (0, 1.0, 2.7), Vec3 (4.0, 1.0, 2.7), Vec3 (4.0, 1.0, 0.0)},
                      0.1,
                      0.3,
                      builder.newObject(),
                      Pipe,
                      steel,
                      EndCondition::joined (prism.walls[3]),
                      EndCondition::joined (floor));

  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions (
      {Vec3 (3.6, 2.4, 1.5), Vec3 (11.0, 3.6, 1.5), Vec3 (2.2, 4.0, 1.6)},
      parameters.num_scanners,
      2);
  d.angular_step_deg = 0.5;
  d.max_range = 50.0;
  d.has_rgb = d.has_intensity = d.has_label = true;
  d.label_names = {"none", "wall", "floor", "ceiling", "box", "column", "pipe"};
}

void
describePipesScene (const SceneParameters& parameters, SceneDescription& d)
{
  enum : std::uint32_t { Ground = 1, Support, PipeLabel };
  SceneBuilder builder;
  const Material concrete = material (150, 148, 140, 0.45);
  const Material paint = material (220, 180, 40, 0.6);
  const Material steel[3] = {material (150, 155, 160, 0.55),
                             material (90, 110, 150, 0.4),
                             material (170, 60, 50, 0.45)};
  const std::uint32_t ground =
      builder.addPolygon (Vec3::Zero(),
                          Vec3::UnitX(),
                          Vec3::UnitY(),
                          {{Vec2 (-8, -9), Vec2 (20, -9), Vec2 (20, 9), Vec2 (-8, 9)}},
                          builder.newObject(),
                          Ground,
                          concrete);

  // Portal frames: two columns and a beam each; the column tops meet the beam's
  // underside.
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (const double x : {0.0, 6.0, 12.0}) {
    const std::uint32_t frame = builder.newObject();
    const auto beam = builder.addBox (
        Vec3 (x, 0, 3.15), I, Vec3 (0.15, 2.1, 0.15), frame, Support, paint);
    for (const double y : {-1.8, 1.8}) {
      const auto column = builder.addBox (
          Vec3 (x, y, 1.5), I, Vec3 (0.15, 0.15, 1.5), frame, Support, paint, ground);
      const double x0 = x - 0.15, x1 = x + 0.15, y0 = y - 0.15, y1 = y + 0.15;
      builder.addLine (Vec3 (x0, y0, 3), Vec3 (x0, y1, 3), column[0], beam[4]);
      builder.addLine (Vec3 (x1, y0, 3), Vec3 (x1, y1, 3), column[1], beam[4]);
      builder.addLine (Vec3 (x0, y0, 3), Vec3 (x1, y0, 3), column[2], beam[4]);
      builder.addLine (Vec3 (x0, y1, 3), Vec3 (x1, y1, 3), column[3], beam[4]);
    }
  }

  // Pipes resting on the beams (top at z = 3.3).
  struct PipeSpec {
    double radius, y;
    int shape; // 0 straight, 1 elbow down at the end, 2 elbow sideways, 3 rises from
               // the ground
  };
  const PipeSpec pipes[] = {{0.25, -1.4, 0},
                            {0.15, -0.8, 1},
                            {0.10, -0.35, 0},
                            {0.08, 0.0, 2},
                            {0.20, 0.5, 0},
                            {0.05, 1.0, 0},
                            {0.12, 1.5, 3}};
  int k = 0;
  for (const auto& p : pipes) {
    const double z = 3.3 + p.radius, bend = std::max (3.0 * p.radius, 0.3);
    std::vector<Vec3> line;
    EndCondition first = EndCondition::open(), last = EndCondition::open();
    switch (p.shape) {
    case 0:
      line = {Vec3 (-4, p.y, z), Vec3 (16, p.y, z)};
      break;
    case 1:
      line = {Vec3 (-4, p.y, z), Vec3 (15, p.y, z), Vec3 (15, p.y, 0)};
      last = EndCondition::joined (ground);
      break;
    case 2:
      line = {Vec3 (-4, p.y, z), Vec3 (17, p.y, z), Vec3 (17, -6, z)};
      break;
    default:
      line = {Vec3 (-3, p.y, 0), Vec3 (-3, p.y, z), Vec3 (16, p.y, z)};
      first = EndCondition::joined (ground);
      break;
    }
    detail::addPipeRun (builder,
                        line,
                        p.radius,
                        bend,
                        builder.newObject(),
                        PipeLabel,
                        steel[k++ % 3],
                        first,
                        last);
  }

  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions ({Vec3 (3.0, -7.0, 1.6),
                                               Vec3 (9.0, 6.5, 1.6),
                                               Vec3 (-5.0, 5.0, 1.6),
                                               Vec3 (18.0, -3.0, 1.6)},
                                              parameters.num_scanners,
                                              3);
  d.angular_step_deg = 0.3;
  d.max_range = 80.0;
  d.has_rgb = d.has_intensity = d.has_label = true;
  d.label_names = {"none", "ground", "support", "pipe"};
}
} // namespace simulation
} // namespace pcl_ext
