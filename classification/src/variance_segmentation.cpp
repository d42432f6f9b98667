/*
 * pcl_ext: segmentByLocalVariance precompiled for the common point types.
 */
#include <pcl_ext/classification/impl/variance_segmentation.hpp>
#include <pcl_ext/common/instantiate.h>

PCL_EXT_INSTANTIATE (segmentByLocalVariance, PCL_EXT_XYZ_POINT_TYPES)
