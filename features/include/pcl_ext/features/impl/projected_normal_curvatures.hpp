/*
 * pcl_ext: ProjectedNormalCurvaturesEstimation implementation.
 */
#pragma once

#include <pcl_ext/features/local_variance.h>
#include <pcl_ext/features/projected_normal_curvatures.h>

#include <limits>

template <typename PointInT, typename PointNT, typename PointOutT>
void
pcl_ext::ProjectedNormalCurvaturesEstimation<PointInT, PointNT, PointOutT>::setInvalid (
    PointOutT& out)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  out.principal_curvature_x = out.principal_curvature_y = out.principal_curvature_z =
      nan;
  out.pc1 = out.pc2 = nan;
}

template <typename PointInT, typename PointNT, typename PointOutT>
bool
pcl_ext::ProjectedNormalCurvaturesEstimation<PointInT, PointNT, PointOutT>::
    computePoint (std::size_t row, PointOutT& out) const
{
  const auto& normals = *normals_;
  const PointNT& own = normals[(*indices_)[row]];
  const Eigen::Vector3d n (own.normal_x, own.normal_y, own.normal_z);
  if (!n.allFinite() || !(n.squaredNorm() > 0.0)) {
    setInvalid (out);
    return false;
  }
  ProjectedNormalAccumulator accumulator (n);
  for (const auto j : (*nb_)[row])
    accumulator.add (Eigen::Vector3d (
        normals[j].normal_x, normals[j].normal_y, normals[j].normal_z));
  ProjectedNormalDirections directions;
  if (accumulator.count() < kMinNeighbours || !accumulator.compute (directions)) {
    setInvalid (out);
    return false;
  }
  out.principal_curvature_x = static_cast<float> (directions.max_direction.x());
  out.principal_curvature_y = static_cast<float> (directions.max_direction.y());
  out.principal_curvature_z = static_cast<float> (directions.max_direction.z());
  out.pc1 = static_cast<float> (directions.max_change);
  out.pc2 = static_cast<float> (directions.min_change);
  return true;
}

template <typename PointInT, typename PointNT, typename PointOutT>
void
pcl_ext::ProjectedNormalCurvaturesEstimation<PointInT, PointNT, PointOutT>::
    computeFeature (PointCloudOut& output)
{
  output.is_dense = this->computeRows (
      output,
      256,
      [this] (std::size_t r, PointOutT& out) { return computePoint (r, out); },
      &setInvalid);
}

#define PCL_EXT_INSTANTIATE_ProjectedNormalCurvaturesEstimation(T)                     \
  template class pcl_ext::ProjectedNormalCurvaturesEstimation<T, pcl::Normal>;         \
  template class pcl_ext::ProjectedNormalCurvaturesEstimation<T, pcl::PointNormal>;    \
  template class pcl_ext::                                                             \
      ProjectedNormalCurvaturesEstimation<T, pcl_ext::CovarianceFeatures>;
