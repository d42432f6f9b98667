/*
 * pcl_ext: precompiled LeftoverRegionGrowing for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/leftover_region_growing.hpp>

PCL_EXT_INSTANTIATE (LeftoverRegionGrowing, PCL_EXT_XYZ_POINT_TYPES)
