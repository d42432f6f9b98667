/*
 * pcl_ext: precompiled AutoProfileSegmentation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/auto_profile_segmentation.hpp>

PCL_EXT_INSTANTIATE (AutoProfileSegmentation, PCL_EXT_XYZ_POINT_TYPES)
