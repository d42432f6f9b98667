/*
 * pcl_ext: precompiled LeftoverPlaneAssignment for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/segmentation/impl/leftover_plane_assignment.hpp>

PCL_EXT_INSTANTIATE (LeftoverPlaneAssignment, PCL_EXT_XYZ_POINT_TYPES)
