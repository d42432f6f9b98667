/*
 * pcl_ext: precompiled NanoflannKdTree for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/search/impl/nanoflann_kdtree.hpp>

PCL_EXT_INSTANTIATE (NanoflannKdTree, PCL_EXT_XYZ_POINT_TYPES)
