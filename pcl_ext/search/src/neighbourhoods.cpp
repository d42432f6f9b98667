/*
 * pcl_ext: precompiled Neighbourhoods for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/search/impl/neighbourhoods.hpp>

PCL_EXT_INSTANTIATE (Neighbourhoods, PCL_EXT_XYZ_POINT_TYPES)
