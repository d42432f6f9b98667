/*
 * pcl_ext: non-template part of the covariance kernel.
 */
#include <pcl_ext/common/covariance.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

void
pcl_ext::CovarianceSums::add (const CovarianceSums& other)
{
  if (other.n_ == 0)
    return;
  if (n_ == 0) {
    *this = other;
    return;
  }
  // With q - c = (q - c') + t, t = c' - c: sum (q - c)(q - c)^T = S' + t s'^T + s' t^T
  // + m t t^T, s' and S' the other's first and second sums, m its count.
  const Eigen::Vector3d t = other.centre_ - centre_;
  const Eigen::Vector3d& s = other.sum_;
  const double m = static_cast<double> (other.n_);
  xx_ += other.xx_ + 2.0 * t.x() * s.x() + m * t.x() * t.x();
  xy_ += other.xy_ + t.x() * s.y() + s.x() * t.y() + m * t.x() * t.y();
  xz_ += other.xz_ + t.x() * s.z() + s.x() * t.z() + m * t.x() * t.z();
  yy_ += other.yy_ + 2.0 * t.y() * s.y() + m * t.y() * t.y();
  yz_ += other.yz_ + t.y() * s.z() + s.y() * t.z() + m * t.y() * t.z();
  zz_ += other.zz_ + 2.0 * t.z() * s.z() + m * t.z() * t.z();
  sum_ += s + m * t;
  n_ += other.n_;
}

std::size_t
pcl_ext::CovarianceSums::finish (Eigen::Matrix3d& covariance,
                                 Eigen::Vector3d& centroid) const
{
  if (n_ == 0)
    return 0;
  const double inv_n = 1.0 / static_cast<double> (n_);
  const Eigen::Vector3d mean = sum_ * inv_n;
  covariance (0, 0) = xx_ * inv_n - mean.x() * mean.x();
  covariance (0, 1) = xy_ * inv_n - mean.x() * mean.y();
  covariance (0, 2) = xz_ * inv_n - mean.x() * mean.z();
  covariance (1, 1) = yy_ * inv_n - mean.y() * mean.y();
  covariance (1, 2) = yz_ * inv_n - mean.y() * mean.z();
  covariance (2, 2) = zz_ * inv_n - mean.z() * mean.z();
  covariance (1, 0) = covariance (0, 1);
  covariance (2, 0) = covariance (0, 2);
  covariance (2, 1) = covariance (1, 2);
  centroid = centre_ + mean;
  return n_;
}

bool
pcl_ext::computeEigenDecomposition (const Eigen::Matrix3d& covariance,
                                    EigenDecomposition& result)
{
  if (!covariance.allFinite())
    return false;
  // The closed-form solver is exact enough in double for 3x3 covariances, and several
  // times faster than the iterative one; Eigen scales the matrix internally before
  // solving.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect (covariance);
  if (solver.info() != Eigen::Success)
    return false;
  result.values = solver.eigenvalues().cwiseMax (0.0);
  result.vectors = solver.eigenvectors();
  return result.values.allFinite() && result.vectors.allFinite();
}

double
pcl_ext::surfaceVariance (const Eigen::Vector3d& ascending_values)
{
  const double sum = ascending_values.sum();
  if (!(sum > 0.0) || !std::isfinite (sum))
    return std::numeric_limits<double>::quiet_NaN();
  return ascending_values[0] / sum;
}

pcl_ext::EigenFeatures
pcl_ext::computeEigenFeatures (const Eigen::Vector3d& ascending_values,
                               const Eigen::Vector3d& normal)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EigenFeatures f{nan, nan, nan, nan, nan, nan, nan, nan};
  const double l0 = ascending_values[0], l1 = ascending_values[1],
               l2 = ascending_values[2];
  const double sum = l0 + l1 + l2;
  if (!(sum > 0.0) || !std::isfinite (sum) || !(l2 > 0.0) || !normal.allFinite())
    return f;
  const double e0 = l0 / sum, e1 = l1 / sum, e2 = l2 / sum;
  const auto plogp = [] (double e) { return e > 0.0 ? e * std::log (e) : 0.0; };
  f.surface_variance = e0;
  f.linearity = (l2 - l1) / l2;
  f.planarity = (l1 - l0) / l2;
  f.scattering = l0 / l2;
  f.omnivariance = std::cbrt (e0 * e1 * e2);
  f.anisotropy = (l2 - l0) / l2;
  f.eigenentropy = -(plogp (e0) + plogp (e1) + plogp (e2));
  f.verticality = 1.0 - std::abs (normal.z() / normal.norm());
  return f;
}

bool
pcl_ext::isFinite (const EigenFeatures& f)
{
  return std::isfinite (f.surface_variance) && std::isfinite (f.linearity) &&
         std::isfinite (f.planarity) && std::isfinite (f.scattering) &&
         std::isfinite (f.omnivariance) && std::isfinite (f.anisotropy) &&
         std::isfinite (f.eigenentropy) && std::isfinite (f.verticality);
}
