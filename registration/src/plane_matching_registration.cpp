/*
 * pcl_ext: registration by plane matching, instantiated for the XYZ point types (source
 * and target of the same type).
 */
#include <pcl_ext/common/instantiate.h>
#include <pcl_ext/registration/impl/plane_matching_registration.hpp>

PCL_EXT_INSTANTIATE (PlaneMatchingRegistration, PCL_EXT_XYZ_POINT_TYPES)
