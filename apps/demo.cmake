# pcl_ext_demo: runs each method on generated scenes and writes PNGs and a summary.
if(TARGET pcl_ext_visualization AND TARGET pcl_ext_simulation)
  pcl_ext_add_app(demo
    SOURCES
      src/demo/demo.cpp
      src/demo/demo_context.cpp
      src/demo/step_scenes.cpp
      src/demo/step_neighbourhoods.cpp
      src/demo/step_profiles.cpp
      src/demo/step_classification.cpp
      src/demo/step_variance_segmentation.cpp
      src/demo/step_registration.cpp
      src/demo/step_crf.cpp
    DEPENDS
      pcl_ext::common pcl_ext_apps_common pcl_ext::simulation pcl_ext::visualization
      pcl_ext::evaluation pcl_ext::segmentation pcl_ext::classification
      pcl_ext::registration pcl_ext::io pcl_ext_scene_crf_input)
endif()
