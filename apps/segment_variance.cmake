# pcl_ext_segment_variance: Belton & Lichti region growing over the local variance classes.
pcl_ext_add_app(segment_variance
  SOURCES src/segment_variance.cpp
  DEPENDS pcl_ext::segmentation pcl_ext::classification pcl_ext_apps_common pcl_ext::io)
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_segment_variance PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_segment_variance PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
