# pcl_ext_register_to_map: register a building scan to its footprint by plane matching
# (Khoshelham & Gorte 2009).
set(register_to_map_deps pcl_ext::registration pcl_ext::search pcl_ext::io pcl_ext_apps_common)
if(TARGET pcl_ext::visualization)
  list(APPEND register_to_map_deps pcl_ext::visualization)
endif()
pcl_ext_add_app(register_to_map
  SOURCES src/register_to_map.cpp src/register_to_map_defaults.cpp src/register_to_map_output.cpp
  DEPENDS ${register_to_map_deps})
if(TARGET pcl_ext::visualization)
  target_compile_definitions(pcl_ext_register_to_map PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
