/*
 * pcl_ext: colours for segment numbers, and a cloud coloured by segment, as the
 * segmenters' getColoredCloud() give it.
 */
#pragma once

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace pcl_ext {
/** \brief The colour of segment number \a segment: hues a golden-ratio step apart, so
 * that neighbouring numbers get distinct colours and a segment keeps its colour from
 * run to run (pcl::RegionGrowing draws random ones). */
inline void
segmentColour (std::size_t segment, std::uint8_t rgb[3])
{
  const double h =
      std::fmod (0.11 + 0.618033988749895 * static_cast<double> (segment), 1.0) * 6.0;
  const double v = segment % 2 ? 0.75 : 0.95, s = 0.85;
  const int sector = static_cast<int> (h) % 6;
  const double f = h - std::floor (h), lo = v * (1 - s), fall = v * (1 - s * f),
               rise = v * (1 - s * (1 - f));
  const double table[6][3] = {{v, rise, lo},
                              {fall, v, lo},
                              {lo, v, rise},
                              {lo, fall, v},
                              {rise, lo, v},
                              {v, lo, fall}};
  for (int i = 0; i < 3; ++i)
    rgb[i] = static_cast<std::uint8_t> (255 * table[sector][i]);
}

/** \brief The points of \a cloud coloured by segment (segmentColour), white where in
 * none, with the cloud's width, height and is_dense: what
 * pcl::RegionGrowing::getColoredCloud() gives. Empty when the cloud or the segment list
 * is empty. */
template <typename PointT>
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
colourBySegment (const pcl::PointCloud<PointT>& cloud,
                 const std::vector<pcl::PointIndices>& segments)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr coloured (
      new pcl::PointCloud<pcl::PointXYZRGB>);
  if (cloud.empty() || segments.empty())
    return coloured;
  coloured->resize (cloud.size());
  coloured->width = cloud.width;
  coloured->height = cloud.height;
  coloured->is_dense = cloud.is_dense;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    auto& q = (*coloured)[i];
    q.x = cloud[i].x;
    q.y = cloud[i].y;
    q.z = cloud[i].z;
    q.r = q.g = q.b = 255;
  }
  for (std::size_t c = 0; c < segments.size(); ++c) {
    std::uint8_t rgb[3];
    segmentColour (c, rgb);
    for (const auto index : segments[c].indices) {
      auto& q = (*coloured)[index];
      q.r = rgb[0];
      q.g = rgb[1];
      q.b = rgb[2];
    }
  }
  return coloured;
}
} // namespace pcl_ext
