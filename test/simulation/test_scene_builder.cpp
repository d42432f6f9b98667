/*
 * Tests of SceneBuilder: the ids it hands out and the crease and border curves each
 * shape brings with it.
 */
#include <pcl_ext/simulation/scene_builder.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace pcl_ext::simulation;

namespace {
using Kind = GroundTruthCurve::Kind;

/** Number of curves of \a kind between segments \a a and \a b (b = 0: borders of a). */
int
countCurves (const SceneGeometry& geometry, Kind kind, std::uint32_t a, std::uint32_t b)
{
  int n = 0;
  for (const auto& c : geometry.curves())
    n += c.kind == kind && ((c.segment_a == a && c.segment_b == b) ||
                            (b != 0 && c.segment_a == b && c.segment_b == a));
  return n;
}

const std::vector<std::vector<Vec2>> kSquare = {
    {Vec2 (0, 0), Vec2 (1, 0), Vec2 (1, 1), Vec2 (0, 1)}};
} // namespace

TEST (SceneBuilder, IdsStartAtOneAndCount)
{
  SceneBuilder builder;
  EXPECT_EQ (builder.newObject(), 1u);
  EXPECT_EQ (builder.newObject(), 2u);
  Material red;
  red.rgb = Eigen::Vector3f (255.f, 0.f, 0.f);
  const SurfaceInfo info = builder.newSurface (2, 7, red);
  EXPECT_EQ (info.segment, 1u);
  EXPECT_EQ (info.object, 2u);
  EXPECT_EQ (info.label, 7u);
  EXPECT_EQ (info.material.rgb, red.rgb);
  const std::uint32_t sphere =
      builder.add (std::make_shared<Sphere> (Vec3::Zero(), 1.0), 2, 7, red);
  EXPECT_EQ (sphere, 2u);
  // A part of an existing surface shares its segment id.
  builder.addPart (std::make_shared<Sphere> (Vec3 (3, 0, 0), 1.0), info);
  const auto& primitives = builder.geometry().primitives();
  ASSERT_EQ (primitives.size(), 2u);
  EXPECT_EQ (primitives[0]->info.segment, 2u);
  EXPECT_EQ (primitives[1]->info.segment, 1u);
  EXPECT_TRUE (builder.geometry().curves().empty());
}

TEST (SceneBuilder, PolygonEdgesAreBordersCreasesOrNothing)
{
  SceneBuilder builder;
  const std::uint32_t object = builder.newObject();
  const std::uint32_t free = builder.addPolygon (
      Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), kSquare, object, 1, Material());
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Border, free, 0), 4);
  // Edge 0 meets segment 9, edge 1 is free, edges 2 and 3 have no curve.
  const std::uint32_t mixed =
      builder.addPolygon (Vec3 (0, 0, 1),
                          Vec3::UnitX(),
                          Vec3::UnitY(),
                          kSquare,
                          object,
                          1,
                          Material(),
                          {{9, 0, SceneBuilder::kNoCurve, SceneBuilder::kNoCurve}});
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Crease, mixed, 9), 1);
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Border, mixed, 0), 1);
  EXPECT_EQ (builder.geometry().curves().size(), 6u);
  // The crease runs along edge 0, from vertex 0 to vertex 1, in world coordinates.
  const GroundTruthCurve& crease = builder.geometry().curves()[4];
  EXPECT_EQ (crease.a, Vec3 (0, 0, 1));
  EXPECT_EQ (crease.b, Vec3 (1, 0, 1));
}

TEST (SceneBuilder, BoxFacesAndEdges)
{
  SceneBuilder builder;
  const auto faces = builder.addBox (Vec3 (0, 0, 1),
                                     Eigen::Matrix3d::Identity(),
                                     Vec3 (1, 2, 1),
                                     builder.newObject(),
                                     2,
                                     Material());
  for (std::size_t f = 0; f < 6; ++f)
    EXPECT_EQ (faces[f], f + 1); // -x, +x, -y, +y, -z, +z
  EXPECT_EQ (builder.geometry().primitives().size(), 6u);
  ASSERT_EQ (builder.geometry().curves().size(), 12u);
  for (const auto& c : builder.geometry().curves())
    EXPECT_EQ (c.kind, Kind::Crease);
  // Faces of one axis never meet; faces of two axes meet once, along an edge of the
  // box.
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Crease, faces[0], faces[1]), 0);
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Crease, faces[1], faces[5]), 1);
  for (const auto& c : builder.geometry().curves())
    if ((c.segment_a == faces[1] && c.segment_b == faces[5]) ||
        (c.segment_a == faces[5] && c.segment_b == faces[1])) {
      EXPECT_EQ (c.a.x(), 1.0); // the +x face
      EXPECT_EQ (c.b.x(), 1.0);
      EXPECT_EQ (c.a.z(), 2.0); // the top face
      EXPECT_EQ (std::abs (c.a.y() - c.b.y()), 4.0);
    }

  // Standing on the ground (segment 1): no bottom face, its four edges are creases with
  // it.
  SceneBuilder on_ground;
  const std::uint32_t ground =
      on_ground.addPolygon (Vec3 (-5, -5, 0),
                            Vec3::UnitX(),
                            Vec3::UnitY(),
                            {{Vec2 (0, 0), Vec2 (10, 0), Vec2 (10, 10), Vec2 (0, 10)}},
                            on_ground.newObject(),
                            1,
                            Material());
  const auto standing = on_ground.addBox (Vec3 (0, 0, 1),
                                          Eigen::Matrix3d::Identity(),
                                          Vec3 (1, 1, 1),
                                          on_ground.newObject(),
                                          2,
                                          Material(),
                                          ground);
  EXPECT_EQ (standing[4], 0u);
  EXPECT_EQ (on_ground.geometry().primitives().size(), 6u); // the ground and five faces
  int with_ground = 0;
  for (const std::size_t f : {0, 1, 2, 3})
    with_ground +=
        countCurves (on_ground.geometry(), Kind::Crease, standing[f], ground);
  EXPECT_EQ (with_ground, 4);
}

TEST (SceneBuilder, FrustumEndsDecideTheirCurves)
{
  SceneBuilder builder;
  const std::uint32_t object = builder.newObject();
  // Open at the base (a border circle), capped at the top (a new segment and a crease).
  const std::uint32_t pipe = builder.addFrustum (Vec3::Zero(),
                                                 Vec3 (0, 0, 2),
                                                 3.0,
                                                 0.2,
                                                 0.2,
                                                 object,
                                                 1,
                                                 Material(),
                                                 EndCondition::open(),
                                                 EndCondition::capped());
  EXPECT_EQ (builder.geometry().primitives().size(), 2u); // the side and the cap
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Border, pipe, 0), 1);
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Crease, pipe, pipe + 1), 1);
  const GroundTruthCurve& top = builder.geometry().curves()[1];
  EXPECT_EQ (top.shape, GroundTruthCurve::Shape::Circle);
  EXPECT_NEAR ((top.a - Vec3 (0, 0, 3)).norm(), 0.0, 1e-12); // the axis is normalised
  EXPECT_EQ (top.radius, 0.2);
  // Joined to segment 40 at the base, continuing smoothly at the top: one crease only.
  const std::uint32_t leg = builder.addFrustum (Vec3 (5, 0, 0),
                                                Vec3::UnitX(),
                                                1.0,
                                                0.1,
                                                0.1,
                                                object,
                                                1,
                                                Material(),
                                                EndCondition::joined (40),
                                                EndCondition::smooth());
  EXPECT_EQ (countCurves (builder.geometry(), Kind::Crease, leg, 40), 1);
  EXPECT_EQ (builder.geometry().curves().size(), 3u);
  // A cone's apex has no rim.
  builder.addFrustum (Vec3 (9, 0, 0),
                      Vec3::UnitZ(),
                      1.0,
                      0.3,
                      0.0,
                      object,
                      1,
                      Material(),
                      EndCondition::open(),
                      EndCondition::open());
  EXPECT_EQ (builder.geometry().curves().size(), 4u);
}

TEST (SceneBuilder, IntersectionOfATrunkWithTheGround)
{
  SceneBuilder builder;
  const std::uint32_t ground =
      builder.addPolygon (Vec3 (-5, -5, 0),
                          Vec3::UnitX(),
                          Vec3::UnitY(),
                          {{Vec2 (0, 0), Vec2 (10, 0), Vec2 (10, 10), Vec2 (0, 10)}},
                          builder.newObject(),
                          1,
                          Material(),
                          {{SceneBuilder::kNoCurve,
                            SceneBuilder::kNoCurve,
                            SceneBuilder::kNoCurve,
                            SceneBuilder::kNoCurve}});
  // A trunk of radius 0.2 from 1 m below the ground to 2 m above it.
  const ConeFrustum trunk (Vec3 (1, 1, -1), Vec3::UnitZ(), 3.0, 0.2, 0.2);
  const auto& plane = *builder.geometry().primitives()[0];
  builder.addIntersection (trunk, 7, plane, ground, 64);
  ASSERT_EQ (builder.geometry().curves().size(), 64u); // a closed chain
  for (const auto& c : builder.geometry().curves()) {
    EXPECT_EQ (c.kind, Kind::Crease);
    EXPECT_EQ (c.segment_a, 7u);
    EXPECT_EQ (c.segment_b, ground);
    EXPECT_NEAR (c.a.z(), 0.0, 1e-9);
    EXPECT_NEAR ((c.a - Vec3 (1, 1, 0)).norm(), 0.2, 1e-9);
  }
}
