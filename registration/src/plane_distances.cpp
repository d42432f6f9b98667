/*
 * pcl_ext: the distances between the matched planes of a registration, instantiated for
 * the XYZ point types.
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/registration/impl/plane_distances.hpp>

PCL_EXT_INSTANTIATE (computePlaneDistances, PCL_EXT_XYZ_POINT_TYPES)
