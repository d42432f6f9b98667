/*
 * pcl_ext: colouring clouds by label, class or scalar field.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief An 8-bit colour. */
struct Colour {
  std::uint8_t r, g, b;
};

/** \brief Scalar colour maps. */
enum class ColourMap {
  Viridis, ///< perceptually uniform, dark blue to yellow (default)
  Jet,     ///< blue - cyan - yellow - red
  Grey     ///< black to white
};

/** \brief Distinct colours per label: label L > 0 gets pcl_ext::segmentColour (L - 1),
 * the colour of segment L - 1 in the segmenters' getColoredCloud, so the same label
 * always gets the same colour in every picture; label 0 ("unsegmented" / "ignore") is
 * grey. */
std::vector<Colour>
colourByLabel (const std::vector<std::uint32_t>& labels);

/** \brief One line of a legend: what a colour means. */
struct LegendEntry {
  std::string name;
  Colour colour;
};

/** \brief The legend of colourByClass: surface, edge, boundary and unknown. */
std::vector<LegendEntry>
classLegend ();

/** \brief Fixed colours for pcl_ext::PointClass values, as in Belton & Lichti's
 * figures: surface blue, edge red, boundary green, unknown grey. */
std::vector<Colour>
colourByClass (const std::vector<std::uint32_t>& classes);

/** \brief Colour a scalar field. NaN values are dark grey. With \a min >= \a max the
 * range is taken from the 2nd and 98th percentiles of the finite values, so outliers do
 * not wash out the map. */
std::vector<Colour>
colourByScalar (const std::vector<float>& values,
                ColourMap map = ColourMap::Viridis,
                float min = 0.0f,
                float max = 0.0f);

/** \brief The colour of \a t in [0, 1] (clamped) on \a map. */
Colour
mapColour (float t, ColourMap map);

/** \brief An XYZRGB cloud from any XYZ cloud and one colour per point (sizes must
 * match; otherwise the result is empty). */
template <typename PointT>
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
makeColouredCloud (const pcl::PointCloud<PointT>& cloud,
                   const std::vector<Colour>& colours)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr out (new pcl::PointCloud<pcl::PointXYZRGB>);
  if (cloud.size() != colours.size())
    return out;
  out->resize (cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    auto& p = (*out)[i];
    p.x = cloud[i].x;
    p.y = cloud[i].y;
    p.z = cloud[i].z;
    p.r = colours[i].r;
    p.g = colours[i].g;
    p.b = colours[i].b;
  }
  out->is_dense = cloud.is_dense;
  return out;
}
} // namespace visualization
} // namespace pcl_ext
