/*
 * pcl_ext: precompiled MultiscaleCrfClassification for the common point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/classification/impl/multiscale_crf_classification.hpp>

PCL_EXT_INSTANTIATE (MultiscaleCrfClassification, PCL_EXT_XYZ_POINT_TYPES)
