/*
 * pcl_ext: the simulated test objects of Sithole & Mapurisa (figures 10, 11 and 13).
 */
#include "scene_parts.h"

#include <cmath>

namespace pcl_ext {
namespace simulation {
using detail::material;

void
describeCubesScene (const SceneParameters& parameters, SceneDescription& d)
{
  // Eight cubes floating on a 4 x 2 grid, each a different size and a random
  // orientation.
  SceneBuilder builder;
  RandomStream rng = detail::layoutStream (parameters.seed, 0xc0be5ULL);
  const double sizes[8] = {0.6, 1.0, 1.4, 0.8, 1.8, 0.5, 1.2, 2.0};
  for (int k = 0; k < 8; ++k) {
    const Vec3 centre (-6.0 + 4.0 * (k % 4), 4.0 * (k / 4), 1.5 + 0.6 * rng.uniform());
    const double h = 0.5 * sizes[k];
    builder.addBox (centre,
                    detail::randomRotation (rng),
                    Vec3 (h, h, h),
                    builder.newObject(),
                    0,
                    material (200, 200, 200, 0.6));
  }
  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions (
      {Vec3 (-4.0, -9.0, 2.0), Vec3 (6.0, -8.0, 2.5), Vec3 (0.0, 14.0, 2.0)},
      parameters.num_scanners,
      2);
  d.default_points = 41500;
  d.angular_step_deg = 0.2;
}

void
describeSpheresScene (const SceneParameters& parameters, SceneDescription& d)
{
  // Three nests of concentric spheres and two single spheres. The outer spheres of a
  // nest are cut open towards the scanners so that the spheres inside can be scanned at
  // all.
  SceneBuilder builder;
  d.scan_positions = detail::choosePositions (
      {Vec3 (-2.0, -12.0, 2.5), Vec3 (4.0, -11.0, 3.5), Vec3 (1.0, 12.0, 2.5)},
      parameters.num_scanners,
      2);
  Vec3 viewer = Vec3::Zero();
  for (const auto& p : d.scan_positions)
    viewer += p;
  viewer /= static_cast<double> (d.scan_positions.size());
  RandomStream rng = detail::layoutStream (parameters.seed, 0x5feeULL);
  struct Nest {
    Vec3 centre;
    std::vector<double> radii;
  };
  const std::vector<Nest> nests{{Vec3 (-4.5, 0.0, 2.5), {2.0, 1.3, 0.6}},
                                {Vec3 (0.5, 1.0, 2.0), {1.5, 0.8}},
                                {Vec3 (5.0, 0.0, 2.5), {1.8, 1.1, 0.6, 0.25}},
                                {Vec3 (-1.5, 5.0, 1.2), {0.7}},
                                {Vec3 (3.0, 5.5, 1.0), {0.5}}};
  for (const auto& nest : nests) {
    for (std::size_t k = 0; k < nest.radii.size(); ++k) {
      const double r = nest.radii[k] * (1.0 + 0.05 * (rng.uniform() - 0.5));
      const bool innermost = k + 1 == nest.radii.size();
      const Vec3 axis = (viewer - nest.centre).normalized();
      // Cut height 0.25 r: an opening of about 0.97 r facing the scanners.
      const double cut = innermost ? std::numeric_limits<double>::infinity() : 0.25 * r;
      const std::uint32_t segment =
          builder.add (std::make_shared<Sphere> (nest.centre, r, axis, cut),
                       builder.newObject(),
                       0,
                       material (200, 200, 200, 0.6));
      if (!innermost)
        builder.addCircle (
            nest.centre + cut * axis, axis, std::sqrt (r * r - cut * cut), segment, 0);
    }
  }
  d.geometry = std::move (builder.geometry());
  d.default_points = 155000;
  d.angular_step_deg = 0.1;
}

void
describeCoaxialScene (const SceneParameters& parameters, SceneDescription& d)
{
  // A pipe of radius 0.2 m runs along x from -1.5 to 6 m; from x = 0 to 3 it lies
  // inside a coaxial open pipe of radius 0.4 m closed at x = 3 by an annular step; a
  // flange of radius 0.3 m sits on it at x = 4.5 m. A second assembly, vertical,
  // reduces from 0.3 to 0.15 m.
  SceneBuilder builder;
  const Material steel = material (190, 190, 195, 0.6);
  const Vec3 x = Vec3::UnitX();
  const double zc = 1.2;
  {
    const std::uint32_t object = builder.newObject();
    const std::uint32_t outer = builder.addFrustum (Vec3 (0, 0, zc),
                                                    x,
                                                    3.0,
                                                    0.4,
                                                    0.4,
                                                    object,
                                                    0,
                                                    steel,
                                                    EndCondition::open(),
                                                    EndCondition::smooth());
    const std::uint32_t step = builder.add (
        std::make_shared<Annulus> (Vec3 (3, 0, zc), x, 0.2, 0.4), object, 0, steel);
    builder.addCircle (Vec3 (3, 0, zc), x, 0.4, outer, step);
    const std::uint32_t inner = builder.addFrustum (Vec3 (-1.5, 0, zc),
                                                    x,
                                                    7.5,
                                                    0.2,
                                                    0.2,
                                                    object,
                                                    0,
                                                    steel,
                                                    EndCondition::capped(),
                                                    EndCondition::capped());
    builder.addCircle (Vec3 (3, 0, zc), x, 0.2, inner, step);
    const std::uint32_t flange = builder.addFrustum (Vec3 (4.5, 0, zc),
                                                     x,
                                                     0.3,
                                                     0.3,
                                                     0.3,
                                                     object,
                                                     0,
                                                     steel,
                                                     EndCondition::smooth(),
                                                     EndCondition::smooth());
    for (const double xf : {4.5, 4.8}) {
      const std::uint32_t face = builder.add (
          std::make_shared<Annulus> (Vec3 (xf, 0, zc), x, 0.2, 0.3), object, 0, steel);
      builder.addCircle (Vec3 (xf, 0, zc), x, 0.3, flange, face);
      builder.addCircle (Vec3 (xf, 0, zc), x, 0.2, inner, face);
    }
  }
  {
    const std::uint32_t object = builder.newObject();
    const Vec3 z = Vec3::UnitZ();
    const Vec3 base (2.0, 2.5, 0.0);
    const std::uint32_t wide = builder.addFrustum (base,
                                                   z,
                                                   1.2,
                                                   0.3,
                                                   0.3,
                                                   object,
                                                   0,
                                                   steel,
                                                   EndCondition::open(),
                                                   EndCondition::smooth());
    const std::uint32_t step = builder.add (
        std::make_shared<Annulus> (base + 1.2 * z, z, 0.15, 0.3), object, 0, steel);
    builder.addCircle (base + 1.2 * z, z, 0.3, wide, step);
    const std::uint32_t narrow = builder.addFrustum (base + 1.2 * z,
                                                     z,
                                                     1.3,
                                                     0.15,
                                                     0.15,
                                                     object,
                                                     0,
                                                     steel,
                                                     EndCondition::joined (step),
                                                     EndCondition::open());
    (void)narrow;
  }
  d.geometry = std::move (builder.geometry());
  d.scan_positions = detail::choosePositions (
      {Vec3 (1.0, -4.0, 1.8), Vec3 (4.5, -3.0, 1.0), Vec3 (0.0, 5.5, 1.6)},
      parameters.num_scanners,
      2);
  d.angular_step_deg = 0.1;
}
} // namespace simulation
} // namespace pcl_ext
