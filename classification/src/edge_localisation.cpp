/*
 * pcl_ext: precompiled EdgeLocalisation for the common point types.
 */
#include <pcl_ext/classification/impl/edge_localisation.hpp>
#include <pcl_ext/common/instantiate.h>

PCL_EXT_INSTANTIATE (EdgeLocalisation, PCL_EXT_XYZ_POINT_TYPES)
