/*
 * pcl_ext: a plane in 3-D, one type and one sign convention for every module.
 */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <limits>

namespace pcl_ext {
/** \brief A plane n . x + d = 0 with unit normal n, in double precision, and what is
 * known of the points it stands for.
 *
 * The convention is PCL's (pcl::ModelCoefficients holds a, b, c, d of a x + b y + c z
 * + d = 0): coefficients() is the homogeneous vector pi = (n, d) of Khoshelham & Gorte
 * (2009) eq. 3 and Belton & Lichti (2006) eq. 13. A fitted plane passes through the
 * centroid of its points (d = -n . centroid). A default plane is invalid: its normal
 * and offset are NaN until set. */
struct Plane {
  /** Unit normal n; NaN when there is no plane. */
  Eigen::Vector3d normal =
      Eigen::Vector3d::Constant (std::numeric_limits<double>::quiet_NaN());
  /** Offset: n . x + d = 0 on the plane, so -d is the signed distance of the origin's
   * foot point along n. */
  double d = std::numeric_limits<double>::quiet_NaN();
  /** Centroid of the supporting points (a point of the plane when it was fitted to
   * them), or any point of the supporting patch. */
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  /** Root mean square distance of the supporting points to the plane (NaN: unknown). */
  double rms = std::numeric_limits<double>::quiet_NaN();
  /** Largest distance of a supporting point to the plane (NaN: unknown). */
  double max_residual = std::numeric_limits<double>::quiet_NaN();
  /** Number of supporting points (0 for planes not fitted to points). */
  std::size_t size = 0;
  /** Bounding box of the supporting points (empty when not computed). */
  Eigen::AlignedBox3d extent;

  /** \brief The plane with unit normal \a n (normalised here) through \a point; an
   * invalid plane when \a n is zero or not finite. */
  static Plane
  throughPoint (const Eigen::Vector3d& n, const Eigen::Vector3d& point)
  {
    Plane plane;
    const double length = n.norm();
    if (!(length > 0.0) || !std::isfinite (length))
      return plane;
    plane.normal = n / length;
    plane.d = -plane.normal.dot (point);
    plane.centroid = point;
    return plane;
  }

  /** \brief True when the normal and offset are finite. */
  bool
  isValid () const
  {
    return normal.allFinite() && std::isfinite (d);
  }

  /** \brief Signed distance n . x + d of \a x (positive on the normal's side). */
  double
  signedDistance (const Eigen::Vector3d& x) const
  {
    return normal.dot (x) + d;
  }

  /** \brief The foot of the perpendicular from \a x onto the plane. */
  Eigen::Vector3d
  project (const Eigen::Vector3d& x) const
  {
    return x - signedDistance (x) * normal;
  }

  /** \brief The homogeneous vector (n, d), as pcl::ModelCoefficients orders it. */
  Eigen::Vector4d
  coefficients () const
  {
    return Eigen::Vector4d (normal.x(), normal.y(), normal.z(), d);
  }
};
} // namespace pcl_ext
