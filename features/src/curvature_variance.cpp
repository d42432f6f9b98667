/*
 * pcl_ext: precompiled CurvatureVarianceEstimation for the common point types, with
 * normals from pcl::Normal, pcl::PointNormal or pcl_ext::CovarianceFeatures.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/features/impl/curvature_variance.hpp>

PCL_EXT_INSTANTIATE (CurvatureVarianceEstimation, PCL_EXT_XYZ_POINT_TYPES)
