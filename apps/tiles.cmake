# pcl_ext_tiles: a method tile by tile with halos, for clouds larger than memory; with
# Debian's OpenMPI the tiles are shared among the ranks of `mpirun -np N pcl_ext_tiles ...`.
pcl_ext_add_app(tiles
  SOURCES
    src/tiles/tiles.cpp
    src/tiles/tile_steps.cpp
    src/tiles/merge_output.cpp
    src/tiles/profile_frame.cpp
    src/tiles/profile_parts.cpp
    src/tiles/profile_stages.cpp
    src/tiles/profile_tiles.cpp
    src/tiles/profile_part_steps.cpp
    src/tiles/profile_curve_steps.cpp
    src/tiles/profile_cylinder_join.cpp
    src/tiles/segment_points_file.cpp
    src/tiles/second_pass_steps.cpp
    src/tiles/tile_intersections.cpp
    src/tiles/tile_outputs.cpp
    src/tiles/input_fields.cpp
    src/tiles/tile_cloud.cpp
    src/tiles/tile_scheduler.cpp
    src/tiles/tile_method.cpp
    src/tiles/variance_tiles.cpp
    src/tiles/classify_variance_tiles.cpp
    src/tiles/segment_variance_tiles.cpp
    src/tiles/reintegration_margin.cpp
    src/tiles/crf_classify_tiles.cpp
  DEPENDS pcl_ext_crf_app_inputs pcl_ext::classification pcl_ext::segmentation pcl_ext::tiling pcl_ext_apps_common pcl_ext::io)
find_package(MPI COMPONENTS CXX)
if(MPI_CXX_FOUND)
  target_link_libraries(pcl_ext_tiles PRIVATE MPI::MPI_CXX)
  target_compile_definitions(pcl_ext_tiles PRIVATE PCL_EXT_HAVE_MPI)
endif()
