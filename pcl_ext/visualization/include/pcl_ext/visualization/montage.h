/*
 * pcl_ext: montages of segmentations: one tile per labelling of the same cloud.
 */
#pragma once

#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief A tile showing \a cloud coloured by \a labels (colourByLabel: 0 grey, every
 * other label its own colour), titled \a title, with a legend "unsegmented" for the
 * grey when any label is 0. Sizes must match; otherwise the tile is empty. \a
 * point_size 0: from the point spacing (Layer). */
template <typename PointT>
View
makeLabelView (const std::string& title,
               const pcl::PointCloud<PointT>& cloud,
               const std::vector<std::uint32_t>& labels,
               double point_size = 0.0)
{
  View view;
  view.title = title;
  view.layers.push_back (
      {makeColouredCloud (cloud, colourByLabel (labels)), point_size});
  if (std::find (labels.begin(), labels.end(), 0u) != labels.end())
    view.legend.push_back ({"unsegmented", colourByLabel ({0u}).front()});
  return view;
}

/** \brief \a labels renumbered so that each segment takes the label of the \a reference
 * segment it overlaps most, as a picture's colours then match the reference's: pairs
 * (segment, reference segment) are taken by decreasing number of shared points, each
 * segment and each reference segment at most once (greedy best overlap). Segments left
 * unpaired take new labels above every reference label, in order of first appearance;
 * label 0 (no segment) stays 0 and is never paired. Sizes must match; otherwise \a
 * labels is returned unchanged. */
std::vector<std::uint32_t>
matchLabelsToReference (const std::vector<std::uint32_t>& labels,
                        const std::vector<std::uint32_t>& reference);

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
