/*
 * pcl_ext: wall planes from roof outlines, instantiated for the XYZ point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/registration/impl/roof_outline_plane_extraction.hpp>

PCL_EXT_INSTANTIATE (RoofOutlinePlaneExtraction, PCL_EXT_XYZ_POINT_TYPES)
