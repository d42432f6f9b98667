/*
 * pcl_ext: precompiled AdaptiveSupervoxelSegmentation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/adaptive_supervoxel_segmentation.hpp>

PCL_EXT_INSTANTIATE (AdaptiveSupervoxelSegmentation, PCL_EXT_XYZ_POINT_TYPES)
