/*
 * pcl_ext: the point type of synthetic scans, with per-point ground truth.
 */
#pragma once

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace pcl_ext {
namespace simulation {
/** \brief A simulated TLS return with its ground truth.
 *
 * \c point_class holds a pcl_ext::PointClass. It is saved as the PCD field \c class
 * (see scene_io.h): \c class is a C++ keyword and cannot name a member, so the
 * registered tag is \c point_class and the field is renamed when saving and loading.
 */
struct EIGEN_ALIGN16 SimulatedPoint {
  PCL_ADD_POINT4D;
  PCL_ADD_RGB;
  float intensity = 0.f; ///< reflectance-like return strength in [0, 1]
  /** \brief True segment id, >= 1: a connected visible piece of a surface by default,
   * or the surface (see TlsScanSimulation::setConnectedSegments). */
  std::uint32_t segment = 0;
  std::uint32_t object = 0;      ///< true object id, >= 1
  std::uint32_t point_class = 0; ///< pcl_ext::PointClass
  std::uint32_t label = 0;       ///< scene label (see each scene), 0 = none
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
} // namespace simulation
} // namespace pcl_ext

POINT_CLOUD_REGISTER_POINT_STRUCT (
    pcl_ext::simulation::SimulatedPoint,
    (float, x, x) (float, y, y) (float, z, z) (float, rgb, rgb) (
        float, intensity, intensity) (std::uint32_t, segment, segment) (
        std::uint32_t, object, object) (std::uint32_t,
                                        point_class,
                                        point_class) (std::uint32_t, label, label))
