/*
 * pcl_ext: CurvatureVarianceEstimation implementation.
 */
#pragma once

#include <pcl_ext/features/curvature_variance.h>
#include <pcl_ext/features/local_variance.h>

#include <limits>

template <typename PointInT, typename PointNT, typename PointOutT>
bool
pcl_ext::CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>::computePoint (
    std::size_t row, PointOutT& out) const
{
  const auto nn = (*nb_)[row];
  const auto& normals = *normals_;
  std::size_t count = 0;
  const double variance = curvatureVariance (
      nn.begin(),
      nn.end(),
      [&normals] (pcl::index_t j) { return detail::curvatureOf (normals[j]); },
      count);
  out.curvature_variance = static_cast<float> (variance);
  return std::isfinite (variance);
}

template <typename PointInT, typename PointNT, typename PointOutT>
void
pcl_ext::CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>::computeFeature (
    PointCloudOut& output)
{
  output.is_dense = this->computeRows (
      output,
      1024,
      [this] (std::size_t r, PointOutT& out) { return computePoint (r, out); },
      [] (PointOutT& out) {
        out.curvature_variance = std::numeric_limits<float>::quiet_NaN();
      });
}

#define PCL_EXT_INSTANTIATE_CurvatureVarianceEstimation(T)                             \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl::Normal>;                 \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl::PointNormal>;            \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl_ext::CovarianceFeatures>;
