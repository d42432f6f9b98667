/*
 * pcl_ext: precompiled NearestOfEachSegment for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/nearest_of_each_segment.hpp>

PCL_EXT_INSTANTIATE (NearestOfEachSegment, PCL_EXT_XYZ_POINT_TYPES)
