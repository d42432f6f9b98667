/*
 * pcl_ext: chi-squared centroid boundary test (Belton & Lichti 2006, section 2.3, eq.
 * 6-8).
 */
#pragma once

#include <pcl_ext/features/centroid_offset_test_options.h>
#include <pcl_ext/features/neighbourhood_feature.h>

#include <pcl/features/feature.h>
#include <pcl/point_types.h>

namespace pcl_ext {
/** \brief Boundary points by the position of each point relative to its neighbourhood's
 * centroid (Belton & Lichti 2006, section 2.3, eq. 6-8).
 *
 * The index point p is projected on the tangent plane of its neighbourhood:
 * u = e1 . (p - c), v = e2 . (p - c) (eq. 7-8), with c the centroid and e1, e2 the
 * eigenvectors of the two largest eigenvalues l1, l2. Near an open border the
 * neighbours lie on one side, so the centroid moves away from p; p is a boundary point
 * when n (u^2 / l1 + v^2 / l2) > chi2_2(confidence) (eq. 6 with n, see below). Output
 * compatible with pcl::BoundaryEstimation: pcl::Boundary, boundary_point 1 or 0.
 *
 * Unlike pcl::BoundaryEstimation (the largest angular gap between neighbours around the
 * normal), it needs no normals, only the covariance, so it costs one pass over each
 * neighbourhood, and it is not fooled by a single missing sector on irregular TLS
 * sampling.
 *
 * Departure from the printed eq. 6: the statistic is multiplied by the neighbourhood
 * size n (the covariance of the centroid is S / n, as in the confidence region for a
 * mean of Johnson & Wichern that the paper cites). Without it, a point exactly on a
 * straight border of a uniformly sampled plane scores 2.57, below chi2_2(0.95) = 5.991,
 * so the test at the paper's confidence levels finds corners only.
 * setScaleByNeighbourhoodSize(false) gives the printed form. See
 * pcl_ext::centroidOffsetStatistic.
 *
 * Points without a tangent plane (fewer than 3 neighbours, coincident or collinear
 * points) and non-finite points get boundary_point = 0 and make the output not dense.
 */
template <typename PointInT, typename PointOutT = pcl::Boundary>
class ChiSquaredBoundaryEstimation
: public NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT>,
  public CentroidOffsetTestOptions {
  using Base = NeighbourhoodFeature<pcl::Feature<PointInT, PointOutT>, PointInT>;

public:
  using Ptr = pcl::shared_ptr<ChiSquaredBoundaryEstimation<PointInT, PointOutT>>;
  using ConstPtr =
      pcl::shared_ptr<const ChiSquaredBoundaryEstimation<PointInT, PointOutT>>;
  using PointCloudOut = pcl::PointCloud<PointOutT>;

  ChiSquaredBoundaryEstimation()
  {
    this->feature_name_ = "ChiSquaredBoundaryEstimation";
  }

  /** \brief Range noise standard deviation sigma of the scanner, in the cloud's units.
   * Default 0: eq. 6 as above. Valid: finite, >= 0. With it, u^2 and v^2 are compared
   * with l1 / n + sigma^2 and l2 / n + sigma^2 (see pcl_ext::centroidOffsetStatistic):
   * the index point's own noise displaces it from the centroid by up to sigma, which
   * eq. 6 alone can read as a border where k neighbours span only a few sigma (near a
   * scanner). It only widens the region: it removes boundary points, never adds one.
   * The same test as LocalVarianceClassification::setNoiseStandardDeviation. */
  void
  setNoiseStandardDeviation (double sigma)
  {
    noise_sigma_ = sigma;
  }

  double
  getNoiseStandardDeviation () const
  {
    return noise_sigma_;
  }

protected:
  using Base::indices_;
  using Base::input_;
  using Base::nb_;

  bool
  checkInputs () override;

  void
  computeFeature (PointCloudOut& output) override;

  /** \brief One point; false when it has no tangent plane (boundary_point 0 written).
   */
  bool
  computePoint (std::size_t row, double quantile, PointOutT& out) const;

  double noise_sigma_ = 0.0;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/features/impl/chi_squared_boundary.hpp>
#endif
