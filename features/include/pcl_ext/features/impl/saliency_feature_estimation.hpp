/*
 * pcl_ext: template part of SaliencyFeatureEstimation.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/features/saliency_feature_estimation.h>

#include <pcl/console/print.h>
#include <pcl/common/point_tests.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>

namespace pcl_ext {
namespace detail {
/** xyz (non-finite points stay NaN and out of the tree), normalised colour and
 * intensity. */
template <typename PointT>
void
copyPointAttributes (const pcl::PointCloud<PointT>& in,
                     pcl::PointCloud<pcl::PointXYZ>& xyz,
                     std::vector<Eigen::Vector3f>* colours,
                     std::vector<float>* intensity)
{
  xyz.resize (in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    xyz[i].getVector3fMap() = in[i].getVector3fMap();
  if constexpr (pcl::traits::has_color_v<PointT>)
    if (colours) {
      colours->assign (in.size(), Eigen::Vector3f::Constant (1.f / 3.f));
      for (std::size_t i = 0; i < in.size(); ++i) {
        const float sum = static_cast<float> (in[i].r) + in[i].g + in[i].b;
        if (sum > 0.f)
          (*colours)[i] = Eigen::Vector3f (in[i].r / sum, in[i].g / sum, in[i].b / sum);
      }
    }
  if constexpr (pcl::traits::has_intensity_v<PointT>)
    if (intensity) {
      intensity->resize (in.size());
      for (std::size_t i = 0; i < in.size(); ++i)
        (*intensity)[i] = std::isfinite (in[i].intensity) ? in[i].intensity : 0.f;
    }
}
} // namespace detail
} // namespace pcl_ext

template <typename PointT>
void
pcl_ext::SaliencyFeatureEstimation<PointT>::compute (Eigen::MatrixXf& features)
{
  features.resize (0, 0);
  names_.clear();
  if (!input_ || input_->empty()) {
    PCL_ERROR ("[pcl_ext::SaliencyFeatureEstimation::compute] Empty input cloud.\n");
    return;
  }
  if (!initCompute())
    return;
  std::vector<float> radii = radii_;
  if (radii.empty())
    radii.assign (indices_->size(), radius_);
  bool ok = radii.size() == indices_->size();
  for (const float r : radii)
    ok = ok && r > 0.f && std::isfinite (r);
  if (!ok) {
    PCL_ERROR ("[pcl_ext::SaliencyFeatureEstimation::compute] Need one positive, "
               "finite radius "
               "per index (setRadius or setRadii).\n");
    deinitCompute();
    return;
  }
  if (!indicesInRange (
          *indices_, input_->size(), "[pcl_ext::SaliencyFeatureEstimation::compute]")) {
    deinitCompute();
    return;
  }
  pcl::PointCloud<pcl::PointXYZ> xyz;
  std::vector<Eigen::Vector3f> colours;
  std::vector<float> intensity;
  detail::copyPointAttributes (*input_, xyz, &colours, &intensity);
  SaliencyFeatureOptions options = options_;
  options.colour = use_colour_ && !colours.empty();
  options.intensity = use_intensity_ && !intensity.empty();
  std::vector<float> flat;
  std::vector<pcl::index_t> ids;
  for (std::size_t i = 0; i < xyz.size(); ++i)
    if (pcl::isFinite (xyz[i])) {
      flat.insert (flat.end(), {xyz[i].x, xyz[i].y, xyz[i].z});
      ids.push_back (static_cast<pcl::index_t> (i));
    }
  for (const auto i : *indices_)
    ok = ok && pcl::isFinite (xyz[i]);
  if (ids.empty() || !ok) {
    PCL_ERROR (
        "[pcl_ext::SaliencyFeatureEstimation::compute] No finite point, or an indexed "
        "point is not finite.\n");
    deinitCompute();
    return;
  }
  search::KdTree3f tree;
  tree.build (std::move (flat), std::move (ids));
  LocalGround ground;
  ground.build (xyz,
                options.up,
                options.ground_cell,
                options.ground_reach,
                options.ground_estimate);
  if (computeSaliencyFeatures (xyz,
                               tree,
                               colours,
                               intensity,
                               ground,
                               *indices_,
                               radii,
                               options,
                               features,
                               threads_))
    names_ = saliencyFeatureNames (options);
  deinitCompute();
}

#define PCL_EXT_INSTANTIATE_SaliencyFeatureEstimation(T)                               \
  template class pcl_ext::SaliencyFeatureEstimation<T>;
