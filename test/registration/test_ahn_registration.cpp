/*
 * Real data: AHN3 airborne tiles registered to their BGT footprints (labelled "data"; skipped
 * without ../shared/data). The true cloud-to-map transform is the identity, so the cloud is
 * moved by a known rigid transform and its recovery measured. Airborne data has dense roofs and
 * sparse walls, so walls come from roof outlines: a plugged-in extractor fits vertical planes to
 * the outline points of each building of the building class, which shows the PlaneExtractor
 * hook at work. Each tile is registered from an identity guess, once with bounds of 10 deg and
 * 10 m around it (a rough GNSS pose) and once by the paper's global search.
 */
#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <pcl/io/pcd_io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>

using namespace pcl_ext;

namespace
{
const std::string kDir = std::string (PCL_EXT_SHARED_DATA_DIR) + "/amsterdam_ahn3_bgt_footprints";
constexpr std::uint32_t kGround = 2, kBuilding = 6;  // LAS classes

// The largest run of \a inliers along the horizontal line of a vertical plane (normal n): the
// points sorted along the line and split where they are more than \a gap apart, so that a
// wall is one stretch of outline and not two collinear ones across a courtyard or a street.
pcl::Indices
largestRun (const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl::Indices& inliers, const Eigen::Vector3f& n,
            float gap)
{
  const Eigen::Vector2f along = Eigen::Vector2f (-n.y (), n.x ()).normalized ();
  std::vector<std::pair<float, int>> position;
  for (const int i : inliers)
    position.emplace_back (along.dot (cloud[i].getVector3fMap ().head<2> ()), i);
  std::sort (position.begin (), position.end ());
  std::size_t best_begin = 0, best_end = 0;
  for (std::size_t begin = 0, end = 0; begin < position.size (); begin = end)
  {
    for (end = begin + 1; end < position.size () && position[end].first - position[end - 1].first <= gap; ++end)
      ;
    if (end - begin > best_end - best_begin)
    {
      best_begin = begin;
      best_end = end;
    }
  }
  pcl::Indices run;
  for (std::size_t q = best_begin; q < best_end; ++q)
    run.push_back (position[q].second);
  std::sort (run.begin (), run.end ());
  return run;
}

// Ground: one plane of the ground class. Walls: vertical planes through the roof outline points
// of each building (building-class points clustered in 2D), so that no plane is fitted across
// two buildings. An outline point has its 2D neighbours to one side and, on the open side,
// points of another class: where the tile cuts a roof there is nothing beyond, and no wall.
PlaneExtractor<pcl::PointXYZ>
roofOutlineExtractor (std::vector<std::uint32_t> labels)
{
  return [labels] (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, std::vector<pcl::PointIndices>& sets) {
    sets.clear ();
    pcl::IndicesPtr ground (new pcl::Indices);
    pcl::Indices building;
    pcl::PointCloud<pcl::PointXYZ>::Ptr flat (new pcl::PointCloud<pcl::PointXYZ>),
        others (new pcl::PointCloud<pcl::PointXYZ>);
    for (std::size_t i = 0; i < cloud->size (); ++i)
    {
      if (labels[i] == kGround)
        ground->push_back (static_cast<int> (i));
      if (labels[i] == kBuilding)
      {
        building.push_back (static_cast<int> (i));
        flat->emplace_back ((*cloud)[i].x, (*cloud)[i].y, 0.f);
      }
      else
        others->emplace_back ((*cloud)[i].x, (*cloud)[i].y, 0.f);
    }
    pcl::SACSegmentation<pcl::PointXYZ> sac;
    sac.setInputCloud (cloud);
    sac.setModelType (pcl::SACMODEL_PLANE);
    sac.setMethodType (pcl::SAC_RANSAC);
    sac.setDistanceThreshold (0.3);
    sac.setMaxIterations (500);
    sac.setIndices (ground);
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    sac.segment (inliers, coefficients);
    if (!inliers.indices.empty ())
      sets.push_back (inliers);
    if (flat->empty () || others->empty ())
      return true;

    // Buildings: the building points in 2D, 1 m apart at most (AHN3: about 0.25 m spacing).
    std::vector<pcl::PointIndices> buildings;
    pcl::search::KdTree<pcl::PointXYZ>::Ptr flat_search (new pcl::search::KdTree<pcl::PointXYZ>);
    flat_search->setInputCloud (flat);
    pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
    clustering.setClusterTolerance (1.0);
    clustering.setMinClusterSize (100);
    clustering.setSearchMethod (flat_search);
    clustering.setInputCloud (flat);
    clustering.extract (buildings);

    pcl::KdTreeFLANN<pcl::PointXYZ> beyond;
    beyond.setInputCloud (others);
    sac.setModelType (pcl::SACMODEL_PARALLEL_PLANE);
    sac.setAxis (Eigen::Vector3f::UnitZ ());
    sac.setEpsAngle (5.0 * M_PI / 180.0);
    sac.setDistanceThreshold (0.3);
    pcl::Indices nn;
    std::vector<float> d2;
    for (const auto& members : buildings)
    {
      pcl::PointCloud<pcl::PointXYZ>::Ptr roof (new pcl::PointCloud<pcl::PointXYZ> (*flat, members.indices));
      pcl::KdTreeFLANN<pcl::PointXYZ> tree;
      tree.setInputCloud (roof);
      pcl::IndicesPtr outline (new pcl::Indices);
      for (std::size_t j = 0; j < roof->size (); ++j)
      {
        if (tree.nearestKSearch ((*roof)[j], 12, nn, d2) < 12)
          continue;
        const Eigen::Vector2f p = (*roof)[j].getVector3fMap ().head<2> ();
        Eigen::Vector2f mean = Eigen::Vector2f::Zero ();
        float spacing = 0.f;
        for (std::size_t q = 1; q < nn.size (); ++q)
        {
          mean += (*roof)[nn[q]].getVector3fMap ().head<2> ();
          spacing += std::sqrt (d2[q]);
        }
        mean /= static_cast<float> (nn.size () - 1);
        spacing /= static_cast<float> (nn.size () - 1);
        if ((mean - p).norm () <= 0.35f * spacing)
          continue;
        const Eigen::Vector2f out = p + (p - mean).normalized ();
        if (beyond.radiusSearch (pcl::PointXYZ (out.x (), out.y (), 0.f), 1.0, nn, d2, 1) == 0)
          continue;
        outline->push_back (building[members.indices[j]]);
      }
      std::sort (outline->begin (), outline->end ());
      while (outline->size () >= 15)
      {
        sac.setIndices (outline);
        sac.segment (inliers, coefficients);
        if (inliers.indices.size () < 15)
          break;
        const Eigen::Vector3f normal (coefficients.values[0], coefficients.values[1], coefficients.values[2]);
        const pcl::Indices run = largestRun (*cloud, inliers.indices, normal, 1.5f);
        if (run.size () < 15)
          break;
        pcl::IndicesPtr rest (new pcl::Indices);
        std::set_difference (outline->begin (), outline->end (), run.begin (), run.end (), std::back_inserter (*rest));
        outline = rest;
        pcl::PointIndices wall;
        wall.indices = run;
        sets.push_back (wall);
      }
    }
    return true;
  };
}

struct TileFigures
{
  bool converged = false;
  std::size_t scan_planes = 0, map_planes = 0, matched = 0;
  double rotation_deg = 0.0, translation = 0.0, seconds = 0.0;
};

// Registers the tile moved by \a perturbation, from an identity guess within the given bounds
// (infinite: the paper's global search), and measures the error at the cloud's centre.
bool
registerTile (const std::string& tile, const Eigen::Matrix4d& perturbation, double max_rotation_deg,
              double max_translation, TileFigures& figures)
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
  std::vector<std::uint32_t> labels;
  std::vector<float> ground_z;
  for (const auto& p : points)
  {
    if (p.label != kGround && p.label != kBuilding)
      continue;
    if (p.label == kGround)
      ground_z.push_back (p.z);
    const Eigen::Vector4d q = perturbation * Eigen::Vector4d (p.x, p.y, p.z, 1.0);
    cloud->emplace_back (float (q.x ()), float (q.y ()), float (q.z ()));
    labels.push_back (p.label);
  }
  // The map has no heights: the floor is put at the terrain's median height.
  std::nth_element (ground_z.begin (), ground_z.begin () + ground_z.size () / 2, ground_z.end ());
  MapPlaneParameters map_parameters;
  map_parameters.floor_height = ground_z[ground_z.size () / 2];

  const auto start = std::chrono::steady_clock::now ();
  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (cloud);
  reg.setPlaneExtractor (roofOutlineExtractor (labels));
  EXPECT_TRUE (reg.setFootprints (footprints, map_parameters));
  // Every plane initiates (m = n = 64, the most): the map of a curved facade is many short
  // walls, and the matching ones are not among the longest.
  reg.setInitialScanPlanes (64);
  reg.setInitialMapPlanes (64);
  reg.setMaxRotationFromGuess (max_rotation_deg);
  reg.setMaxTranslationFromGuess (max_translation);
  // The cloud is georeferenced (up to the perturbation): the guess is the identity, in the
  // map's local frame.
  Eigen::Matrix4f guess = Eigen::Matrix4f::Identity ();
  guess.topRightCorner<3, 1> () = -reg.getLocalOrigin ().cast<float> ();
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned, guess);
  figures.seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  figures.converged = reg.hasConverged ();
  figures.scan_planes = reg.getSourcePlanes ().size ();
  figures.map_planes = reg.getMapPlanes ().size ();
  figures.matched = reg.getMatchingResult ().matches.size ();
  const auto& s = reg.getMatchingResult ().statistics;
  std::printf ("AHN %s (bounds %.0f deg, %.0f m): %zu scan planes, %zu map planes, converged %d, %zu matched; "
               "combinations %llu / %llu / %llu / %llu; %.2f s\n", tile.c_str (), max_rotation_deg, max_translation,
               figures.scan_planes, figures.map_planes, int (figures.converged), figures.matched,
               (unsigned long long) s.unconstrained, (unsigned long long) s.vertical,
               (unsigned long long) s.orientation, (unsigned long long) s.residual, figures.seconds);
  Eigen::Matrix4d truth = perturbation.inverse ();
  truth.topRightCorner<3, 1> () -= reg.getLocalOrigin ();
  if (!figures.converged)
    return true;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  for (const auto& p : *cloud)
    centre += p.getVector3fMap ().cast<double> ();
  centre /= double (cloud->size ());
  const auto error = computeTransformationError (reg.getFinalTransformationDouble (), truth, centre);
  figures.rotation_deg = error.rotation_deg;
  std::printf ("AHN %s: rotation error %.3f deg, translation error %.3f m, plane distance mean %.3f m, "
               "max %.3f m\n", tile.c_str (), error.rotation_deg, error.translation, reg.getPlaneDistances ().mean,
               reg.getPlaneDistances ().max);
  return true;
}

// 3 degrees of yaw, 1 degree of tilt, (2, -1.5, 0.3) m; the truth is its inverse.
Eigen::Matrix4d
perturbation ()
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity ();
  t.topLeftCorner<3, 3> () = (Eigen::AngleAxisd (3.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ ()) *
                              Eigen::AngleAxisd (1.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ()))
                                 .toRotationMatrix ();
  t.topRightCorner<3, 1> () = Eigen::Vector3d (2.0, -1.5, 0.3);
  return t;
}
}  // namespace

// The perturbation puts the cloud's centre 3.16 deg and 1.04 m off; the bounds below assert a
// clear improvement where there is one, and no loss where there is little.
// Measured (Release): 2386_9702, a curved block cut by the tile's edge: 20 scan planes, 121 map
// planes; bounded search 10 matched, rotation error 0.95 deg, translation error 0.16 m, 0.2 s;
// the global search finds the same pose (1 s). Before: one fit of outline walls across all
// buildings (41 planes, some along the tile's edge) and m = n = 16 gave a quarter turn onto a
// neighbouring block (91.5 deg, 34 m).
TEST (AhnRegistration, Tile2386_9702RecoversAKnownPerturbation)
{
  const double inf = std::numeric_limits<double>::infinity ();
  TileFigures bounded, global;
  if (!registerTile ("2386_9702", perturbation (), 10.0, 10.0, bounded))
    GTEST_SKIP () << "real data not found in " << kDir;
  ASSERT_TRUE (bounded.converged);
  EXPECT_GE (bounded.matched, 8u);
  EXPECT_LE (bounded.rotation_deg, 1.5);
  EXPECT_LE (bounded.translation, 0.5);
  ASSERT_TRUE (registerTile ("2386_9702", perturbation (), inf, inf, global));
  ASSERT_TRUE (global.converged);
  EXPECT_LE (global.rotation_deg, 1.5);
  EXPECT_LE (global.translation, 0.5);
}

// Measured (Release): 2397_9705, two rows of houses: 29 scan planes, 123 map planes; bounded
// search 9 matched, rotation error 2.2 deg (1.0 of tilt: the terrain under the one floor
// plane is 0.6 deg off level, and outline walls say little about tilt; 2.0 of yaw),
// translation error 0.48 m, 0.4 s; the global search finds the same pose in 5-8 s. At the
// cloud's centre the identity is 3.16 deg and 1.04 m off: the rotation is barely better: roof outlines are short, jagged stand-ins
// for walls, 2-5 deg off their map walls even at the true pose. The result moves with the
// extractor's and the matcher's thresholds (outline band 0.2-0.4 m: 1.0-2.2 deg here, 0.8-2.8
// deg on 2386_9702; angle tolerance 2-4 deg: 1.2-2.2 deg); the values above were not tuned.
TEST (AhnRegistration, Tile2397_9705RecoversAKnownPerturbation)
{
  const double inf = std::numeric_limits<double>::infinity ();
  TileFigures bounded, global;
  if (!registerTile ("2397_9705", perturbation (), 10.0, 10.0, bounded))
    GTEST_SKIP () << "real data not found in " << kDir;
  ASSERT_TRUE (bounded.converged);
  EXPECT_GE (bounded.matched, 7u);
  EXPECT_LE (bounded.rotation_deg, 3.0);
  EXPECT_LE (bounded.translation, 1.0);
  ASSERT_TRUE (registerTile ("2397_9705", perturbation (), inf, inf, global));
  ASSERT_TRUE (global.converged);
  EXPECT_LE (global.rotation_deg, 3.0);
  EXPECT_LE (global.translation, 1.0);
}
