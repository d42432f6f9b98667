/*
 * Real data: an AHN3 airborne tile registered to its BGT footprints (labelled "data"; skipped
 * without ../shared/data). The true cloud-to-map transform is the identity, so the cloud is
 * moved by a known rigid transform and its recovery measured. Airborne data has dense roofs and
 * sparse walls, so walls come from roof outlines: a plugged-in extractor fits vertical planes to
 * the outline points of the building class, which shows the PlaneExtractor hook at work.
 */
#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <pcl/io/pcd_io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

using namespace pcl_ext;

namespace
{
const std::string kDir = std::string (PCL_EXT_SHARED_DATA_DIR) + "/amsterdam_ahn3_bgt_footprints";

// Ground: one plane of the ground class. Walls: vertical planes through the outline points of
// the building class (points whose 2D neighbours all lie to one side).
PlaneExtractor<pcl::PointXYZ>
roofOutlineExtractor (std::vector<std::uint32_t> labels)
{
  return [labels] (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, std::vector<pcl::PointIndices>& sets) {
    sets.clear ();
    pcl::IndicesPtr ground (new pcl::Indices), building (new pcl::Indices);
    for (std::size_t i = 0; i < cloud->size (); ++i)
      if (labels[i] == 2)
        ground->push_back (static_cast<int> (i));
      else if (labels[i] == 6)
        building->push_back (static_cast<int> (i));
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

    // Outline points of the roofs, in 2D.
    pcl::PointCloud<pcl::PointXYZ>::Ptr flat (new pcl::PointCloud<pcl::PointXYZ>);
    for (const int i : *building)
      flat->emplace_back ((*cloud)[i].x, (*cloud)[i].y, 0.f);
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (flat);
    pcl::IndicesPtr outline (new pcl::Indices);
    pcl::Indices nn;
    std::vector<float> d2;
    for (std::size_t j = 0; j < flat->size (); ++j)
    {
      if (tree.nearestKSearch ((*flat)[j], 12, nn, d2) < 12)
        continue;
      Eigen::Vector2f mean = Eigen::Vector2f::Zero ();
      float spacing = 0.f;
      for (std::size_t q = 1; q < nn.size (); ++q)
      {
        mean += (*flat)[nn[q]].getVector3fMap ().head<2> ();
        spacing += std::sqrt (d2[q]);
      }
      mean /= static_cast<float> (nn.size () - 1);
      spacing /= static_cast<float> (nn.size () - 1);
      if ((mean - (*flat)[j].getVector3fMap ().head<2> ()).norm () > 0.35f * spacing)
        outline->push_back ((*building)[j]);
    }
    sac.setModelType (pcl::SACMODEL_PARALLEL_PLANE);
    sac.setAxis (Eigen::Vector3f::UnitZ ());
    sac.setEpsAngle (5.0 * M_PI / 180.0);
    sac.setDistanceThreshold (0.4);
    for (int plane = 0; plane < 40 && outline->size () >= 15; ++plane)
    {
      sac.setIndices (outline);
      sac.segment (inliers, coefficients);
      if (inliers.indices.size () < 15)
        break;
      std::sort (inliers.indices.begin (), inliers.indices.end ());
      pcl::IndicesPtr rest (new pcl::Indices);
      std::set_difference (outline->begin (), outline->end (), inliers.indices.begin (), inliers.indices.end (),
                           std::back_inserter (*rest));
      outline = rest;
      sets.push_back (inliers);
    }
    return true;
  };
}
}  // namespace

// Disabled: not met. Measured on tile 2386_9702: 41 scan planes (ground + roof-outline walls),
// 121 map planes (13 buildings), 5 matched, rotation error 91.5 deg, translation error 34 m:
// the city block's walls are all parallel or perpendicular and the outline walls few, so a
// quarter turn onto a neighbouring block fits as many planes. m = n = 12 finds no combination
// within the residual tolerances; m = n = 24 with a 1 m tolerance: 6 matched, 19.8 deg, 41 m.
// Restricting the map to the footprints under the scan, or walls from the roof outline of each
// building separately, is the next step.
TEST (AhnRegistration, DISABLED_RecoversAKnownPerturbation)
{
  const std::string cloud_path = kDir + "/ahn_2386_9702.pcd", footprint_path = kDir + "/bgt_footprints_local_2386_9702.txt";
  if (!std::ifstream (cloud_path) || !std::ifstream (footprint_path))
    GTEST_SKIP () << "real data not found in " << kDir;
  pcl::PointCloud<pcl::PointXYZL> tile;
  ASSERT_EQ (pcl::io::loadPCDFile (cloud_path, tile), 0);
  std::vector<io::Footprint> footprints;
  io::loadFootprints (footprint_path, footprints);

  // Perturbation: 3 degrees of yaw, 1 degree of tilt, (2, -1.5, 0.3) m; truth = its inverse.
  Eigen::Matrix4d perturbation = Eigen::Matrix4d::Identity ();
  perturbation.topLeftCorner<3, 3> () = (Eigen::AngleAxisd (3.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ ()) *
                                         Eigen::AngleAxisd (1.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ()))
                                            .toRotationMatrix ();
  perturbation.topRightCorner<3, 1> () = Eigen::Vector3d (2.0, -1.5, 0.3);
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  std::vector<std::uint32_t> labels;
  std::vector<float> ground_z;
  for (const auto& p : tile)
  {
    if (p.label != 2 && p.label != 6)
      continue;
    if (p.label == 2)
      ground_z.push_back (p.z);
    const Eigen::Vector4d q = perturbation * Eigen::Vector4d (p.x, p.y, p.z, 1.0);
    cloud->emplace_back (float (q.x ()), float (q.y ()), float (q.z ()));
    labels.push_back (p.label);
  }
  // The map has no heights: the floor is put at the terrain's median height.
  std::nth_element (ground_z.begin (), ground_z.begin () + ground_z.size () / 2, ground_z.end ());
  MapPlaneParameters map_parameters;
  map_parameters.floor_height = ground_z[ground_z.size () / 2];

  PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
  reg.setInputSource (cloud);
  reg.setPlaneExtractor (roofOutlineExtractor (labels));
  ASSERT_TRUE (reg.setFootprints (footprints, map_parameters));
  reg.setInitialScanPlanes (16);
  reg.setInitialMapPlanes (16);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  reg.align (aligned);
  const auto& s = reg.getMatchingResult ().statistics;
  std::printf ("AHN 2386_9702: %zu scan planes, %zu map planes, converged %d, %zu matched; combinations "
               "%llu / %llu / %llu / %llu\n", reg.getSourcePlanes ().size (), reg.getMapPlanes ().size (),
               int (reg.hasConverged ()), reg.getMatchingResult ().matches.size (),
               (unsigned long long) s.unconstrained, (unsigned long long) s.vertical,
               (unsigned long long) s.orientation, (unsigned long long) s.residual);
  ASSERT_TRUE (reg.hasConverged ());
  Eigen::Matrix4d truth = perturbation.inverse ();
  truth.topRightCorner<3, 1> () -= reg.getLocalOrigin ();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  for (const auto& p : *cloud)
    centre += p.getVector3fMap ().cast<double> ();
  centre /= double (cloud->size ());
  const auto error = computeTransformationError (reg.getFinalTransformationDouble (), truth, centre);
  std::printf ("AHN 2386_9702: rotation error %.3f deg, translation error %.3f m, plane distance mean "
               "%.3f m, max %.3f m\n", error.rotation_deg, error.translation, reg.getPlaneDistances ().mean,
               reg.getPlaneDistances ().max);
  EXPECT_LE (error.rotation_deg, 0.5);
  EXPECT_LE (error.translation, 0.5);
}
