# pcl_ext_compare_segmenters: pcl_ext's segmenters against stock PCL (and CGAL) ones on the same
# cloud.
# The method table and the isolated (forked) runs are a small library, shared with the
# segmenter benchmark under test/benchmarks.
add_library(pcl_ext_segmenter_comparison STATIC
  src/compare_segmenters/isolated_run.cpp
  src/compare_segmenters/pcl_ext_methods.cpp
  src/compare_segmenters/pcl_methods.cpp)
target_include_directories(pcl_ext_segmenter_comparison PUBLIC
  ${CMAKE_CURRENT_SOURCE_DIR}/src/compare_segmenters)
target_compile_options(pcl_ext_segmenter_comparison PRIVATE -Wall -Wextra)
target_link_libraries(pcl_ext_segmenter_comparison PUBLIC
  pcl_ext::segmentation pcl_ext::classification
  ${PCL_SEGMENTATION_LIBRARIES} ${PCL_SAMPLE_CONSENSUS_LIBRARIES} ${PCL_FEATURES_LIBRARIES}
  ${PCL_SEARCH_LIBRARIES} ${PCL_OCTREE_LIBRARIES})
# CGAL's plane region growing joins the comparison where CGAL is installed (Debian package
# libcgal-dev, which the scripts install; header-only).
find_package(CGAL QUIET)
if(CGAL_FOUND)
  target_sources(pcl_ext_segmenter_comparison PRIVATE src/compare_segmenters/cgal_methods.cpp)
  target_link_libraries(pcl_ext_segmenter_comparison PRIVATE CGAL::CGAL)
  target_compile_definitions(pcl_ext_segmenter_comparison PRIVATE PCL_EXT_HAVE_CGAL)
  # The tool's tests expect CGAL's method then.
  set_property(GLOBAL PROPERTY PCL_EXT_COMPARE_WITH_CGAL ON)
endif()

pcl_ext_add_app(compare_segmenters
  SOURCES
    src/compare_segmenters/compare_segmenters.cpp
    src/compare_segmenters/comparison.cpp
    src/compare_segmenters/comparison_report.cpp
  DEPENDS
    pcl_ext_segmenter_comparison pcl_ext::evaluation pcl_ext::io pcl_ext_apps_common)
if(TARGET pcl_ext_visualization)
  target_link_libraries(pcl_ext_compare_segmenters PRIVATE pcl_ext::visualization)
  target_compile_definitions(pcl_ext_compare_segmenters PRIVATE PCL_EXT_HAVE_VISUALIZATION)
endif()
