/*
 * The rows of the bad-input matrix for the plane extractions and the registration.
 */
#include "bad_input.h"

#include "plane_fixtures.h"

#include <pcl_ext/registration/map_planes.h>
#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>

#include <pcl/common/point_tests.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace pcl_ext {
namespace test {
namespace bad_input {
void
addRegistrationSubjects (std::vector<Subject>& s)
{
  // Parameter: the inlier distance (> 0). Too few points for a plane, or none on a
  // plane, or points on a line, is no plane (and no error). At the micrometre scale
  // PCL's plane model rejects every sample (its collinearity test has a fixed absolute
  // threshold), so no plane is found there either.
  s.push_back ({"SACPlaneExtraction",
                kCloudInputs,
                {{Bad::OnePoint, Expect::NoneFound},
                 {Bad::Collinear, Expect::NoneFound},
                 {Bad::Tiny, Expect::NoneFound}},
                [] (const Input& in) {
                  SACPlaneExtraction<Point> sac;
                  sac.setInputCloud (in.cloud);
                  if (in.indices)
                    sac.setIndices (in.indices);
                  sac.setDistanceThreshold (in.param ? *in.param : 0.02 * in.scale);
                  if (in.nan_param)
                    sac.setDistanceThreshold (std::numeric_limits<double>::quiet_NaN());
                  sac.setMinInliers (20);
                  std::vector<pcl::PointIndices> planes;
                  sac.extract (planes);
                  return segments (in, planes);
                }});

  // The box as a classified airborne cloud: its floor is ground, the rest building
  // (label by height above the lowest point); parameter: the outline band (> 0). A
  // horizontal plane, or one point, is all floor: no building point, which is refused.
  // At the micrometre scale the plane models reject every sample (as for
  // SACPlaneExtraction).
  s.push_back (
      {"RoofOutlinePlaneExtraction",
       kCloudInputs,
       {{Bad::Coplanar, Expect::Refused},
        {Bad::Collinear, Expect::NoneFound},
        {Bad::Tiny, Expect::NoneFound}},
       [] (const Input& in) {
         float floor = std::numeric_limits<float>::infinity();
         for (const auto& p : *in.cloud)
           if (pcl::isFinite (p))
             floor = std::min (floor, p.z);
         pcl::PointCloud<pcl::Label>::Ptr labels (new pcl::PointCloud<pcl::Label>);
         for (const auto& p : *in.cloud)
           labels->push_back (pcl::Label{p.z < floor + 0.02 * in.scale ? 2u : 6u});
         RoofOutlinePlaneExtraction<Point> walls;
         walls.setInputCloud (in.cloud);
         walls.setInputLabels (labels);
         if (in.indices)
           walls.setIndices (in.indices);
         walls.setGroundDistanceThreshold (0.02 * in.scale);
         walls.setBuildingTolerance (0.2 * in.scale);
         walls.setMinBuildingPoints (20);
         walls.setOpenSideDistance (0.2 * in.scale);
         walls.setMaxGap (0.3 * in.scale);
         walls.setOutlineBand (in.param ? *in.param : 0.02 * in.scale);
         if (in.nan_param)
           walls.setOutlineBand (std::numeric_limits<double>::quiet_NaN());
         std::vector<pcl::PointIndices> planes;
         walls.extract (planes);
         return segments (in, planes);
       }});

  // Registration of the cloud to an H-shaped footprint; parameter: the angle tolerance.
  s.push_back ({"PlaneMatchingRegistration",
                kCloudInputs,
                {{Bad::SomeNaNDense, Expect::Ran},
                 {Bad::SomeNaNNotDense, Expect::Ran},
                 {Bad::DuplicatePoints, Expect::Ran},
                 {Bad::Collinear, Expect::Ran},
                 {Bad::Coplanar, Expect::Ran},
                 {Bad::Utm, Expect::Ran},
                 {Bad::Tiny, Expect::Ran}},
                [] (const Input& in) {
                  PlaneMatchingRegistration<Point, Point> reg;
                  io::Footprint footprint;
                  footprint.polygons.resize (1);
                  footprint.polygons[0].outer = pcl_ext::test::asymmetricH();
                  EXPECT_TRUE (reg.setFootprints ({footprint}));
                  reg.setInputSource (in.cloud);
                  if (in.indices)
                    reg.setIndices (in.indices);
                  reg.setNumberOfThreads (2);
                  if (in.param)
                    reg.setTolerances (*in.param, 0.5);
                  if (in.nan_param)
                    reg.setTolerances (std::numeric_limits<double>::quiet_NaN(), 0.5);
                  Cloud aligned;
                  reg.align (aligned);
                  Outcome o;
                  o.produced = reg.hasConverged();
                  o.finite_transform = reg.getFinalTransformation().allFinite();
                  return o;
                }});
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
