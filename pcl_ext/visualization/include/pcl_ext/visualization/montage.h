/*
 * pcl_ext: montages of segmentations: one tile per labelling of the same cloud.
 */
#pragma once

#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief A tile showing \a cloud coloured by \a labels (colourByLabel: 0 grey, every
 * other label its own colour), titled \a title. Sizes must match; otherwise the tile is
 * empty. */
template <typename PointT>
View
makeLabelView (const std::string& title,
               const pcl::PointCloud<PointT>& cloud,
               const std::vector<std::uint32_t>& labels,
               double point_size = 1.5)
{
  View view;
  view.title = title;
  view.layers.push_back (
      {makeColouredCloud (cloud, colourByLabel (labels)), point_size});
  return view;
}

/** \brief Render options for a montage of \a tiles tiles of \a tile_width x \a
 * tile_height pixels, in rows of at most \a max_columns (fewer when there are fewer
 * tiles), so that every tile keeps its size however many there are. All tiles share one
 * camera (renderToPng). \a tiles 0 is taken as 1; sizes are clamped so that the image
 * stays within 16384 pixels. */
RenderOptions
makeMontageOptions (std::size_t tiles,
                    int tile_width = 520,
                    int tile_height = 400,
                    int max_columns = 4);
} // namespace visualization
} // namespace pcl_ext
