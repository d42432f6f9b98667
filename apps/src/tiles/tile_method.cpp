/*
 * pcl_ext_tiles: the methods by name.
 */
#include "tile_method.h"
#include "variance_tiles.h"

namespace pcl_ext {
namespace apps {
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
