/*
 * pcl_ext: precompiled CoplanarSegmentMerging for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/coplanar_segment_merging.hpp>

PCL_EXT_INSTANTIATE (CoplanarSegmentMerging, PCL_EXT_XYZ_POINT_TYPES)
