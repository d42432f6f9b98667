# pcl_ext_evaluate: segmentation or classification metrics of a prediction against ground truth.
pcl_ext_add_app(evaluate
  SOURCES src/evaluate.cpp
  DEPENDS pcl_ext::evaluation pcl_ext::io pcl_ext_apps_common)
