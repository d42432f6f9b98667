/*
 * pcl_ext: precompiled LocalVarianceClassification for the common point types.
 */
#include <pcl_ext/classification/impl/local_variance_classification.hpp>
#include <pcl_ext/common/instantiate.h>

PCL_EXT_INSTANTIATE (LocalVarianceClassification, PCL_EXT_XYZ_POINT_TYPES)
