/*
 * pcl_ext: template part of AdaptiveSupervoxelSegmentation.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>

#include <pcl/console/print.h>
#include <pcl/point_types.h>

#include <limits>

namespace pcl_ext {
namespace detail {
/** Copy the indexed points as PointXYZ (others NaN) and their normalised RGB, when
 * PointT has colour: the super-voxel code is not templated on the point type. */
template <typename PointT>
void
copyXyzAndColour (const pcl::PointCloud<PointT>& in,
                  const pcl::Indices& indices,
                  pcl::PointCloud<pcl::PointXYZ>& xyz,
                  std::vector<Eigen::Vector3f>& colours)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  xyz.assign (in.size(), pcl::PointXYZ (nan, nan, nan));
  for (const auto i : indices)
    xyz[i].getVector3fMap() = in[i].getVector3fMap();
  colours.clear();
  if constexpr (pcl::traits::has_color_v<PointT>) {
    colours.resize (in.size(), Eigen::Vector3f::Constant (1.f / 3.f));
    for (const auto i : indices) {
      const auto& p = in[i];
      const float sum = static_cast<float> (p.r) + p.g + p.b;
      if (sum > 0.f)
        colours[i] = Eigen::Vector3f (p.r / sum, p.g / sum, p.b / sum);
    }
  }
}
} // namespace detail
} // namespace pcl_ext

template <typename PointT>
void
pcl_ext::AdaptiveSupervoxelSegmentation<PointT>::segment (SupervoxelSet& supervoxels)
{
  supervoxels.clear();
  if (!input_ || input_->empty()) {
    PCL_ERROR (
        "[pcl_ext::AdaptiveSupervoxelSegmentation::segment] Empty input cloud.\n");
    return;
  }
  if (!initCompute())
    return;
  if (!indicesInRange (*indices_,
                       input_->size(),
                       "[pcl_ext::AdaptiveSupervoxelSegmentation::segment]")) {
    deinitCompute();
    return;
  }
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::vector<Eigen::Vector3f> colours;
  detail::copyXyzAndColour (*input_, *indices_, *xyz, colours);
  computeAdaptiveSupervoxels (xyz, colours, parameters_, supervoxels);
  deinitCompute();
}

template <typename PointT>
void
pcl_ext::AdaptiveSupervoxelSegmentation<PointT>::extract (
    std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  SupervoxelSet set;
  segment (set);
  clusters.resize (set.size());
  for (std::size_t v = 0; v < set.size(); ++v) {
    clusters[v].header = input_->header;
    clusters[v].indices = set.supervoxels[v].members;
  }
}

#define PCL_EXT_INSTANTIATE_AdaptiveSupervoxelSegmentation(T)                          \
  template class pcl_ext::AdaptiveSupervoxelSegmentation<T>;
