/*
 * pcl_ext: the covariance kernel shared by every feature and segmenter.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include <Eigen/Core>

#include <cstddef>

namespace pcl_ext {
/** \brief Ascending eigenvalues and matching unit eigenvectors (columns) of a 3x3
 * covariance. */
struct EigenDecomposition {
  Eigen::Vector3d values = Eigen::Vector3d::Zero(); ///< l0 <= l1 <= l2
  Eigen::Matrix3d vectors =
      Eigen::Matrix3d::Identity(); ///< column i belongs to values(i)

  /** \brief The surface normal: the eigenvector of the smallest eigenvalue. */
  Eigen::Vector3d
  normal () const
  {
    return vectors.col (0);
  }
};

/** \brief The standard eigen features of a neighbourhood (Weinmann et al. 2015 and
 * Belton & Lichti 2006 eq. 4), from ascending eigenvalues l0 <= l1 <= l2 and the
 * normal.
 *
 * With e_i = l_i / (l0 + l1 + l2):
 * - surface_variance = l0 / (l0 + l1 + l2)  (Belton & Lichti eq. 4, "change of
 * curvature")
 * - linearity = (l2 - l1) / l2, planarity = (l1 - l0) / l2, scattering = l0 / l2
 * - omnivariance = cbrt(e0 e1 e2), anisotropy = (l2 - l0) / l2
 * - eigenentropy = -sum e_i ln e_i (0 ln 0 taken as 0)
 * - verticality = 1 - |n_z| (0 on a horizontal surface, 1 on a vertical one)
 */
struct EigenFeatures {
  double surface_variance;
  double linearity;
  double planarity;
  double scattering;
  double omnivariance;
  double anisotropy;
  double eigenentropy;
  double verticality;
};

/** \brief Running sums of points around a local centre (the first point added), from
 * which a covariance and centroid are formed in double without a second pass: for
 * points taken one at a time, for instance while they are being assigned to one of
 * several groups. computeLocalCovariance is these sums over an index range.
 */
class CovarianceSums {
public:
  /** \brief Add a finite point, in the cloud's coordinates. */
  void
  add (const Eigen::Vector3d& point)
  {
    if (n_ == 0)
      centre_ = point;
    const Eigen::Vector3d p = point - centre_;
    sum_ += p;
    xx_ += p.x() * p.x();
    xy_ += p.x() * p.y();
    xz_ += p.x() * p.z();
    yy_ += p.y() * p.y();
    yz_ += p.y() * p.z();
    zz_ += p.z() * p.z();
    ++n_;
  }

  /** \brief Add the sums of other points (another part of a cloud), moved to this
   * centre: the same covariance as had their points been added here. */
  void
  add (const CovarianceSums& other);

  /** \brief The number of points added. */
  std::size_t
  size () const
  {
    return n_;
  }

  /** \brief The points' population covariance (divided by n) and their mean, in the
   * cloud's coordinates. \return size(); 0 leaves the outputs unchanged */
  std::size_t
  finish (Eigen::Matrix3d& covariance, Eigen::Vector3d& centroid) const;

private:
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  double xx_ = 0, xy_ = 0, xz_ = 0, yy_ = 0, yz_ = 0, zz_ = 0;
  std::size_t n_ = 0;
};

/** \brief The sums of the finite points of \a cloud[\a begin .. \a end). */
template <typename PointT, typename IndexIterator>
CovarianceSums
sumFinitePoints (const pcl::PointCloud<PointT>& cloud,
                 IndexIterator begin,
                 IndexIterator end);

/** \brief Covariance and centroid of a neighbourhood, accumulated in double around a
 * local centre (the first finite point), so that coordinates such as x = 6,000,000 m
 * lose nothing.
 *
 * \param[in] cloud the points
 * \param[in] begin, end a range of point indices into \a cloud
 * \param[out] covariance the population covariance (divided by n)
 * \param[out] centroid the mean, in the cloud's coordinates
 * \return the number of finite points used; 0 leaves the outputs unchanged
 */
template <typename PointT, typename IndexIterator>
std::size_t
computeLocalCovariance (const pcl::PointCloud<PointT>& cloud,
                        IndexIterator begin,
                        IndexIterator end,
                        Eigen::Matrix3d& covariance,
                        Eigen::Vector3d& centroid);

/** \brief Same, over a whole index container. */
template <typename PointT, typename IndexContainer>
inline std::size_t
computeLocalCovariance (const pcl::PointCloud<PointT>& cloud,
                        const IndexContainer& indices,
                        Eigen::Matrix3d& covariance,
                        Eigen::Vector3d& centroid)
{
  return computeLocalCovariance (
      cloud, std::begin (indices), std::end (indices), covariance, centroid);
}

/** \brief Eigen decomposition of a symmetric 3x3 covariance, eigenvalues ascending.
 *
 * Tiny negative eigenvalues from round-off are clamped to 0. Eigenvector signs are as
 * the solver returns them: orienting the normal is the caller's business (for instance
 * pcl::flipNormalTowardsViewpoint).
 * \return false when the matrix is not finite
 */
bool
computeEigenDecomposition (const Eigen::Matrix3d& covariance,
                           EigenDecomposition& result);

/** \brief Belton & Lichti eq. 4: l0 / (l0 + l1 + l2); NaN when the sum is not positive.
 */
double
surfaceVariance (const Eigen::Vector3d& ascending_values);

/** \brief All eigen features (see EigenFeatures); every field NaN when the eigenvalues
 * sum to zero (all points coincide) or are not finite. */
EigenFeatures
computeEigenFeatures (const Eigen::Vector3d& ascending_values,
                      const Eigen::Vector3d& normal);

/** \brief True when every eigen feature is finite. */
bool
isFinite (const EigenFeatures& features);

/** \brief The normal of a small patch, the points [begin, end) of \a cloud (a point's
 * nearest few), and its surface variance (eq. 4); optionally the smallest eigenvalue of
 * its covariance, the mean squared distance of its points from their plane.
 * \return false, the outputs unchanged, with fewer than 3 finite points or no spread */
template <typename PointT, typename IndexIterator>
bool
fitPatchNormal (const pcl::PointCloud<PointT>& cloud,
                IndexIterator begin,
                IndexIterator end,
                Eigen::Vector3f& normal,
                float& curvature,
                float* smallest_variance = nullptr);
} // namespace pcl_ext

#include <pcl_ext/common/impl/covariance.hpp>
