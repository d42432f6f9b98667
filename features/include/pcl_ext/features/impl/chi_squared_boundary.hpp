/*
 * pcl_ext: ChiSquaredBoundaryEstimation implementation.
 */
#pragma once

#include <pcl_ext/features/chi_squared_boundary.h>
#include <pcl_ext/features/local_variance.h>

#include <cmath>

template <typename PointInT, typename PointOutT>
bool
pcl_ext::ChiSquaredBoundaryEstimation<PointInT, PointOutT>::checkInputs()
{
  if (!std::isfinite (confidenceQuantile())) {
    PCL_ERROR (
        "[pcl_ext::%s::compute] confidence = %g; it must lie strictly between 0 and "
        "1.\n",
        this->feature_name_.c_str(),
        confidence_);
    return false;
  }
  if (!(noise_sigma_ >= 0.0) || !std::isfinite (noise_sigma_)) {
    PCL_ERROR (
        "[pcl_ext::%s::compute] noise standard deviation = %g; it must be finite and "
        ">= 0.\n",
        this->feature_name_.c_str(),
        noise_sigma_);
    return false;
  }
  return true;
}

template <typename PointInT, typename PointOutT>
bool
pcl_ext::ChiSquaredBoundaryEstimation<PointInT, PointOutT>::computePoint (
    std::size_t row, double quantile, PointOutT& out) const
{
  const auto nn = (*nb_)[row];
  LocalCovariance local;
  out.boundary_point = 0;
  if (!computeNeighbourhoodCovariance (*input_, nn.begin(), nn.end(), local))
    return false;
  const PointInT& p = (*input_)[(*indices_)[row]];
  const double statistic = centroidOffsetStatistic (Eigen::Vector3d (p.x, p.y, p.z),
                                                    local,
                                                    scale_by_size_,
                                                    noise_sigma_ * noise_sigma_);
  out.boundary_point = statistic > quantile ? 1 : 0;
  return true;
}

template <typename PointInT, typename PointOutT>
void
pcl_ext::ChiSquaredBoundaryEstimation<PointInT, PointOutT>::computeFeature (
    PointCloudOut& output)
{
  const double quantile = confidenceQuantile();
  output.is_dense = this->computeRows (
      output,
      256,
      [this, quantile] (std::size_t r, PointOutT& out) {
        return computePoint (r, quantile, out);
      },
      [] (PointOutT& out) { out.boundary_point = 0; });
}

#define PCL_EXT_INSTANTIATE_ChiSquaredBoundaryEstimation(T)                            \
  template class pcl_ext::ChiSquaredBoundaryEstimation<T, pcl::Boundary>;
