/*
 * Real data: AHN3 airborne tiles registered to their BGT footprints (labelled "data";
 * skipped without the data folder, PCL_EXT_SHARED_DATA_DIR). The true cloud-to-map
 * transform is the identity, so the cloud is moved by a known rigid transform and its
 * recovery measured. Airborne data has dense roofs and sparse walls, so walls come from
 * roof outlines: RoofOutlinePlaneExtraction, plugged in through the PlaneExtractor
 * hook, fits vertical planes to the outline points of each building of the building
 * class. Each tile is registered from an identity guess, once with bounds of 10 deg and
 * 10 m around it (a rough GNSS pose) and once by the paper's global search.
 */

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>

using namespace pcl_ext;

namespace {
const std::string kDir =
    std::string (PCL_EXT_SHARED_DATA_DIR) + "/amsterdam_ahn3_bgt_footprints";
constexpr std::uint32_t kGround = 2, kBuilding = 6; // LAS classes

struct TileFigures {
  bool converged = false;
  std::size_t scan_planes = 0, map_planes = 0, matched = 0;
  double rotation_deg = 0.0, translation = 0.0, seconds = 0.0;
};

// Registers the tile moved by \a perturbation, from an identity guess within the given
// bounds (infinite: the paper's global search), and measures the error at the cloud's
// centre.
bool
registerTile (const std::string& tile,
              const Eigen::Matrix4d& perturbation,
              double max_rotation_deg,
              double max_translation,
              TileFigures& figures)
{
  const std::string cloud_path = kDir + "/ahn_" + tile + ".pcd";
  const std::string footprint_path = kDir + "/bgt_footprints_local_" + tile + ".txt";
  if (!std::ifstream (cloud_path) || !std::ifstream (footprint_path))
    return false;
  pcl::PointCloud<pcl::PointXYZL> points;
  EXPECT_EQ (pcl::io::loadPCDFile (cloud_path, points), 0);
  std::vector<io::Footprint> footprints;
  io::loadFootprints (footprint_path, footprints);

  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Label>::Ptr labels (new pcl::PointCloud<pcl::Label>);
  std::vector<float> ground_z;
  for (const auto& p : points) {
    if (p.label != kGround && p.label != kBuilding)
      continue;
    if (p.label == kGround)
      ground_z.push_back (p.z);
    const Eigen::Vector4d q = perturbation * Eigen::Vector4d (p.x, p.y, p.z, 1.0);
    cloud->emplace_back (float (q.x()), float (q.y()), float (q.z()));
    labels->push_back (pcl::Label{p.label});
  }
  // The map has no heights: the floor is put at the terrain's median height.
  std::nth_element (
      ground_z.begin(), ground_z.begin() + ground_z.size() / 2, ground_z.end());
  MapPlaneParameters map_parameters;
  map_parameters.floor_height = ground_z[ground_z.size() / 2];

  const auto start = std::chrono::steady_clock::now();
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (cloud);
  // Ground: one plane of the ground class; walls: vertical planes through each
  // building's roof outline, with the extractor's defaults (not tuned to these tiles).
  RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
  walls.setInputLabels (labels);
  walls.setGroundLabel (kGround);
  walls.setBuildingLabel (kBuilding);
  reg.setPlaneExtractor (walls.asExtractor());
  EXPECT_TRUE (reg.setFootprints (footprints, map_parameters));
  // Every plane initiates (m = n = 64, the most): the map of a curved facade is many
  // short walls, and the matching ones are not among the longest.
  reg.setInitialScanPlanes (64);
  reg.setInitialMapPlanes (64);
  reg.setMaxRotationFromGuess (max_rotation_deg);
  reg.setMaxTranslationFromGuess (max_translation);
  // The cloud is georeferenced (up to the perturbation): the guess is the identity, in
  // the map's local frame.
  Eigen::Matrix4f guess = Eigen::Matrix4f::Identity();
  guess.topRightCorner<3, 1>() = -reg.getLocalOrigin().cast<float>();
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned, guess);
  figures.seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  figures.converged = reg.hasConverged();
  figures.scan_planes = reg.getSourcePlanes().size();
  figures.map_planes = reg.getMapPlanes().size();
  figures.matched = reg.getMatchingResult().matches.size();
  const auto& s = reg.getMatchingResult().statistics;
  std::printf ("AHN %s (bounds %.0f deg, %.0f m): %zu scan planes, %zu map planes, "
               "converged %d, %zu matched; "
               "combinations %llu / %llu / %llu / %llu; %.2f s\n",
               tile.c_str(),
               max_rotation_deg,
               max_translation,
               figures.scan_planes,
               figures.map_planes,
               int (figures.converged),
               figures.matched,
               (unsigned long long)s.unconstrained,
               (unsigned long long)s.vertical,
               (unsigned long long)s.orientation,
               (unsigned long long)s.residual,
               figures.seconds);
  Eigen::Matrix4d truth = perturbation.inverse();
  truth.topRightCorner<3, 1>() -= reg.getLocalOrigin();
  if (!figures.converged)
    return true;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : *cloud)
    centre += p.getVector3fMap().cast<double>();
  centre /= double (cloud->size());
  const auto error =
      computeTransformationError (reg.getFinalTransformationDouble(), truth, centre);
  figures.rotation_deg = error.rotation_deg;
  PlaneDistanceMetrics distances;
  reg.getPlaneDistances (distances);
  std::printf ("AHN %s: rotation error %.3f deg, translation error %.3f m, plane "
               "distance mean %.3f m, "
               "max %.3f m\n",
               tile.c_str(),
               error.rotation_deg,
               error.translation,
               distances.mean,
               distances.max);
  return true;
}

// 3 degrees of yaw, 1 degree of tilt, (2, -1.5, 0.3) m; the truth is its inverse.
Eigen::Matrix4d
perturbation ()
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() =
      (Eigen::AngleAxisd (3.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd (1.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  t.topRightCorner<3, 1>() = Eigen::Vector3d (2.0, -1.5, 0.3);
  return t;
}
} // namespace

// The perturbation puts the cloud's centre 3.16 deg and 1.04 m off; the bounds below
// assert a clear improvement where there is one, and no loss where there is little.
// 2386_9702: a curved block cut by the tile's edge; the bounded and the global search
// find the same pose.
TEST (AhnRegistration, Tile2386_9702RecoversAKnownPerturbation)
{
  const double inf = std::numeric_limits<double>::infinity();
  TileFigures bounded, global;
  if (!registerTile ("2386_9702", perturbation(), 10.0, 10.0, bounded))
    GTEST_SKIP() << "real data not found in " << kDir;
  ASSERT_TRUE (bounded.converged);
  EXPECT_GE (bounded.matched, 8u);
  EXPECT_LE (bounded.rotation_deg, 1.5);
  EXPECT_LE (bounded.translation, 0.5);
  ASSERT_TRUE (registerTile ("2386_9702", perturbation(), inf, inf, global));
  ASSERT_TRUE (global.converged);
  EXPECT_LE (global.rotation_deg, 1.5);
  EXPECT_LE (global.translation, 0.5);
}

// 2397_9705: two rows of houses. The rotation comes out barely better than the
// identity's: roof outlines are short, jagged stand-ins for walls, a few degrees off
// their map walls even at the true pose, and say little about tilt (the terrain under
// the one floor plane is not quite level); the translation is clearly better. The
// result moves with the extractor's and the matcher's thresholds, which were not tuned
// to these tiles. The measured errors, plane counts and times of both tiles are in
// docs/khoshelham_gorte.md.
TEST (AhnRegistration, Tile2397_9705RecoversAKnownPerturbation)
{
  const double inf = std::numeric_limits<double>::infinity();
  TileFigures bounded, global;
  if (!registerTile ("2397_9705", perturbation(), 10.0, 10.0, bounded))
    GTEST_SKIP() << "real data not found in " << kDir;
  ASSERT_TRUE (bounded.converged);
  EXPECT_GE (bounded.matched, 7u);
  EXPECT_LE (bounded.rotation_deg, 3.0);
  EXPECT_LE (bounded.translation, 1.0);
  ASSERT_TRUE (registerTile ("2397_9705", perturbation(), inf, inf, global));
  ASSERT_TRUE (global.converged);
  EXPECT_LE (global.rotation_deg, 3.0);
  EXPECT_LE (global.translation, 1.0);
}
