/*
 * pcl_ext: precompiled ProjectedNormalCurvaturesEstimation for the common point types,
 * with normals from pcl::Normal, pcl::PointNormal or pcl_ext::CovarianceFeatures.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/features/impl/projected_normal_curvatures.hpp>
#include <pcl_ext/point_types.h>

PCL_EXT_INSTANTIATE (ProjectedNormalCurvaturesEstimation, PCL_EXT_XYZ_POINT_TYPES)
