/*
 * pcl_ext: precompiled estimateCloudNoise for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/search/impl/cloud_noise.hpp>

PCL_EXT_INSTANTIATE (estimateCloudNoise, PCL_EXT_XYZ_POINT_TYPES)
