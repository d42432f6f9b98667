/*
 * pcl_ext: planes as Khoshelham & Gorte (2009) use them for registration.
 */
#pragma once

#include <pcl/PointIndices.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace pcl_ext {
/** \brief A plane pi = (n, -d): points x on it satisfy n . x = d (Khoshelham & Gorte
 * 2009, eq. 3), n of unit length, d signed (eq. 2's absolute value is not used: it
 * contradicts eq. 1's normal on one side of the origin, see computeMapPlanes), with
 * what the matcher needs to know about its support. */
struct RegistrationPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< unit normal n
  double d = 0.0;                                    ///< signed offset: n . x = d
  Eigen::Vector3d centroid =
      Eigen::Vector3d::Zero(); ///< a point of the supporting patch
  Eigen::AlignedBox3d extent;  ///< bounding box of the patch (empty when unknown)
  std::size_t support = 0;     ///< inlier count (scan planes), 0 for map planes
  double rms = 0.0;            ///< RMS distance of the inliers to the plane (m)

  /** \brief The homogeneous vector pi = (n1, n2, n3, -d) of eq. 3. */
  Eigen::Vector4d
  coefficients () const
  {
    return Eigen::Vector4d (normal.x(), normal.y(), normal.z(), -d);
  }

  /** \brief Signed distance of \a x to the plane. */
  double
  signedDistance (const Eigen::Vector3d& x) const
  {
    return normal.dot (x) - d;
  }
};

/** \brief A plane extracted from a scan: the plane and its inlier indices. */
struct ScanPlane : RegistrationPlane {
  pcl::PointIndices inliers; ///< indices into the scanned cloud
};

/** \brief A plane inferred from a footprint polygon (section 3.1): a wall on one edge,
 * or the floor. */
struct MapPlane : RegistrationPlane {
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
 * n' = R n, d' = s d + n' . t (the inverse-transpose rule of eq. 6, kept unit-normal).
 */
RegistrationPlane
transformPlane (const RegistrationPlane& plane, const Eigen::Matrix4d& transformation);

/** \brief transformPlane for many planes under one transform, part by part: the scale
 * (a cube root) and the rotation are computed once, and each part of the image only
 * when asked for. The parts are those of transformPlane, to the last bit. */
class PlaneTransformer {
public:
  explicit PlaneTransformer (const Eigen::Matrix4d& transformation);

  /** \brief n' = R n (normalised). */
  Eigen::Vector3d
  normal (const RegistrationPlane& plane) const
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
  extent (const RegistrationPlane& plane) const;

  /** \brief The whole image, as transformPlane. */
  RegistrationPlane
  operator() (const RegistrationPlane& plane) const;

private:
  Eigen::Matrix3d block_; // s R
  double scale_;
  Eigen::Matrix3d rotation_; // R
  Eigen::Vector3d t_;
};
} // namespace pcl_ext
