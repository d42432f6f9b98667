/*
 * pcl_ext: precompiled ChiSquaredBoundaryEstimation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/features/impl/chi_squared_boundary.hpp>

PCL_EXT_INSTANTIATE (ChiSquaredBoundaryEstimation, PCL_EXT_XYZ_POINT_TYPES)
