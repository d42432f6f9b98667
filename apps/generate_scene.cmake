# pcl_ext_generate_scene: synthetic TLS scenes with exact ground truth.
pcl_ext_add_app(generate_scene
  SOURCES src/generate_scene.cpp
  DEPENDS pcl_ext::simulation pcl_ext::io pcl_ext_apps_common)
