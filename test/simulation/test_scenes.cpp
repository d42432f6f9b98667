/*
 * Ground truth of the synthetic scenes: classes, plane residuals, occlusion, point
 * counts, the building's transform and bad parameters.
 */
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>

using namespace pcl_ext;
using namespace pcl_ext::simulation;

namespace {
constexpr double kDegree = 0.017453292519943295;

Vec3
scenePoint (const SyntheticScene& scene, std::size_t i)
{
  const auto& p = scene.cloud[i];
  return scene.cloud_from_scene.inverse() * Vec3 (p.x, p.y, p.z);
}

// Brute-force distances to the crease and border curves of a segment.
void
curveDistances (const SceneGeometry& geometry,
                const Vec3& p,
                std::uint32_t segment,
                double& crease,
                double& border)
{
  crease = border = std::numeric_limits<double>::infinity();
  for (const auto& c : geometry.curves())
    if (c.segment_a == segment || c.segment_b == segment) {
      const double d = c.distance (p);
      if (c.kind == GroundTruthCurve::Kind::Crease)
        crease = std::min (crease, d);
      else
        border = std::min (border, d);
    }
}

class SceneGroundTruth : public ::testing::TestWithParam<std::string> {};
} // namespace

// With noise 0 the measured point is the true one: every point's class must agree with
// its distance to its own segment's curves, compared with the local spacing range *
// step. The coverage borders only turn Surface points into Boundary points, and Edge
// points of a crease whose other face the scan did not see near them.
TEST_P (SceneGroundTruth, ClassesMatchCurveDistances)
{
  SceneParameters parameters;
  parameters.noise = 0.0;
  parameters.points = 15000;
  SyntheticScene covered;
  ASSERT_TRUE (generateScene (GetParam(), parameters, covered));
  parameters.coverage_boundaries = false;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene (GetParam(), parameters, scene));
  ASSERT_GT (scene.cloud.size(), 10000u);
  ASSERT_EQ (covered.cloud.size(), scene.cloud.size());
  std::size_t shadow_borders = 0, one_sided_creases = 0;
  for (std::size_t i = 0; i < scene.cloud.size(); ++i)
    if (covered.cloud[i].point_class != scene.cloud[i].point_class) {
      ASSERT_EQ (covered.cloud[i].point_class,
                 static_cast<std::uint32_t> (PointClass::Boundary));
      if (scene.cloud[i].point_class == static_cast<std::uint32_t> (PointClass::Edge))
        ++one_sided_creases;
      else {
        ASSERT_EQ (scene.cloud[i].point_class,
                   static_cast<std::uint32_t> (PointClass::Surface));
        ++shadow_borders;
      }
    }
  // A crease's points stay edges where the scan saw both its faces: not all of them
  // are seen from one side only.
  std::size_t creases = 0;
  for (const auto& p : scene.cloud)
    creases += p.point_class == static_cast<std::uint32_t> (PointClass::Edge);
  if (creases > 0)
    EXPECT_LT (one_sided_creases, creases) << GetParam();
  else
    EXPECT_EQ (one_sided_creases, 0u) << GetParam();
  // Every scene has occlusions or a blind cone; none is all border.
  EXPECT_GT (shadow_borders, 0u) << GetParam();
  EXPECT_LT (shadow_borders, scene.cloud.size() / 4) << GetParam();
  ASSERT_EQ (scene.scanner_of_point.size(), scene.cloud.size());
  const SceneGeometry& geometry = scene.description->geometry;
  std::map<std::uint32_t, std::size_t> per_class;
  // Tolerance: float coordinates (about 1e-5 m at 100 m) against the exact threshold.
  const double eps = 1e-4;
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    const auto& p = scene.cloud[i];
    ASSERT_GE (p.segment, 1u);
    ASSERT_GE (p.object, 1u);
    const Vec3 q = scenePoint (scene, i);
    const double range = (q - scene.scan_positions[scene.scanner_of_point[i]]).norm();
    const double threshold = range * scene.angular_step_deg * kDegree;
    double crease, border;
    ASSERT_LT (p.segment, scene.surface_of_segment.size());
    curveDistances (geometry, q, scene.surface_of_segment[p.segment], crease, border);
    const auto cls = static_cast<PointClass> (p.point_class);
    ++per_class[p.point_class];
    if (cls == PointClass::Edge)
      EXPECT_LE (crease, threshold + eps) << GetParam() << " point " << i;
    else if (cls == PointClass::Boundary)
      EXPECT_LE (border, threshold + eps) << GetParam() << " point " << i;
    else {
      ASSERT_EQ (cls, PointClass::Surface);
      EXPECT_GT (crease, threshold - eps) << GetParam() << " point " << i;
      EXPECT_GT (border, threshold - eps) << GetParam() << " point " << i;
    }
  }
  std::cout << "[ " << GetParam() << " ] " << scene.cloud.size() << " points, step "
            << scene.angular_step_deg << " deg: surface " << per_class[1] << ", edge "
            << per_class[2] << ", boundary " << per_class[3] << std::endl;
  EXPECT_EQ (per_class[0], 0u);
  EXPECT_GT (per_class[1], scene.cloud.size() / 2);
  if (GetParam() != "spheres") // spheres have no crease
    EXPECT_GT (per_class[2], 0u);
}

// Nothing is returned from behind a closer (opaque) surface as seen from its scanner.
TEST_P (SceneGroundTruth, NoPointBehindACloserSurface)
{
  SceneParameters parameters;
  parameters.noise = 0.0;
  parameters.points = 15000;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene (GetParam(), parameters, scene));
  const SceneGeometry& geometry = scene.description->geometry;
  for (std::size_t i = 0; i < scene.cloud.size(); i += 7) {
    const Vec3 q = scenePoint (scene, i);
    const Vec3 o = scene.scan_positions[scene.scanner_of_point[i]];
    const Ray ray{o, (q - o).normalized()};
    const double range = (q - o).norm();
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& primitive : geometry.primitives()) {
      double t;
      Vec3 n;
      if (primitive->porosity == 0.0 && primitive->intersect (ray, 0.0, nearest, t, n))
        nearest = t;
    }
    EXPECT_GE (nearest, range - 1e-3) << GetParam() << " point " << i;
  }
}

INSTANTIATE_TEST_SUITE_P (AllScenes,
                          SceneGroundTruth,
                          ::testing::Values ("indoor",
                                             "cubes",
                                             "spheres",
                                             "coaxial",
                                             "pipes",
                                             "tree",
                                             "building",
                                             "street"));

TEST (Scenes, PlanarResidualsMatchTheNoise)
{
  // Residuals along the true plane normal are noise * cos(incidence).
  for (const std::string name : {"indoor", "cubes", "building"}) {
    SceneParameters parameters;
    parameters.noise = 0.01;
    parameters.points = 60000;
    SyntheticScene scene;
    ASSERT_TRUE (generateScene (name, parameters, scene));
    const SceneGeometry& geometry = scene.description->geometry;
    std::map<std::uint32_t, const PlanarPolygon*> planes;
    for (const auto& primitive : geometry.primitives())
      if (const auto* plane = dynamic_cast<const PlanarPolygon*> (primitive.get()))
        planes[plane->info.segment] = plane;
    struct Sums {
      double r2 = 0, cos2 = 0;
      std::size_t n = 0;
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
      Vec3 sum = Vec3::Zero();
    };
    std::map<std::uint32_t, Sums> sums;
    for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
      const auto it = planes.find (scene.surface_of_segment[scene.cloud[i].segment]);
      if (it == planes.end())
        continue;
      const Vec3 q = scenePoint (scene, i);
      const Vec3 d = (q - scene.scan_positions[scene.scanner_of_point[i]]).normalized();
      Sums& s = sums[it->first];
      const double r = it->second->implicit (q);
      s.r2 += r * r;
      s.cos2 += std::pow (d.dot (it->second->normal()), 2);
      s.n += 1;
      s.sum += q;
      s.scatter += q * q.transpose();
    }
    int checked = 0;
    for (const auto& [segment, s] : sums) {
      if (s.n < 500)
        continue;
      const double rms = std::sqrt (s.r2 / s.n);
      const double expected = 0.01 * std::sqrt (s.cos2 / s.n);
      EXPECT_NEAR (rms, expected, 0.1 * expected) << name << " segment " << segment;
      // A least-squares plane fits as well as the true plane.
      const Vec3 mean = s.sum / s.n;
      const Eigen::Matrix3d cov = s.scatter / s.n - mean * mean.transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (cov);
      EXPECT_NEAR (
          std::sqrt (std::max (0.0, solver.eigenvalues()[0])), expected, 0.1 * expected)
          << name << " segment " << segment;
      ++checked;
    }
    EXPECT_GT (checked, 2) << name;
  }
}

TEST (Scenes, PointCountsOfThePapers)
{
  SceneParameters parameters;
  SyntheticScene cubes, spheres;
  ASSERT_TRUE (generateScene ("cubes", parameters, cubes));
  ASSERT_TRUE (generateScene ("spheres", parameters, spheres));
  EXPECT_NEAR (static_cast<double> (cubes.cloud.size()), 41500.0, 0.03 * 41500.0);
  EXPECT_NEAR (static_cast<double> (spheres.cloud.size()), 155000.0, 0.03 * 155000.0);
  // 8 cubes of 6 faces (some hidden), one object each.
  std::map<std::uint32_t, int> objects;
  for (const auto& p : cubes.cloud)
    objects[p.object] = 1;
  EXPECT_EQ (objects.size(), 8u);
}

TEST (Scenes, IndoorSegmentsAreConnectedPieces)
{
  // The interior wall (faces at x = 7.9 and 8.1, full height, a door) cuts the ceiling
  // and the two long walls: each room sees its own part, a segment apiece. Only the
  // floor is seen whole, from both rooms through the door. Without connected segments,
  // one id per surface.
  SceneParameters parameters;
  SyntheticScene pieces, surfaces;
  ASSERT_TRUE (generateScene ("indoor", parameters, pieces));
  parameters.connected_segments = false;
  ASSERT_TRUE (generateScene ("indoor", parameters, surfaces));
  ASSERT_EQ (pieces.cloud.size(), surfaces.cloud.size());
  const auto spans = [] (const SyntheticScene& scene) {
    std::map<std::uint32_t, std::pair<bool, bool>> sides; // segment -> (room 1, room 2)
    for (const auto& p : scene.cloud) {
      auto& s = sides[p.segment];
      s.first = s.first || p.x < 7.85;
      s.second = s.second || p.x > 8.15;
    }
    std::map<std::uint32_t, std::uint32_t>
        labels; // scene label -> segments in both rooms
    for (const auto& p : scene.cloud)
      if (sides[p.segment].first && sides[p.segment].second)
        labels[p.label] += 1;
    return labels;
  };
  const auto both = spans (pieces);
  ASSERT_EQ (both.size(), 1u);
  EXPECT_EQ (both.begin()->first, 2u);         // the floor
  EXPECT_GT (spans (surfaces).count (3u), 0u); // the ceiling, as one surface
  // Every piece maps to its surface; the ceiling is in at least two pieces.
  std::map<std::uint32_t, std::size_t> ceiling_pieces;
  for (std::size_t i = 0; i < pieces.cloud.size(); ++i) {
    ASSERT_EQ (pieces.cloud[i].object, surfaces.cloud[i].object);
    ASSERT_EQ (pieces.surface_of_segment.at (pieces.cloud[i].segment),
               surfaces.cloud[i].segment);
    if (pieces.cloud[i].label == 3u)
      ++ceiling_pieces[pieces.cloud[i].segment];
  }
  EXPECT_GE (ceiling_pieces.size(), 2u);
}

TEST (Scenes, TargetPointCount)
{
  SceneParameters parameters;
  parameters.points = 200000;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("street", parameters, scene));
  EXPECT_NEAR (static_cast<double> (scene.cloud.size()), 200000.0, 0.03 * 200000.0);
}

TEST (Scenes, OffsetShiftsEveryPoint)
{
  SceneParameters parameters;
  parameters.angular_step_deg = 0.5;
  SyntheticScene local, shifted;
  ASSERT_TRUE (generateScene ("cubes", parameters, local));
  parameters.offset = Vec3 (1000.0, -2000.0, 30.0);
  ASSERT_TRUE (generateScene ("cubes", parameters, shifted));
  ASSERT_EQ (local.cloud.size(), shifted.cloud.size());
  for (std::size_t i = 0; i < local.cloud.size(); ++i) {
    EXPECT_NEAR (shifted.cloud[i].x, local.cloud[i].x + 1000.0, 1e-3);
    EXPECT_NEAR (shifted.cloud[i].y, local.cloud[i].y - 2000.0, 1e-3);
    EXPECT_NEAR (shifted.cloud[i].z, local.cloud[i].z + 30.0, 1e-3);
    EXPECT_EQ (shifted.cloud[i].segment, local.cloud[i].segment);
  }
}

TEST (Scenes, BuildingTransformMapsWallsOntoTheFootprint)
{
  SceneParameters parameters;
  parameters.noise = 0.02;
  parameters.points = 100000;
  parameters.superfluous_planes = 3;
  parameters.missing_walls = 1;
  parameters.offset = Vec3 (85000.0, 445000.0, 0.0);
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("building", parameters, scene));
  ASSERT_EQ (scene.footprint.size(), 12u); // the H-shaped default plan
  EXPECT_FALSE (scene.cloud_from_scene.matrix().isIdentity (1e-3)); // an arbitrary pose
  const Eigen::Matrix4d T = scene.scan_to_map;
  EXPECT_NEAR ((T.topLeftCorner<3, 3>().determinant()), 1.0, 1e-9);
  std::size_t walls = 0, ground = 0;
  std::map<std::uint32_t, std::size_t> labels;
  for (const auto& p : scene.cloud) {
    ++labels[p.label];
    const Eigen::Vector4d m = T * Eigen::Vector4d (p.x, p.y, p.z, 1.0);
    if (p.label == 1) {
      double best = 1e9;
      const std::size_t n = scene.footprint.size();
      for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Vector2d a = scene.footprint[k],
                              d = scene.footprint[(k + 1) % n] - a;
        const double s =
            std::clamp ((m.head<2>() - a).dot (d) / d.squaredNorm(), 0.0, 1.0);
        best = std::min (best, (m.head<2>() - (a + s * d)).norm());
      }
      EXPECT_LT (best, 6.0 * 0.02 + 0.01); // float coordinates lose ~1e-5 m of the pose
      EXPECT_GT (m.z(), -0.2);
      EXPECT_LT (m.z(), parameters.building_height + 0.2);
      ++walls;
    }
    else if (p.label == 2) {
      EXPECT_NEAR (m.z(), 0.0, 6.0 * 0.02 + 0.01);
      ++ground;
    }
  }
  EXPECT_GT (walls, 10000u);
  EXPECT_GT (ground, 10000u);
  EXPECT_GT (labels[4], 0u); // superfluous planes
  EXPECT_GT (labels[5], 0u); // vegetation hiding a wall
}

TEST (Scenes, BuildingFromAGivenFootprintAndPose)
{
  SceneParameters parameters;
  parameters.points = 30000;
  parameters.footprint = {Eigen::Vector2d (0, 0),
                          Eigen::Vector2d (0, 15),
                          Eigen::Vector2d (20, 15),
                          Eigen::Vector2d (20, 0)}; // clockwise: reversed internally
  parameters.has_pose = true;
  parameters.pose = Eigen::Isometry3d::Identity();
  parameters.pose.translation() = Vec3 (1, 2, 3);
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("building", parameters, scene));
  EXPECT_TRUE ((scene.scan_to_map.topRightCorner<3, 1>().isApprox (Vec3 (-1, -2, -3))));
  EXPECT_GT (scene.cloud.size(), 20000u);
}

TEST (Scenes, StreetHasEveryClassWithColourAndIntensity)
{
  SceneParameters parameters;
  parameters.points = 100000;
  SyntheticScene scene;
  ASSERT_TRUE (generateScene ("street", parameters, scene));
  ASSERT_TRUE (scene.has_rgb && scene.has_intensity && scene.has_label);
  std::map<std::uint32_t, std::size_t> labels;
  std::map<std::uint32_t, double> green;
  for (const auto& p : scene.cloud) {
    ++labels[p.label];
    green[p.label] += p.g;
    EXPECT_GE (p.intensity, 0.f);
    EXPECT_LE (p.intensity, 1.f);
  }
  for (std::uint32_t l = 1; l <= 5; ++l)
    EXPECT_GT (labels[l], 100u) << "label " << l;
  EXPECT_EQ (labels[0], 0u);
  // Vegetation and terrain are greener than the pathway.
  EXPECT_GT (green[1] / labels[1], green[4] / labels[4]);
}

TEST (Scenes, BadParametersFailCleanly)
{
  SyntheticScene scene;
  SceneParameters good;
  EXPECT_FALSE (generateScene ("no_such_scene", good, scene));
  EXPECT_TRUE (scene.cloud.empty());
  SceneParameters p = good;
  p.noise = -0.01;
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  EXPECT_TRUE (scene.cloud.empty());
  p = good;
  p.noise = std::nan ("");
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  p = good;
  p.angular_step_deg = std::nan ("");
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  p = good;
  p.angular_step_deg = -1.0;
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  p = good;
  p.offset = Vec3 (0, std::numeric_limits<double>::infinity(), 0);
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  p = good;
  p.footprint = {Eigen::Vector2d (0, 0), Eigen::Vector2d (1, 0)};
  EXPECT_FALSE (generateScene ("building", p, scene));
  p = good;
  p.scan_positions = {Vec3 (1000, 1000, 0)}; // nothing within range
  p.points = 1000;
  EXPECT_FALSE (generateScene ("cubes", p, scene));
  EXPECT_TRUE (scene.cloud.empty());
}
