/*
 * pcl_ext: precompiled ProfileSegmentation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/profile_segmentation.hpp>

PCL_EXT_INSTANTIATE (ProfileSegmentation, PCL_EXT_XYZ_POINT_TYPES)
