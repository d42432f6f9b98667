/*
 * pcl_ext: covariance features of local neighbourhoods (Belton & Lichti 2006,
 * section 2.1).
 */
#pragma once

#include <pcl_ext/features/neighbourhood_feature.h>
#include <pcl_ext/point_types.h>

#include <pcl/features/feature.h>

namespace pcl_ext {
/** \brief Eigenvalues, normal, surface variance and eigen features of every point's
 * neighbourhood (Belton & Lichti 2006, section 2.1, eq. 1-4).
 *
 * Per point: the population covariance of its neighbourhood (eq. 1-2, in double around
 * a local centre), its ascending eigenvalues l0 <= l1 <= l2, the normal (eigenvector of
 * l0, flipped towards the viewpoint as pcl::NormalEstimation does), the surface
 * variance l0 / (l0 + l1 + l2) (eq. 4, the paper's curvature kappa) and the other eigen
 * features of pcl_ext::computeEigenFeatures. The output type is
 * pcl_ext::CovarianceFeatures (or any type with the same fields).
 *
 * Neighbourhoods: k nearest (setKSearch, the paper's k = 50) or radius
 * (setRadiusSearch), or shared ones through setNeighbourhoods(). Points without a
 * tangent plane (fewer than 3 finite neighbours, all neighbours coincident, or
 * collinear: l1 <= 1e-8 l2) and non-finite points get NaN in every field and make the
 * output not dense.
 *
 * Departures from the text: the covariance is divided by n (the paper's eq. 2;
 * section 2.1 notes the least-squares form without the division, which changes no
 * ratio).
 */
template <typename PointInT, typename PointOutT = pcl_ext::CovarianceFeatures>
class CovarianceFeatureEstimation
: public NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT> {
public:
  using Ptr = pcl::shared_ptr<CovarianceFeatureEstimation<PointInT, PointOutT>>;
  using ConstPtr =
      pcl::shared_ptr<const CovarianceFeatureEstimation<PointInT, PointOutT>>;
  using PointCloudOut = pcl::PointCloud<PointOutT>;

  CovarianceFeatureEstimation() { this->feature_name_ = "CovarianceFeatureEstimation"; }

  /** \brief Viewpoint the normals are flipped towards. Default (0, 0, 0), the scanner
   * origin of a single scan; any finite point. */
  void
  setViewPoint (float vpx, float vpy, float vpz)
  {
    vpx_ = vpx;
    vpy_ = vpy;
    vpz_ = vpz;
  }

  void
  getViewPoint (float& vpx, float& vpy, float& vpz) const
  {
    vpx = vpx_;
    vpy = vpy_;
    vpz = vpz_;
  }

protected:
  using NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT>::input_;
  using NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT>::indices_;
  using NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT>::nb_;

  void
  computeFeature (PointCloudOut& output) override;

  /** \brief One point; false (NaN written) without a tangent plane. */
  bool
  computePoint (std::size_t row, PointOutT& out) const;

  /** \brief NaN in every field. */
  static void
  setInvalid (PointOutT& out);

  float vpx_ = 0.f, vpy_ = 0.f, vpz_ = 0.f;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/features/impl/covariance_features.hpp>
#endif
