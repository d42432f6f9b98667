/*
 * pcl_ext: per-neighbourhood kernels of Belton & Lichti (2006), shared by the feature
 * estimators and the local variance classifier.
 */
#pragma once

#include <pcl_ext/common/covariance.h>

#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pcl_ext {
/** \brief The covariance summary of one neighbourhood: what every Belton & Lichti
 * feature of the index point needs, computed once and reused. */
struct LocalCovariance {
  EigenDecomposition eigen;                           ///< ascending l0 <= l1 <= l2
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(); ///< pt_c of eq. 7-8
  std::size_t size = 0;                               ///< finite neighbours used
};

/** \brief Smallest l1 / l2 for which a neighbourhood has a tangent plane. Below it the
 * points are collinear (to float precision), the normal is undefined and eq. 6 divides
 * by ~0. */
constexpr double kMinPlanarRatio = 1e-8;

/** \brief Fewest neighbours (the index point included) for a covariance with a plane.
 */
constexpr std::size_t kMinNeighbours = 3;

/** \brief Whether ascending eigenvalues describe a neighbourhood with a tangent plane:
 * finite, at least kMinNeighbours points, l1 > kMinPlanarRatio * l2 (so not all
 * coincident, not collinear). */
bool
hasTangentPlane (const Eigen::Vector3d& ascending_values, std::size_t size);

/** \brief Covariance, eigen decomposition and centroid of the points \a begin .. \a end
 * of \a cloud (Belton & Lichti eq. 1-2, population covariance, double precision).
 * \return true when the neighbourhood has a tangent plane (see hasTangentPlane) */
template <typename PointT, typename IndexIterator>
inline bool
computeNeighbourhoodCovariance (const pcl::PointCloud<PointT>& cloud,
                                IndexIterator begin,
                                IndexIterator end,
                                LocalCovariance& result)
{
  Eigen::Matrix3d covariance;
  result.size = computeLocalCovariance (cloud, begin, end, covariance, result.centroid);
  if (result.size < kMinNeighbours ||
      !computeEigenDecomposition (covariance, result.eigen))
    return false;
  return hasTangentPlane (result.eigen.values, result.size);
}

/** \brief The chi-squared quantile with 2 degrees of freedom at \a confidence,
 * chi2_2(alpha) of Belton & Lichti eq. 6. With 2 degrees of freedom the distribution is
 * exponential, so the quantile is exact: -2 ln(1 - confidence) (0.95 gives 5.991).
 * \return NaN unless 0 < confidence < 1 */
double
chiSquaredQuantile2 (double confidence);

/** \brief Belton & Lichti eq. 6-8: the index point's offset from the neighbourhood
 * centroid, in the tangent plane, in units of the neighbourhood's spread.
 *
 * u = e1 . (p - c), v = e2 . (p - c) along the eigenvectors of the two largest
 * eigenvalues l1, l2 (eq. 7-8), and the statistic is n (u^2 / l1 + v^2 / l2).
 *
 * The factor n (neighbourhood size) departs from the printed eq. 6, which has none. The
 * paper describes the test as "a confidence region around the centroid" after Johnson &
 * Wichern, whose region for a mean uses the covariance of the mean, S / n. Without the
 * factor the test cannot work at the confidence levels the paper implies: on a
 * uniformly sampled plane a point exactly on a straight border scores u^2/l1 + v^2/l2
 * = 2.57, below chi2_2(0.95) = 5.991, and every point of a uniform disc lies inside the
 * 95% region. With it, an interior point of a randomly sampled surface scores
 * chi2_2-distributed (so \a confidence is the fraction of interior points kept), and a
 * border point scores about 2.57 n. \param[in] point the index point pt_i \param[in]
 * local its neighbourhood's covariance (must have a tangent plane) \param[in]
 * scale_by_size false gives the printed eq. 6 (no factor n) \param[in] noise_variance
 * the variance sigma^2 of the index point's own position noise, added to l1 / n and l2
 * / n (to l1 and l2 without the factor): u^2 / (l1 / n + sigma^2) + v^2 / (l2 / n +
 * sigma^2). The offset of the index point from the centroid is the centroid's sampling
 * error plus the point's own noise; where the neighbourhood spans only a few sigma the
 * noise alone would fail the test. Default 0: the statistic above.
 */
inline double
centroidOffsetStatistic (const Eigen::Vector3d& point,
                         const LocalCovariance& local,
                         bool scale_by_size = true,
                         double noise_variance = 0.0)
{
  const Eigen::Vector3d d = point - local.centroid;
  const double u = local.eigen.vectors.col (1).dot (d);
  const double v = local.eigen.vectors.col (2).dot (d);
  const double n = scale_by_size ? static_cast<double> (local.size) : 1.0;
  if (noise_variance == 0.0)
    return (u * u / local.eigen.values[1] + v * v / local.eigen.values[2]) * n;
  return u * u / (local.eigen.values[1] / n + noise_variance) +
         v * v / (local.eigen.values[2] / n + noise_variance);
}

/** \brief Principal directions of Belton & Lichti section 5, from the neighbours'
 * normals.
 *
 * Each neighbour normal n_j and its negative image -n_j are projected onto the tangent
 * plane of the index point (normal \a normal); the 2D covariance of these projections
 * is decomposed and its eigenvectors mapped back to 3D. Because every projection comes
 * with its negative, the projections' mean is zero and the covariance is (1/m) sum p_j
 * p_j^T: the result does not depend on how the normals are oriented.
 */
struct ProjectedNormalDirections {
  Eigen::Vector3d max_direction =
      Eigen::Vector3d::Zero(); ///< most change of the normal
  Eigen::Vector3d min_direction = Eigen::Vector3d::Zero(); ///< least change (pipe axis)
  double max_change = 0.0; ///< larger eigenvalue of the projected normals' covariance
  double min_change = 0.0; ///< smaller eigenvalue
};

/** \brief Accumulates projected neighbour normals (section 5) in a tangent-plane basis
 * without allocating, then decomposes the 2x2 covariance in closed form. */
class ProjectedNormalAccumulator {
public:
  /** \brief Start at an index point of unit normal \a normal. */
  explicit ProjectedNormalAccumulator (const Eigen::Vector3d& normal);

  /** \brief Add a neighbour normal (any orientation, any length > 0; it is normalised).
   * Non-finite or zero normals are skipped. */
  inline void
  add (const Eigen::Vector3d& neighbour_normal)
  {
    const double len2 = neighbour_normal.squaredNorm();
    if (!(len2 > 0.0) || !std::isfinite (len2))
      return;
    const double a = neighbour_normal.dot (axis_a_), b = neighbour_normal.dot (axis_b_);
    const double inv = 1.0 / len2;
    aa_ += a * a * inv;
    ab_ += a * b * inv;
    bb_ += b * b * inv;
    ++count_;
  }

  std::size_t
  count () const
  {
    return count_;
  }

  /** \brief The directions; false when fewer than 2 normals were added. */
  bool
  compute (ProjectedNormalDirections& result) const;

private:
  Eigen::Vector3d normal_, axis_a_, axis_b_;
  double aa_ = 0.0, ab_ = 0.0, bb_ = 0.0;
  std::size_t count_ = 0;
};

/** \brief Belton & Lichti eq. 5: the population variance E(k^2) - E(k)^2 of the finite
 * curvatures \a values[i] for the indices \a begin .. \a end, computed around the first
 * value (shifted sums, so no cancellation). \param[out] count the number of finite
 * values used \return the variance; NaN when fewer than \a min_count finite values */
template <typename IndexIterator, typename CurvatureOf>
inline double
curvatureVariance (IndexIterator begin,
                   IndexIterator end,
                   const CurvatureOf& curvature_of,
                   std::size_t& count,
                   std::size_t min_count = kMinNeighbours)
{
  double shift = 0.0, sum = 0.0, sum2 = 0.0;
  count = 0;
  for (IndexIterator it = begin; it != end; ++it) {
    const double k = curvature_of (*it);
    if (!std::isfinite (k))
      continue;
    if (count == 0)
      shift = k;
    const double d = k - shift;
    sum += d;
    sum2 += d * d;
    ++count;
  }
  if (count < min_count || count == 0)
    return std::numeric_limits<double>::quiet_NaN();
  const double mean = sum / static_cast<double> (count);
  return std::max (0.0, sum2 / static_cast<double> (count) - mean * mean);
}
} // namespace pcl_ext
