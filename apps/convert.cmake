# pcl_ext_convert: any point file the tools read (LAS, LAZ, E57, PTX, PTS, PCD, PLY, ASCII,
# Oakland 3-D) to LAS, PCD or PLY.
pcl_ext_add_app(convert
  SOURCES src/convert.cpp
  DEPENDS pcl_ext::io pcl_ext_apps_common)
