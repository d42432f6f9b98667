/*
 * pcl_ext: the settings of Belton & Lichti's chi-squared centroid boundary test
 * (eq. 6).
 */
#pragma once

#include <pcl_ext/features/local_variance.h>

namespace pcl_ext {
/** \brief The settings of the chi-squared centroid boundary test (Belton & Lichti 2006,
 * eq. 6-8; see pcl_ext::centroidOffsetStatistic): its confidence level and whether the
 * statistic is scaled by the neighbourhood size, one set/get pair each.
 *
 * A mixin of the two classes that run the test, pcl_ext::ChiSquaredBoundaryEstimation
 * and pcl_ext::LocalVarianceClassification, so that it is set the same way in both.
 */
class CentroidOffsetTestOptions {
public:
  /** \brief Confidence level of the region around the centroid (the paper's alpha in
   * chi2_2(alpha), eq. 6). Default 0.95 (quantile 5.991); valid: 0 < confidence < 1.
   * Higher values find fewer boundary points. */
  void
  setConfidence (double confidence)
  {
    confidence_ = confidence;
  }

  double
  getConfidence () const
  {
    return confidence_;
  }

  /** \brief Multiply eq. 6 by the neighbourhood size n (the centroid's confidence
   * region). Default true; false gives the printed eq. 6 (see
   * pcl_ext::centroidOffsetStatistic). */
  void
  setScaleByNeighbourhoodSize (bool scale)
  {
    scale_by_size_ = scale;
  }

  bool
  getScaleByNeighbourhoodSize () const
  {
    return scale_by_size_;
  }

protected:
  /** \brief chi2_2(confidence), the statistic's threshold; NaN for a confidence
   * outside (0, 1). */
  double
  confidenceQuantile () const
  {
    return chiSquaredQuantile2 (confidence_);
  }

  double confidence_ = 0.95;
  bool scale_by_size_ = true;
};
} // namespace pcl_ext
