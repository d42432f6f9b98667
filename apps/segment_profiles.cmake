# pcl_ext_segment_profiles: Sithole & Mapurisa profile-intersection segmentation.
pcl_ext_add_app(segment_profiles
  SOURCES src/segment_profiles.cpp
  DEPENDS pcl_ext::segmentation pcl_ext_apps_common pcl_ext::io)
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_segment_profiles PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_segment_profiles PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
