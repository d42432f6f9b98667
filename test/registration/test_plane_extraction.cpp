/*
 * Tests of the scan plane extraction of Khoshelham & Gorte (2009), section 3.1:
 * fitScanPlanes (fit, robust extent, scanner-side normal) and SACPlaneExtraction
 * (sequential RANSAC).
 */
#include <pcl_ext/registration/plane_extraction.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace pcl_ext;

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// Two faces of a box, z = 0 (10 x 8 m) and x = 0 (8 x 5 m), a point every 0.2 m, noise
// \a sigma along the normals; the inlier sets in \a faces (floor first).
Cloud::Ptr
twoFaces (double sigma, std::vector<pcl::PointIndices>& faces)
{
  std::mt19937 rng (3);
  std::normal_distribution<double> noise (0.0, sigma);
  Cloud::Ptr cloud (new Cloud);
  faces.assign (2, pcl::PointIndices());
  for (double x = 0.1; x < 10.0; x += 0.2)
    for (double y = 0.1; y < 8.0; y += 0.2) {
      faces[0].indices.push_back (static_cast<pcl::index_t> (cloud->size()));
      cloud->emplace_back (float (x), float (y), float (noise (rng)));
    }
  for (double y = 0.1; y < 8.0; y += 0.2)
    for (double z = 0.1; z < 5.0; z += 0.2) {
      faces[1].indices.push_back (static_cast<pcl::index_t> (cloud->size()));
      cloud->emplace_back (float (noise (rng)), float (y), float (z));
    }
  return cloud;
}
} // namespace

TEST (PlaneExtraction, FitScanPlanesFitsAndFacesTheScanner)
{
  std::vector<pcl::PointIndices> faces;
  const Cloud::Ptr cloud = twoFaces (0.01, faces);
  ScanViewpoints viewpoints;
  viewpoints.positions = {
      Eigen::Vector3d (5.0, 4.0, 1.5)}; // above the floor, before the wall
  std::vector<ScanPlane> planes;
  ASSERT_TRUE (fitScanPlanes (*cloud, faces, viewpoints, planes));
  ASSERT_EQ (planes.size(), 2u);
  EXPECT_GT (planes[0].normal.z(), 0.9999);
  EXPECT_NEAR (planes[0].d, 0.0, 0.005);
  EXPECT_GT (planes[1].normal.x(), 0.9999);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ (planes[i].size, faces[i].indices.size());
    EXPECT_EQ (planes[i].inliers.indices, faces[i].indices);
    EXPECT_NEAR (planes[i].rms, 0.01, 0.002);
    EXPECT_NEAR (planes[i].normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR (planes[i].d, -planes[i].normal.dot (planes[i].centroid), 1e-12);
  }
  // The extent spans the face (its 1st to 99th percentiles).
  EXPECT_NEAR (planes[0].extent.min().x(), 0.1, 0.25);
  EXPECT_NEAR (planes[0].extent.max().x(), 9.9, 0.25);
  EXPECT_NEAR (planes[1].extent.max().z(), 4.9, 0.25);

  // Seen from below and behind, the normals turn round.
  viewpoints.positions = {Eigen::Vector3d (-5.0, 4.0, -3.0)};
  ASSERT_TRUE (fitScanPlanes (*cloud, faces, viewpoints, planes));
  EXPECT_LT (planes[0].normal.z(), -0.9999);
  EXPECT_LT (planes[1].normal.x(), -0.9999);

  // One scanner index per point, or none.
  viewpoints.scanner_of_point.assign (3, 0);
  EXPECT_FALSE (fitScanPlanes (*cloud, faces, viewpoints, planes));
  EXPECT_TRUE (planes.empty());
}

TEST (PlaneExtraction, SacPlaneExtractionFindsTheLargestPlaneFirst)
{
  std::vector<pcl::PointIndices> faces;
  const Cloud::Ptr cloud = twoFaces (0.01, faces);
  SACPlaneExtraction<pcl::PointXYZ> extraction;
  extraction.setInputCloud (cloud);
  extraction.setDistanceThreshold (0.05);
  extraction.setMinInliers (100);
  std::vector<pcl::PointIndices> planes;
  extraction.extract (planes);
  ASSERT_EQ (planes.size(), 2u);
  // Largest (the floor) first; nearly all of each face, little of the other (the shared
  // edge).
  for (std::size_t i = 0; i < 2; ++i) {
    std::size_t own = 0;
    for (const auto index : planes[i].indices)
      own +=
          std::binary_search (faces[i].indices.begin(), faces[i].indices.end(), index);
    EXPECT_GT (own, 0.95 * faces[i].indices.size()) << "plane " << i;
    EXPECT_GT (own, 0.95 * planes[i].indices.size()) << "plane " << i;
  }
  // The extractor hook gives the same planes.
  std::vector<pcl::PointIndices> hooked;
  extraction.asExtractor() (cloud, pcl::IndicesConstPtr(), hooked);
  ASSERT_EQ (hooked.size(), planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i)
    EXPECT_EQ (hooked[i].indices, planes[i].indices);

  // Bad parameters: a PCL_ERROR and no planes.
  extraction.setDistanceThreshold (0.0);
  ::testing::internal::CaptureStderr();
  extraction.extract (planes);
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE (planes.empty());
  EXPECT_NE (log.find ("[pcl_ext::SACPlaneExtraction::extract]"), std::string::npos)
      << log;
}

TEST (PlaneExtraction, SacPlanesLeaveOutTheStripsOfTheWallsTheyCross)
{
  // An H's long side in plan: two collinear walls y = 0 (x 0-10 and 14-24, 5 m high),
  // and walls x = -6 and x = 30 across the plane y = 0 (y -8..8), a point every 0.1 m.
  // The infinite plane y = 0 holds both collinear walls and a strip of each crossing
  // wall; the plane keeps the walls and leaves the strips out, which still leave the
  // pool (the crossing walls are planes of their own without them).
  Cloud::Ptr cloud (new Cloud);
  for (double z = 0.05; z < 5.0; z += 0.1) {
    for (double x = 0.05; x < 24.0; x += 0.1)
      if (x < 10.0 || x > 14.0)
        cloud->emplace_back (float (x), 0.0f, float (z));
    for (const double x : {-6.0, 30.0})
      for (double y = -7.95; y < 8.0; y += 0.1)
        cloud->emplace_back (float (x), float (y), float (z));
  }
  SACPlaneExtraction<pcl::PointXYZ> extraction;
  extraction.setInputCloud (cloud);
  extraction.setDistanceThreshold (0.4);
  extraction.setMinInliers (200);
  std::vector<pcl::PointIndices> planes;
  extraction.extract (planes);
  ASSERT_EQ (planes.size(), 3u);
  std::size_t on_walls = 0;
  for (const auto i : planes[0].indices) {
    EXPECT_NEAR ((*cloud)[i].y, 0.0f, 1e-6f) << "a crossing wall's point";
    on_walls += (*cloud)[i].x > 0.0f && (*cloud)[i].x < 24.0f;
  }
  EXPECT_EQ (on_walls, planes[0].indices.size());
  EXPECT_EQ (planes[0].indices.size(), 50u * 200u); // both collinear walls
  std::vector<ScanPlane> fitted;
  ASSERT_TRUE (fitScanPlanes (*cloud, planes, ScanViewpoints(), fitted));
  ASSERT_EQ (fitted.size(), 3u);
  EXPECT_LT (fitted[0].extent.sizes().x(), 24.5) << "the strips at -6 and 30 m";
}

// Walls are the planes within the tolerance of vertical.
TEST (PlaneExtraction, CountsVerticalPlanes)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<pcl::PointIndices> sets (3);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      sets[0].indices.push_back (int (cloud.size()));
      cloud.emplace_back (float (i), float (j), 0.f); // floor
      sets[1].indices.push_back (int (cloud.size()));
      cloud.emplace_back (float (i), 0.f, float (j)); // wall
      sets[2].indices.push_back (int (cloud.size()));
      cloud.emplace_back (0.1f * float (j), float (i), float (j)); // 5.7 deg off
    }
  EXPECT_EQ (countVerticalPlanes (cloud, sets), 2);
  EXPECT_EQ (countVerticalPlanes (cloud, sets, 3.0), 1);
}
