/*
 * pcl_ext: CovarianceFeatureEstimation implementation.
 */
#pragma once

#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/features/local_variance.h>

#include <limits>

template <typename PointInT, typename PointOutT>
void
pcl_ext::CovarianceFeatureEstimation<PointInT, PointOutT>::setInvalid (PointOutT& out)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  out.normal_x = out.normal_y = out.normal_z = nan;
  out.lambda0 = out.lambda1 = out.lambda2 = nan;
  out.surface_variance = out.linearity = out.planarity = out.scattering = nan;
  out.omnivariance = out.anisotropy = out.eigenentropy = out.verticality = nan;
}

template <typename PointInT, typename PointOutT>
bool
pcl_ext::CovarianceFeatureEstimation<PointInT, PointOutT>::computePoint (
    std::size_t row, PointOutT& out) const
{
  const auto nn = (*nb_)[row];
  LocalCovariance local;
  if (!computeNeighbourhoodCovariance (*input_, nn.begin(), nn.end(), local)) {
    setInvalid (out);
    return false;
  }
  Eigen::Vector3d normal = local.eigen.normal();
  const PointInT& p = (*input_)[(*indices_)[row]];
  const Eigen::Vector3d to_view (vpx_ - p.x, vpy_ - p.y, vpz_ - p.z);
  if (normal.dot (to_view) < 0.0)
    normal = -normal;
  const EigenFeatures f = computeEigenFeatures (local.eigen.values, normal);
  out.normal_x = static_cast<float> (normal.x());
  out.normal_y = static_cast<float> (normal.y());
  out.normal_z = static_cast<float> (normal.z());
  out.lambda0 = static_cast<float> (local.eigen.values[0]);
  out.lambda1 = static_cast<float> (local.eigen.values[1]);
  out.lambda2 = static_cast<float> (local.eigen.values[2]);
  out.surface_variance = static_cast<float> (f.surface_variance);
  out.linearity = static_cast<float> (f.linearity);
  out.planarity = static_cast<float> (f.planarity);
  out.scattering = static_cast<float> (f.scattering);
  out.omnivariance = static_cast<float> (f.omnivariance);
  out.anisotropy = static_cast<float> (f.anisotropy);
  out.eigenentropy = static_cast<float> (f.eigenentropy);
  out.verticality = static_cast<float> (f.verticality);
  return true;
}

template <typename PointInT, typename PointOutT>
void
pcl_ext::CovarianceFeatureEstimation<PointInT, PointOutT>::computeFeature (
    PointCloudOut& output)
{
  output.is_dense = this->computeRows (
      output,
      256,
      [this] (std::size_t r, PointOutT& out) { return computePoint (r, out); },
      &setInvalid);
}

#define PCL_EXT_INSTANTIATE_CovarianceFeatureEstimation(T)                             \
  template class pcl_ext::CovarianceFeatureEstimation<T, pcl_ext::CovarianceFeatures>;
