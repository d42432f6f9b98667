/*
 * pcl_ext: precompiled ProfilePartSegmentation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/profile_part_segmentation.hpp>

PCL_EXT_INSTANTIATE (ProfilePartSegmentation, PCL_EXT_XYZ_POINT_TYPES)
