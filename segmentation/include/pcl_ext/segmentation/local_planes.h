/*
 * pcl_ext: plane fits to local neighbourhoods and to whole segments, and the
 * intersection of two local planes (Belton & Lichti 2006, sections 3 and 4).
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/plane.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pcl_ext {
/** \brief A plane fitted to a few points (pcl_ext::Plane: n . x + d = 0 through their
 * centroid), with the in-plane principal axes and variances of the points, which give
 * the plane's uncertainty away from its centroid. */
struct LocalPlane : Plane {
  Eigen::Vector3d axis1 = Eigen::Vector3d::UnitX(); ///< in-plane principal axes of the
  Eigen::Vector3d axis2 =
      Eigen::Vector3d::UnitY(); ///< points (middle, largest eigenvalue)
  double variance1 = 0.0;       ///< the points' variance along axis1
  double variance2 = 0.0;       ///< the points' variance along axis2

  /** \brief Square root of the largest eigenvalue: the points' extent. */
  double
  spread () const
  {
    return std::sqrt (variance2);
  }

  /** \brief Standard deviation of signedDistance(p) for a new point \a p of the same
   * surface: the points' noise (from the rms, corrected for the 3 fitted parameters)
   * plus the uncertainty of the plane at \a p, which grows with its distance from the
   * centroid (the prediction variance of a least-squares fit, s^2 (1 + 1/n + u^2 / (n
   * l1) + v^2 / (n l2))). */
  double
  residualSigma (const Eigen::Vector3d& p) const
  {
    const double n = static_cast<double> (size);
    const double s2 = size > 3 ? rms * rms * n / (n - 3.0) : rms * rms;
    const Eigen::Vector3d d = p - centroid;
    const double u = axis1.dot (d), v = axis2.dot (d);
    return std::sqrt (
        s2 * (1.0 + 1.0 / n + u * u / (n * variance1) + v * v / (n * variance2)));
  }
};

/** \brief Fit a plane through the centroid of \a cloud[\a begin .. \a end) (non-finite
 * points skipped).
 *
 * With \a normal null the normal is the eigenvector of the smallest eigenvalue of the
 * points' covariance (total least squares); otherwise the plane takes that normal
 * (normalised) through their centroid, as the paper's first form does ("fit a plane
 * through each point based on their normal vectors ... through the centroid of
 * neighbourhoods"). \return false when fewer than 3 finite points, when the points are
 * collinear or coincident, or when the given normal is not finite and non-zero */
template <typename PointT, typename IndexIterator>
bool
fitLocalPlane (const pcl::PointCloud<PointT>& cloud,
               IndexIterator begin,
               IndexIterator end,
               const Eigen::Vector3d* normal,
               LocalPlane& plane);

/** \brief The same fit from the running sums of the points (finite points only), for
 * callers that accumulate them while choosing the points. */
bool
fitLocalPlane (const CovarianceSums& sums,
               const Eigen::Vector3d* normal,
               LocalPlane& plane);

/** \brief The angle theta of Belton & Lichti eq. 9 between two unoriented unit normals,
 * in [0, pi/2] radians: arccos |n1 . n2| (a covariance normal has no sign, so n and -n
 * are the same plane). */
double
normalAngle (const Eigen::Vector3d& n1, const Eigen::Vector3d& n2);

/** \brief The local intersection point of two planes, Belton & Lichti eq. 10-17.
 *
 * The line of intersection of the planes n_i . x + d_i = 0 (eq. 13-14) solves M x = b
 * (eq. 10-12) and runs along a = n1 x n2, the null space of M (eq. 15). The minimiser
 * of eq. 17, sum ||l(t) - p_i||^2, is the projection of the midpoint m of \a p1 and \a
 * p2 onto that line; it is computed in closed form around m (so large coordinates keep
 * their precision): x = m + alpha n1 + beta n2 with [1 c; c 1] [alpha beta]^T = -[r1
 * r2]^T, c = n1 . n2 and r_i the signed distance of m from plane i. \param[out] point
 * the intersection point \param[out] direction the unit direction a of the line \return
 * false when the normals are parallel (no unique line) or not finite */
bool
intersectLocalPlanes (const Plane& plane1,
                      const Plane& plane2,
                      const Eigen::Vector3d& p1,
                      const Eigen::Vector3d& p2,
                      Eigen::Vector3d& point,
                      Eigen::Vector3d& direction);
/** \brief Fit a plane to \a indices of \a cloud in double precision around the points'
 * centroid (so georeferenced coordinates lose nothing), with its residuals (rms,
 * max_residual) and size.
 * \param[in] viewpoint the normal is turned to face it (n . (viewpoint - centroid) >=
 * 0) \return the plane; invalid (Plane::isValid false, normal NaN) for fewer than 3
 * finite points or collinear points */
template <typename PointT>
Plane
fitSegmentPlane (const pcl::PointCloud<PointT>& cloud,
                 const pcl::Indices& indices,
                 const Eigen::Vector3d& viewpoint);
} // namespace pcl_ext

template <typename PointT, typename IndexIterator>
bool
pcl_ext::fitLocalPlane (const pcl::PointCloud<PointT>& cloud,
                        IndexIterator begin,
                        IndexIterator end,
                        const Eigen::Vector3d* normal,
                        LocalPlane& plane)
{
  return fitLocalPlane (sumFinitePoints (cloud, begin, end), normal, plane);
}

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/local_planes.hpp>
#endif
