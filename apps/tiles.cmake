# pcl_ext_tiles: a method tile by tile with halos, for clouds larger than memory.
pcl_ext_add_app(tiles
  SOURCES
    src/tiles/tiles.cpp
    src/tiles/tile_steps.cpp
    src/tiles/tile_cloud.cpp
    src/tiles/classify_variance_tiles.cpp
  DEPENDS pcl_ext::classification pcl_ext::tiling pcl_ext_apps_common pcl_ext::io)
