# pcl_ext_classify_variance: Belton & Lichti surface / edge / boundary classification.
pcl_ext_add_app(classify_variance
  SOURCES src/classify_variance.cpp
  DEPENDS pcl_ext::classification pcl_ext_apps_common pcl_ext::io)
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_classify_variance PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_classify_variance PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
