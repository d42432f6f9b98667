/*
 * pcl_ext: variance of curvature (Belton & Lichti 2006, section 2.2, eq. 5).
 */
#pragma once

#include <pcl_ext/features/neighbourhood_feature.h>
#include <pcl_ext/point_types.h>

#include <pcl/features/feature.h>
#include <pcl/type_traits.h>

#include <type_traits>

namespace pcl_ext {
namespace detail {
/** \brief The curvature kappa of a normal-like point: its \c curvature field
 * (pcl::Normal, pcl::PointNormal, ...), else its \c surface_variance
 * (pcl_ext::CovarianceFeatures). */
template <typename PointNT>
inline float
curvatureOf (const PointNT& n)
{
  if constexpr (pcl::traits::has_field<PointNT, pcl::fields::curvature>::value)
    return n.curvature;
  else
    return n.surface_variance;
}
} // namespace detail

/** \brief Variance of curvature over each point's neighbourhood (Belton & Lichti 2006,
 * section 2.2, eq. 5): var(kappa) = (1/k) sum (kappa_i - mean kappa)^2 over the k
 * neighbours (the index point included), where kappa is the surface variance of eq. 4.
 *
 * The curvatures come from the normals cloud given with setInputNormals(), one per
 * input point, as in pcl::FeatureFromNormals: its \c curvature field
 * (pcl::NormalEstimation's curvature is eq. 4) or, for pcl_ext::CovarianceFeatures, its
 * \c surface_variance. Only finite curvatures count; a point with fewer than 3 of them,
 * or that is not finite itself, gets NaN and the output is not dense.
 *
 * Near zero on smooth surfaces, plane or curved (a pipe's curvature is high but
 * constant); large near creases, where the neighbourhood mixes low and high curvature.
 * The paper thresholds it at 1e-4 (pcl_ext::LocalVarianceClassification does).
 *
 * Neighbourhoods: setKSearch (paper: the same k as for the curvature, 50),
 * setRadiusSearch, or shared ones (setNeighbourhoods). Output:
 * pcl_ext::CurvatureVariance.
 */
template <typename PointInT,
          typename PointNT,
          typename PointOutT = pcl_ext::CurvatureVariance>
class CurvatureVarianceEstimation
: public NeighbourhoodFeatureFromNormals<PointInT, PointNT, PointOutT> {
  using Base = NeighbourhoodFeatureFromNormals<PointInT, PointNT, PointOutT>;

public:
  using Ptr =
      pcl::shared_ptr<CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>>;
  using ConstPtr =
      pcl::shared_ptr<const CurvatureVarianceEstimation<PointInT, PointNT, PointOutT>>;
  using PointCloudOut = pcl::PointCloud<PointOutT>;

  CurvatureVarianceEstimation() { this->feature_name_ = "CurvatureVarianceEstimation"; }

protected:
  using Base::indices_;
  using Base::input_;
  using Base::nb_;
  using Base::normals_;

  void
  computeFeature (PointCloudOut& output) override;

  /** \brief One point; false (NaN written) when fewer than 3 finite curvatures. */
  bool
  computePoint (std::size_t row, PointOutT& out) const;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/features/impl/curvature_variance.hpp>
#endif
