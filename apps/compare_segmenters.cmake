# pcl_ext_compare_segmenters: pcl_ext's segmenters against stock PCL ones on the same cloud.
pcl_ext_add_app(compare_segmenters
  SOURCES
    src/compare_segmenters/compare_segmenters.cpp
    src/compare_segmenters/comparison_report.cpp
    src/compare_segmenters/isolated_run.cpp
    src/compare_segmenters/pcl_ext_methods.cpp
    src/compare_segmenters/pcl_methods.cpp
  DEPENDS
    pcl_ext::segmentation pcl_ext::evaluation pcl_ext::io pcl_ext::tools
    ${PCL_SEGMENTATION_LIBRARIES} ${PCL_SAMPLE_CONSENSUS_LIBRARIES} ${PCL_FEATURES_LIBRARIES}
    ${PCL_SEARCH_LIBRARIES} ${PCL_OCTREE_LIBRARIES})
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_compare_segmenters PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_compare_segmenters PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
