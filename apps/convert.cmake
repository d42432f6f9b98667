# pcl_ext_convert: real-data point files (ASCII, Oakland 3-D, PLY, PCD) to PCD or PLY.
pcl_ext_add_app(convert
  SOURCES src/convert.cpp
  DEPENDS pcl_ext::io pcl_ext_apps_common)
