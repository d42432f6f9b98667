/*
 * pcl_ext: planes of a scan, instantiated for the XYZ point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/registration/impl/plane_extraction.hpp>

PCL_EXT_INSTANTIATE (SACPlaneExtraction, PCL_EXT_XYZ_POINT_TYPES)
