/*
 * pcl_ext: planes as Khoshelham & Gorte (2009) use them for registration.
 *
 * A plane is pcl_ext::Plane, n . x + d = 0: the paper's pi = (n, -d) of eq. 3 with its
 * n . x = d, written with PCL's sign (coefficients() is the paper's pi either way).
 * Eq. 2's absolute value is not used: it contradicts eq. 1's normal on one side of the
 * origin (see computeMapPlanes).
 */
#pragma once

#include <pcl_ext/common/plane.h>

#include <pcl/PointIndices.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace pcl_ext {
/** \brief A plane extracted from a scan: the plane (size = inlier count, extent = the
 * inliers' robust bounding box) and its inlier indices. */
struct ScanPlane : Plane {
  pcl::PointIndices inliers; ///< indices into the scanned cloud
};

/** \brief A plane inferred from a footprint polygon (section 3.1): a wall on one edge,
 * or the floor. */
struct MapPlane : Plane {
  int polygon =
      -1; ///< index of the polygon (part) in the footprint list; -1 for the floor
  int ring = -1; ///< 0 = outer ring, 1.. = hole; -1 for the floor
  int edge = -1; ///< edge index in the ring (v_edge to v_edge+1); -1 for the floor
  Eigen::Vector2d start =
      Eigen::Vector2d::Zero(); ///< wall: first edge vertex (local frame)
  Eigen::Vector2d end =
      Eigen::Vector2d::Zero(); ///< wall: second edge vertex (local frame)

  bool
  isFloor () const
  {
    return edge < 0;
  }

  /** \brief Wall length (0 for the floor). */
  double
  length () const
  {
    return isFloor() ? 0.0 : (end - start).norm();
  }
};

/** \brief Image of \a plane under x' = T x, T a rigid or similarity transform (s R, t):
 * n' = R n, d' = s d - n' . t (the inverse-transpose rule of eq. 6, kept unit-normal).
 */
Plane
transformPlane (const Plane& plane, const Eigen::Matrix4d& transformation);

/** \brief transformPlane for many planes under one transform, part by part: the scale
 * (a cube root) and the rotation are computed once, and each part of the image only
 * when asked for. The parts are those of transformPlane, to the last bit. */
class PlaneTransformer {
public:
  explicit PlaneTransformer (const Eigen::Matrix4d& transformation);

  /** \brief n' = R n (normalised). */
  Eigen::Vector3d
  normal (const Plane& plane) const
  {
    return (rotation_ * plane.normal).normalized();
  }

  /** \brief x' = s R x + t. */
  Eigen::Vector3d
  point (const Eigen::Vector3d& x) const
  {
    return block_ * x + t_;
  }

  /** \brief Bounding box of the transformed corners of \a plane's extent (empty if it
   * is). */
  Eigen::AlignedBox3d
  extent (const Plane& plane) const;

  /** \brief The whole image, as transformPlane. */
  Plane
  operator() (const Plane& plane) const;

private:
  Eigen::Matrix3d block_; // s R
  double scale_;
  Eigen::Matrix3d rotation_; // R
  Eigen::Vector3d t_;
};
} // namespace pcl_ext
