/*
 * The distances between matched planes (Khoshelham & Gorte 2009, Tables 1-2) under
 * known transforms, on plain inputs and on a plane matching's own planes.
 */
#include <pcl_ext/registration/plane_distances.h>

#include <pcl/point_types.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_ext;

namespace {
Eigen::Matrix4d
makeTransform (double angle_deg, const Eigen::Vector3d& axis, const Eigen::Vector3d& t)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (angle_deg * M_PI / 180.0, axis.normalized())
          .toRotationMatrix();
  m.topRightCorner<3, 1>() = t;
  return m;
}
} // namespace

TEST (PlaneDistances, KnownTransforms)
{
  // Scan: a wall x = 0 (points with alternating +-0.2 m noise along x) and a floor z =
  // 0.
  pcl::PointCloud<pcl::PointXYZ> scan;
  std::vector<pcl::PointIndices> planes (2);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      planes[0].indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ ((i + j) % 2 ? 0.2f : -0.2f, 0.5f * i, 0.5f * j));
      planes[1].indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ (0.5f * i + 1.0f, 0.5f * j, 0.0f));
    }
  scan.push_back (pcl::PointXYZ (std::nanf (""), 0, 0)); // skipped
  planes[1].indices.push_back (static_cast<int> (scan.size() - 1));

  // The map is the scan moved by a known transform; its planes are (n, d), n . x + d =
  // 0.
  const Eigen::Matrix4d truth =
      makeTransform (40.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d (100, 200, 3));
  const Eigen::Matrix3d r = truth.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = truth.topRightCorner<3, 1>();
  std::vector<Eigen::Vector4d> map_planes;
  for (const Eigen::Vector3d n :
       {Eigen::Vector3d (1, 0, 0), Eigen::Vector3d (0, 0, 1)}) {
    const Eigen::Vector3d nm = r * n;
    // Scale the normal by 2 to check that it is normalised.
    map_planes.push_back (2.0 * Eigen::Vector4d (nm.x(), nm.y(), nm.z(), -nm.dot (t)));
  }
  map_planes.push_back (Eigen::Vector4d (0, 1, 0, 0)); // an unmatched map plane
  pcl::Correspondences matches = {pcl::Correspondence (0, 0, 0.f),
                                  pcl::Correspondence (1, 1, 0.f)};

  PlaneDistanceMetrics m;
  ASSERT_TRUE (computePlaneDistances (scan, planes, map_planes, matches, truth, m));
  ASSERT_EQ (m.pairs.size(), 2u);
  EXPECT_EQ (m.points, 200u);
  EXPECT_NEAR (m.pairs[0].mean, 0.2, 1e-6);
  EXPECT_NEAR (m.pairs[0].max, 0.2, 1e-6);
  EXPECT_NEAR (m.pairs[0].centroid_distance, 0.0, 1e-6);
  EXPECT_NEAR (m.pairs[1].mean, 0.0, 1e-6);
  EXPECT_EQ (m.pairs[1].points, 100u);
  EXPECT_NEAR (m.mean, 0.1, 1e-6);
  EXPECT_NEAR (m.max, 0.2, 1e-6);
  EXPECT_NEAR (m.mean_of_planes, 0.1, 1e-6);
  EXPECT_NEAR (m.max_angle_deg, 0.0, 1e-3);

  // Shift the estimate by 0.5 m along z: the floor is 0.5 m off, the wall unaffected.
  Eigen::Matrix4d shifted = truth;
  shifted (2, 3) += 0.5;
  ASSERT_TRUE (computePlaneDistances (scan, planes, map_planes, matches, shifted, m));
  EXPECT_NEAR (m.pairs[1].mean, 0.5, 1e-6);
  EXPECT_NEAR (m.pairs[1].centroid_distance, 0.5, 1e-6);
  EXPECT_NEAR (m.pairs[0].mean, 0.2, 1e-6);
  EXPECT_NEAR (m.max, 0.5, 1e-6);

  // Tilt the estimate by 3 degrees about y: both planes tilt by 3 degrees.
  const Eigen::Matrix4d tilted =
      truth * makeTransform (3.0, Eigen::Vector3d::UnitY(), Eigen::Vector3d::Zero());
  ASSERT_TRUE (computePlaneDistances (scan, planes, map_planes, matches, tilted, m));
  EXPECT_NEAR (m.pairs[1].angle_deg, 3.0, 1e-3);
  EXPECT_NEAR (m.max_angle_deg, 3.0, 1e-3);

  // A correspondence out of range is refused.
  matches.push_back (pcl::Correspondence (2, 0, 0.f));
  EXPECT_FALSE (computePlaneDistances (scan, planes, map_planes, matches, truth, m));
  EXPECT_TRUE (m.pairs.empty());
}

// The overload on ScanPlane, Plane and PlanePair gives the figures of the plain one:
// the inliers of every scan plane, the coefficients of every target plane, one
// correspondence per pair.
TEST (PlaneDistances, OfAPlaneMatchingsOwnPlanes)
{
  pcl::PointCloud<pcl::PointXYZ> scan;
  std::vector<ScanPlane> scan_planes (2);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      scan_planes[0].inliers.indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ (0.05f * ((i * j) % 3), 0.5f * i, 0.5f * j));
      scan_planes[1].inliers.indices.push_back (static_cast<int> (scan.size()));
      scan.push_back (pcl::PointXYZ (0.5f * i, 0.5f * j, 0.1f * (i % 2)));
    }
  std::vector<Plane> target_planes{
      Plane::throughPoint (Eigen::Vector3d (0, 0, 1), Eigen::Vector3d (0, 0, 2)),
      Plane::throughPoint (Eigen::Vector3d (1, 1, 0), Eigen::Vector3d (3, 0, 0))};
  // The second scan plane onto the first target plane and back, with signs.
  const std::vector<PlanePair> matches{{1, 0, 1}, {0, 1, -1}};
  const Eigen::Matrix4d transformation =
      makeTransform (20.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d (1, -2, 0.5));

  PlaneDistanceMetrics own;
  ASSERT_TRUE (computePlaneDistances (
      scan, scan_planes, target_planes, matches, transformation, own));
  std::vector<pcl::PointIndices> inliers{scan_planes[0].inliers,
                                         scan_planes[1].inliers};
  std::vector<Eigen::Vector4d> coefficients{target_planes[0].coefficients(),
                                            target_planes[1].coefficients()};
  const pcl::Correspondences correspondences{pcl::Correspondence (1, 0, 0.f),
                                             pcl::Correspondence (0, 1, 0.f)};
  PlaneDistanceMetrics plain;
  ASSERT_TRUE (computePlaneDistances (
      scan, inliers, coefficients, correspondences, transformation, plain));
  ASSERT_EQ (own.pairs.size(), 2u);
  ASSERT_EQ (plain.pairs.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ (own.pairs[i].scan_plane, plain.pairs[i].scan_plane);
    EXPECT_EQ (own.pairs[i].map_plane, plain.pairs[i].map_plane);
    EXPECT_EQ (own.pairs[i].points, 64u);
    EXPECT_DOUBLE_EQ (own.pairs[i].mean, plain.pairs[i].mean);
    EXPECT_DOUBLE_EQ (own.pairs[i].max, plain.pairs[i].max);
  }
  EXPECT_DOUBLE_EQ (own.mean, plain.mean);
  EXPECT_DOUBLE_EQ (own.rms, plain.rms);
  EXPECT_GT (own.mean, 0.0);

  // A pair naming a target plane that is not there is refused, as in the plain form.
  const std::vector<PlanePair> out_of_range{{0, 2, 1}};
  EXPECT_FALSE (computePlaneDistances (
      scan, scan_planes, target_planes, out_of_range, transformation, own));
  EXPECT_TRUE (own.pairs.empty());
}
