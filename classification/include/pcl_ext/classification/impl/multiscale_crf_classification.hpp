/*
 * pcl_ext: template part of MultiscaleCrfClassification.
 */
#pragma once

#include <pcl_ext/classification/multiscale_crf_classification.h>
#include <pcl_ext/common/indices.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>

template <typename PointT>
pcl_ext::CrfInput
pcl_ext::MultiscaleCrfClassification<PointT>::makeInput (
    const pcl::PointCloud<PointT>& cloud, const pcl::Indices* indices)
{
  CrfInput in;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  xyz->assign (cloud.size(), pcl::PointXYZ (nan, nan, nan));
  auto copy = [&] (std::size_t i) {
    (*xyz)[i].getVector3fMap() = cloud[i].getVector3fMap();
  };
  if (indices)
    for (const auto i : *indices)
      copy (static_cast<std::size_t> (i));
  else
    for (std::size_t i = 0; i < cloud.size(); ++i)
      copy (i);
  in.xyz = xyz;
  if constexpr (pcl::traits::has_color_v<PointT>) {
    in.colours.assign (cloud.size(), Eigen::Vector3f::Constant (1.f / 3.f));
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const float sum = static_cast<float> (cloud[i].r) + cloud[i].g + cloud[i].b;
      if (sum > 0.f)
        in.colours[i] =
            Eigen::Vector3f (cloud[i].r / sum, cloud[i].g / sum, cloud[i].b / sum);
    }
  }
  if constexpr (pcl::traits::has_intensity_v<PointT>) {
    in.intensity.resize (cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      in.intensity[i] = std::isfinite (cloud[i].intensity) ? cloud[i].intensity : 0.f;
  }
  return in;
}

template <typename PointT>
bool
pcl_ext::MultiscaleCrfClassification<PointT>::train (
    const std::vector<PointCloudConstPtr>& clouds,
    const std::vector<std::vector<std::uint32_t>>& labels)
{
  std::vector<CrfInput> inputs;
  for (const auto& c : clouds) {
    if (!c || c->empty()) {
      PCL_ERROR (
          "[pcl_ext::MultiscaleCrfClassification::train] Empty training cloud.\n");
      return false;
    }
    inputs.push_back (makeInput (*c, nullptr));
  }
  return model_.train (inputs, labels);
}

template <typename PointT>
void
pcl_ext::MultiscaleCrfClassification<PointT>::classify (
    pcl::PointCloud<pcl::Label>& labels)
{
  labels.clear();
  probabilities_.resize (0, 0);
  if (!input_ || input_->empty()) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfClassification::classify] Empty input cloud.\n");
    return;
  }
  if (!initCompute())
    return;
  if (!indicesInRange (*indices_,
                       input_->size(),
                       "[pcl_ext::MultiscaleCrfClassification::classify]")) {
    deinitCompute();
    return;
  }
  std::vector<std::uint32_t> all;
  Eigen::MatrixXf probabilities;
  if (model_.classify (makeInput (*input_, indices_.get()), all, probabilities)) {
    labels.resize (indices_->size());
    probabilities_.resize (static_cast<Eigen::Index> (indices_->size()),
                           probabilities.cols());
    for (std::size_t r = 0; r < indices_->size(); ++r) {
      labels[r].label = all[(*indices_)[r]];
      probabilities_.row (static_cast<Eigen::Index> (r)) =
          probabilities.row ((*indices_)[r]);
    }
    labels.header = input_->header;
  }
  deinitCompute();
}

template <typename PointT>
void
pcl_ext::MultiscaleCrfClassification<PointT>::extract (
    std::vector<pcl::PointIndices>& classes)
{
  classes.clear();
  pcl::PointCloud<pcl::Label> labels;
  classify (labels);
  if (labels.empty())
    return;
  // A label not among the model's classes (none is expected) leaves its point out.
  const auto& ids = model_.getClassLabels();
  groupByClass (
      labels,
      indices_.get(),
      ids.size(),
      [&ids] (std::uint32_t label) {
        return static_cast<std::size_t> (std::find (ids.begin(), ids.end(), label) -
                                         ids.begin());
      },
      input_->header,
      classes);
}

#define PCL_EXT_INSTANTIATE_MultiscaleCrfClassification(T)                             \
  template class pcl_ext::MultiscaleCrfClassification<T>;
