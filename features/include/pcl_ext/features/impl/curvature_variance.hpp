/*
 * pcl_ext: CurvatureVarianceEstimation implementation.
 */
#pragma once

#include <pcl_ext/features/curvature_variance.h>
#include <pcl_ext/features/local_variance.h>

#include <pcl/common/point_tests.h>

#include <limits>

template <typename PointInT, typename PointNT, typename PointOutT> bool
pcl_ext::CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>::checkInputs ()
{
  if (!normals_)
  {
    PCL_ERROR ("[pcl_ext::%s::compute] No normals (setInputNormals).\n",
               this->feature_name_.c_str ());
    return false;
  }
  if (normals_->size () != input_->size ())
  {
    PCL_ERROR ("[pcl_ext::%s::compute] %zu normals for %zu points; one per input point is "
               "needed.\n", this->feature_name_.c_str (), normals_->size (), input_->size ());
    return false;
  }
  return true;
}

template <typename PointInT, typename PointNT, typename PointOutT> bool
pcl_ext::CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>::computePoint (
    std::size_t row, PointOutT& out) const
{
  const auto nn = (*nb_)[row];
  const auto& normals = *normals_;
  std::size_t count = 0;
  const double variance = curvatureVariance (
      nn.begin (), nn.end (),
      [&normals] (pcl::index_t j) { return detail::curvatureOf (normals[j]); }, count);
  out.curvature_variance = static_cast<float> (variance);
  return std::isfinite (variance);
}

template <typename PointInT, typename PointNT, typename PointOutT> void
pcl_ext::CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>::computeFeature (
    PointCloudOut& output)
{
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size ());
  bool dense = true;
  if (input_->is_dense)
  {
#pragma omp parallel for num_threads(this->threadCount ()) schedule(dynamic, 1024) \
    reduction(&& : dense) default(none) shared(output, rows)
    for (std::ptrdiff_t r = 0; r < rows; ++r)
      dense = computePoint (static_cast<std::size_t> (r), output[r]) && dense;
  }
  else
  {
#pragma omp parallel for num_threads(this->threadCount ()) schedule(dynamic, 1024) \
    reduction(&& : dense) default(none) shared(output, rows)
    for (std::ptrdiff_t r = 0; r < rows; ++r)
    {
      if (!pcl::isFinite ((*input_)[(*indices_)[r]]))
      {
        output[r].curvature_variance = std::numeric_limits<float>::quiet_NaN ();
        dense = false;
        continue;
      }
      dense = computePoint (static_cast<std::size_t> (r), output[r]) && dense;
    }
  }
  output.is_dense = dense;
}

#define PCL_EXT_INSTANTIATE_CurvatureVarianceEstimation(T)                                \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl::Normal>;                    \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl::PointNormal>;               \
  template class pcl_ext::CurvatureVarianceEstimation<T, pcl_ext::CovarianceFeatures>;
