/*
 * pcl_ext: precompiled CylinderSegmentJoin for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/cylinder_segment_join.hpp>

PCL_EXT_INSTANTIATE (CylinderSegmentJoin, PCL_EXT_XYZ_POINT_TYPES)
