/*
 * pcl_ext: precompiled SaliencyFeatureEstimation for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/features/impl/saliency_feature_estimation.hpp>

PCL_EXT_INSTANTIATE (SaliencyFeatureEstimation, PCL_EXT_XYZ_POINT_TYPES)
