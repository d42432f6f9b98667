/*
 * pcl_ext: Lim & Suter's saliency features (eq. 12) as a PCL-style estimator.
 */
#pragma once

#include <pcl_ext/features/saliency_features.h>

#include <pcl/pcl_base.h>

#include <string>
#include <vector>

namespace pcl_ext {
/** \brief Per-point or per-region features of Lim & Suter (CVPR workshops 2008,
 * section 4.1): the saliency features of eq. 12, the normal angle of eq. 10, height,
 * colour and intensity (see computeSaliencyFeatures for the exact definitions and where
 * pcl_ext departs).
 *
 * Each indexed point is described by the sphere of radius r around it: one radius for
 * all (setRadius) or one per index (setRadii, e.g. the super-voxel radii for
 * super-voxel features at their mid-points). Colour is used when the point type has rgb
 * and intensity when it has intensity, unless switched off. compute() fills one row per
 * index; getFeatureNames() names the columns.
 *
 * Not a pcl::Feature: that takes a fixed output point type, and the number of columns
 * here depends on the point type (colour, intensity) and on the feature scales, so
 * compute() fills an Eigen matrix, one row per index, with the column names beside it.
 *
 * Errors (PCL_ERROR, empty output): empty cloud, no finite point, a radius that is not
 * positive and finite, feature scales that are not positive, finite and ascending,
 * radii not matching the indices, an index out of range, a non-finite indexed point.
 */
template <typename PointT>
class SaliencyFeatureEstimation : public pcl::PCLBase<PointT> {
public:
  using Ptr = pcl::shared_ptr<SaliencyFeatureEstimation<PointT>>;
  using ConstPtr = pcl::shared_ptr<const SaliencyFeatureEstimation<PointT>>;

  /** \brief r, the radius of every region (m); > 0. Default 0 (unset); clears setRadii.
   */
  void
  setRadius (float r)
  {
    radius_ = r;
    radii_.clear();
  }

  float
  getRadius () const
  {
    return radius_;
  }

  /** \brief One r per index (m), each > 0; overrides setRadius. */
  void
  setRadii (const std::vector<float>& radii)
  {
    radii_ = radii;
  }

  const std::vector<float>&
  getRadii () const
  {
    return radii_;
  }

  /** \brief The scanner's up axis for the angle (eq. 10) and height. Default (0, 0, 1).
   * The text writes (0 1 0), a y-up frame. */
  void
  setUpAxis (const Eigen::Vector3f& up)
  {
    options_.up = up;
  }

  const Eigen::Vector3f&
  getUpAxis () const
  {
    return options_.up;
  }

  /** \brief Use colour and intensity when the point type has them. Default true for
   * both. */
  void
  setUseColour (bool use)
  {
    use_colour_ = use;
  }

  bool
  getUseColour () const
  {
    return use_colour_;
  }

  void
  setUseIntensity (bool use)
  {
    use_intensity_ = use;
  }

  bool
  getUseIntensity () const
  {
    return use_intensity_;
  }

  /** \brief Local ground grid: cell (m, default 1, > 0) and reach (cells, default 3, >=
   * 0). */
  void
  setGroundGrid (float cell, int reach)
  {
    options_.ground_cell = cell;
    options_.ground_reach = reach;
  }

  /** \brief How the local ground is found (see GroundEstimate). Default LowestInBlock.
   */
  void
  setGroundEstimate (GroundEstimate estimate)
  {
    options_.ground_estimate = estimate;
  }

  GroundEstimate
  getGroundEstimate () const
  {
    return options_.ground_estimate;
  }

  /** \brief Fixed radii (m, ascending, > 0) at which the multi-scale features are added
   * (see computeSaliencyFeatures; defaultFeatureScales() gives 0.5, 1, 2 m). Default
   * empty: the paper's single-scale set. */
  void
  setFeatureScales (const std::vector<float>& radii)
  {
    options_.scales = radii;
  }

  const std::vector<float>&
  getFeatureScales () const
  {
    return options_.scales;
  }

  /** \brief OpenMP threads. Default 0: all cores. Results do not depend on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }

  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

  /** \brief Column names of the last compute() (see saliencyFeatureNames). */
  const std::vector<std::string>&
  getFeatureNames () const
  {
    return names_;
  }

  /** \brief One row of features per index. */
  void
  compute (Eigen::MatrixXf& features);

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  float radius_ = 0.f;
  std::vector<float> radii_;
  bool use_colour_ = true;
  bool use_intensity_ = true;
  unsigned int threads_ = 0;
  SaliencyFeatureOptions options_;
  std::vector<std::string> names_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/features/impl/saliency_feature_estimation.hpp>
#endif
