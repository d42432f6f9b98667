/*
 * Tests of the adaptive radius of Lim & Suter's super-voxels (section 3.1, eq. 1-4): the
 * noise constant.
 */
#include "../features/crf_test_clouds.h"

#include <pcl_ext/segmentation/adaptive_radius.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

TEST (AdaptiveSupervoxels, NoiseFromAPlanarPatch)
{
  // The mean distance to the plane of Gaussian noise sigma is sigma sqrt(2 / pi).
  const auto cloud = crf_test::floorAndWall (0.02, 0.01);
  std::vector<pcl::index_t> floor;
  for (std::size_t i = 0; i < cloud->size (); ++i)
    if ((*cloud)[i].x > 0.5f)
      floor.push_back (static_cast<pcl::index_t> (i));
  const double sigma = pcl_ext::estimateNoiseFromPlanarPatch (*cloud, floor);
  EXPECT_NEAR (sigma, 0.01 * std::sqrt (2.0 / M_PI), 0.0005);
  EXPECT_TRUE (std::isnan (pcl_ext::estimateNoiseFromPlanarPatch (*cloud, {0, 1})));
  // The automatic estimate finds the same order of noise on the two planes.
  pcl_ext::AdaptiveRadiusEstimator est;
  ASSERT_TRUE (est.initialize (cloud, {}, pcl_ext::AdaptiveRadiusParameters ()));
  EXPECT_GT (est.getNoise (), 0.005);
  EXPECT_LT (est.getNoise (), 0.015);
}
