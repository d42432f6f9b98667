/*
 * pcl_ext: precompiled CovarianceFeatureEstimation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/features/impl/covariance_features.hpp>

PCL_EXT_INSTANTIATE (CovarianceFeatureEstimation, PCL_EXT_XYZ_POINT_TYPES)
