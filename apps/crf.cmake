# Lim & Suter's multi-scale CRF: pcl_ext_crf_train and pcl_ext_crf_classify.
add_library(pcl_ext_crf_app_inputs STATIC src/crf/crf_inputs.cpp)
target_link_libraries(pcl_ext_crf_app_inputs PUBLIC pcl_ext::classification pcl_ext::io pcl_ext_apps_common)
pcl_ext_add_app(crf_train
  SOURCES src/crf_train.cpp
  DEPENDS pcl_ext_crf_app_inputs)
pcl_ext_add_app(crf_classify
  SOURCES src/crf_classify.cpp
  DEPENDS pcl_ext_crf_app_inputs pcl_ext::evaluation)
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_crf_classify PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_crf_classify PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
