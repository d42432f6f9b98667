/*
 * ClusterSizeLimits: the smallest and largest segment a segmenter keeps, set as on
 * pcl::RegionGrowing, their check and the test a segment's size goes through.
 */
#include <pcl_ext/segmentation/cluster_size_limits.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <limits>
#include <type_traits>

namespace {
/** A segmenter's view of the mixin: its protected check and size test. */
class Limits : public pcl_ext::ClusterSizeLimits {
public:
  using ClusterSizeLimits::keepsClusterSize;
  using ClusterSizeLimits::validClusterSizes;
};

TEST (ClusterSizeLimits, DefaultsKeepEverySegmentAsPclRegionGrowing)
{
  Limits limits;
  EXPECT_EQ (limits.getMinClusterSize(), 1u);
  EXPECT_EQ (limits.getMaxClusterSize(), std::numeric_limits<pcl::uindex_t>::max());
  EXPECT_TRUE (limits.validClusterSizes());
  EXPECT_FALSE (limits.keepsClusterSize (0));
  EXPECT_TRUE (limits.keepsClusterSize (1));
  EXPECT_TRUE (limits.keepsClusterSize (std::numeric_limits<pcl::uindex_t>::max()));
}

TEST (ClusterSizeLimits, BoundsAreInclusive)
{
  Limits limits;
  limits.setMinClusterSize (10);
  limits.setMaxClusterSize (20);
  EXPECT_EQ (limits.getMinClusterSize(), 10u);
  EXPECT_EQ (limits.getMaxClusterSize(), 20u);
  EXPECT_TRUE (limits.validClusterSizes());
  EXPECT_FALSE (limits.keepsClusterSize (9));
  EXPECT_TRUE (limits.keepsClusterSize (10));
  EXPECT_TRUE (limits.keepsClusterSize (20));
  EXPECT_FALSE (limits.keepsClusterSize (21));
}

TEST (ClusterSizeLimits, ZeroMinimumOrMaximumBelowMinimumIsInvalid)
{
  Limits limits;
  limits.setMinClusterSize (0);
  EXPECT_FALSE (limits.validClusterSizes());
  limits.setMinClusterSize (5);
  limits.setMaxClusterSize (4);
  EXPECT_FALSE (limits.validClusterSizes());
  limits.setMaxClusterSize (5);
  EXPECT_TRUE (limits.validClusterSizes());
  EXPECT_TRUE (limits.keepsClusterSize (5));
}

TEST (ClusterSizeLimits, SegmentersAreSetThroughIt)
{
  static_assert (std::is_base_of_v<pcl_ext::ClusterSizeLimits,
                                   pcl_ext::ProfileSegmentation<pcl::PointXYZ>>);
  static_assert (std::is_base_of_v<pcl_ext::ClusterSizeLimits,
                                   pcl_ext::VarianceRegionGrowing<pcl::PointXYZ>>);
  pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> growing;
  pcl_ext::ClusterSizeLimits& limits = growing;
  limits.setMinClusterSize (7);
  limits.setMaxClusterSize (70);
  EXPECT_EQ (growing.getMinClusterSize(), 7u);
  EXPECT_EQ (growing.getMaxClusterSize(), 70u);
}
} // namespace
