/*
 * pcl_ext: the point type of local surface intersections (Belton & Lichti 2006, section
 * 4).
 */
#pragma once

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace pcl_ext {
/** \brief A local intersection point of two segments (Belton & Lichti 2006, section 4,
 * eq. 17), with the segments and the pair of surface points it was computed from.
 *
 * Written by pcl_ext::LocalSurfaceIntersection; saved to PCD with the fields x, y, z,
 * segment_a, segment_b, index_a, index_b. The position is computed in double precision
 * and stored as float, like the cloud it came from.
 */
struct EIGEN_ALIGN16 SurfaceIntersectionPoint {
  PCL_ADD_POINT4D;
  std::uint32_t segment_a = 0; ///< segment of the surface point index_a
  std::uint32_t segment_b = 0; ///< segment of the surface point index_b
  std::int32_t index_a = -1;   ///< the surface point p1 of eq. 17
  std::int32_t index_b = -1;   ///< the surface point p2 of eq. 17, on the other segment
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
} // namespace pcl_ext

POINT_CLOUD_REGISTER_POINT_STRUCT (
    pcl_ext::SurfaceIntersectionPoint,
    (float, x, x) (float, y, y) (float, z, z) (std::uint32_t, segment_a, segment_a) (
        std::uint32_t, segment_b, segment_b) (std::int32_t,
                                              index_a,
                                              index_a) (std::int32_t, index_b, index_b))
