/*
 * pcl_ext_tiles: the methods by name, and a method's step on a tile with the margin it
 * needs.
 */
#include "tile_method.h"
#include "variance_tiles.h"

#include <algorithm>

namespace pcl_ext {
namespace apps {
bool
computeOnTile (const tiling::TilePlan& plan,
               const std::string& folder,
               std::size_t tile,
               const NeighbourhoodReach& reach,
               unsigned int threads,
               double margin,
               const TileMethod& method,
               const std::function<bool (const TileCloud&)>& compute,
               TileCloud& cloud,
               const PointSelection& select)
{
  for (;;) {
    if (!loadTileCloud (plan, folder, tile, reach, threads, cloud, margin, select) ||
        !compute (cloud))
      return false;
    const double needed = method.getNeededMargin();
    if (needed <= cloud.margin || cloud.whole)
      return true;
    margin = std::max (needed, 1.25 * cloud.margin);
  }
}

std::unique_ptr<TileMethod>
makeTileMethod (const std::string& name)
{
  if (name == "classify_variance")
    return makeClassifyVarianceTiles();
  if (name == "segment_variance")
    return makeSegmentVarianceTiles();
  if (name == "crf_classify")
    return makeCrfClassifyTiles();
  return nullptr;
}
} // namespace apps
} // namespace pcl_ext
