/*
 * Khoshelham & Gorte registration with its defaults: the generated building in the
 * scene's own random pose (up to 10 degrees of tilt) registered with every default.
 */
#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/common/io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_ext;

namespace {
struct Scene {
  simulation::SyntheticScene scene;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
};

// The building as pcl_ext_generate_scene building -seed <seed> makes it.
Scene
generate (unsigned int seed)
{
  Scene s;
  simulation::SceneParameters p;
  p.seed = seed;
  if (simulation::generateScene ("building", p, s.scene))
    pcl::copyPointCloud (s.scene.cloud, *s.cloud);
  return s;
}

// Registers with every default but the number of initial scan and map planes when given
// (m = n); the errors of the pose at the footprint's centre, half way up the walls.
bool
registerScene (const Scene& s, TransformationError& error, int initial_planes = 0)
{
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  if (initial_planes > 0) {
    reg.setInitialScanPlanes (initial_planes);
    reg.setInitialMapPlanes (initial_planes);
  }
  io::Footprint footprint;
  footprint.polygons.resize (1);
  footprint.polygons[0].outer = s.scene.footprint;
  if (!reg.setFootprints ({footprint}))
    return false;
  reg.setInputSource (s.cloud);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned);
  if (!reg.hasConverged())
    return false;
  Eigen::Matrix4d truth = s.scene.scan_to_map;
  truth.topRightCorner<3, 1>() -= reg.getLocalOrigin();
  Eigen::AlignedBox2d box;
  for (const auto& q : s.scene.footprint)
    box.extend (q - reg.getLocalOrigin().head<2>());
  const Eigen::Vector3d centre (box.center().x(), box.center().y(), 5.0);
  // The scan point the truth puts at the centre.
  const Eigen::Vector3d at =
      truth.topLeftCorner<3, 3>().transpose() * (centre - truth.topRightCorner<3, 1>());
  error = computeTransformationError (reg.getFinalTransformationDouble(), truth, at);
  return true;
}

// Seeds of the report set (6-50); the tuning set is 1-5.
TEST (RegistrationDefaults, GeneratedBuildingInItsRandomPose)
{
  for (const unsigned int seed : {6u, 17u, 31u}) {
    const Scene s = generate (seed);
    ASSERT_FALSE (s.cloud->empty());
    TransformationError error;
    ASSERT_TRUE (registerScene (s, error)) << "seed " << seed;
    EXPECT_LT (error.rotation_deg, 0.2) << "seed " << seed;
    EXPECT_LT (error.translation, 0.05) << "seed " << seed;
  }
}

// Section 3.2: with the paper's smallest initial sets, m = n = 7 (and k = 4, the
// default), the search still finds the match: the initial scan planes are the walls
// longest in plan. Seed 9 failed when each wall's set held the strips of the walls it
// cuts across.
TEST (RegistrationDefaults, SevenInitialPlanesOfEachFindTheMatch)
{
  for (const unsigned int seed : {9u, 22u, 44u}) {
    const Scene s = generate (seed);
    ASSERT_FALSE (s.cloud->empty());
    TransformationError error;
    ASSERT_TRUE (registerScene (s, error, 7)) << "seed " << seed;
    EXPECT_LT (error.rotation_deg, 0.2) << "seed " << seed;
    EXPECT_LT (error.translation, 0.05) << "seed " << seed;
  }
}

} // namespace
