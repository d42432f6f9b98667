/*
 * pcl_ext: montages of segmentations.
 */
#include <pcl_ext/visualization/montage.h>

#include <algorithm>

namespace pcl_ext {
namespace visualization {
RenderOptions
makeMontageOptions (std::size_t tiles, int tile_width, int tile_height, int max_columns)
{
  const int n = static_cast<int> (std::clamp<std::size_t> (tiles, 1, 1024));
  const int columns = std::min (n, std::max (1, max_columns));
  const int rows = (n + columns - 1) / columns;
  RenderOptions options;
  options.columns = columns;
  options.zoom_out = 2.8; // tiles are small: keep the whole scene inside each
  options.width = std::clamp (tile_width, 16, 16384 / columns) * columns;
  options.height = std::clamp (tile_height, 16, 16384 / rows) * rows;
  return options;
}
} // namespace visualization
} // namespace pcl_ext
