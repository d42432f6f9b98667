/*
 * pcl_ext: precompiled LocalSurfaceIntersection for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/local_surface_intersection.hpp>

PCL_EXT_INSTANTIATE (LocalSurfaceIntersection, PCL_EXT_XYZ_POINT_TYPES)
