# Helpers shared by every module: one library per module, exported as pcl_ext::<module>.
#
# PCL 1.13 defines no PCL:: namespaced targets; its config creates plain imported targets
# (pcl_common, pcl_features, ...) that PCL_<COMPONENT>_LIBRARIES name. Modules link those, and the
# package config re-runs find_package(PCL) so that consumers see the same names.

set(PCL_EXT_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/pcl_ext)
set(PCL_EXT_EXPORT_SET pcl_extTargets)

# pcl_ext_add_module(<module> [SOURCES ...] [DEPENDS ...])
# Creates target pcl_ext_<module> with alias pcl_ext::<module>; headers live in
# <module dir>/include/pcl_ext/..., installed as-is.
function(pcl_ext_add_module module)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target pcl_ext_${module})
  if(ARG_SOURCES)
    add_library(${target} ${ARG_SOURCES})
    set(scope PUBLIC)
    # Installed, a module finds the modules it needs beside it (a consumer's runpath
    # covers only its own direct dependencies), wherever the prefix is.
    set_target_properties(${target} PROPERTIES
      VERSION ${PROJECT_VERSION}
      SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
      INSTALL_RPATH "$ORIGIN")
    target_compile_options(${target} PRIVATE -Wall -Wextra)
    if(PCL_EXT_POINT_TYPES)
      # The Boost.Preprocessor sequence instantiate.h expects: (pcl::PointXYZ)(pcl::PointXYZRGB)
      list(TRANSFORM PCL_EXT_POINT_TYPES PREPEND "(" OUTPUT_VARIABLE types)
      list(TRANSFORM types APPEND ")")
      list(JOIN types "" types)
      target_compile_definitions(${target} PRIVATE "PCL_EXT_XYZ_POINT_TYPES=${types}")
    endif()
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(pcl_ext::${module} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${module})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} ${scope} cxx_std_17)
  target_link_libraries(${target} ${scope} ${ARG_DEPENDS})
  install(TARGETS ${target} EXPORT ${PCL_EXT_EXPORT_SET}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()

# pcl_ext_add_app(<name> SOURCES ... DEPENDS ...): a command-line tool pcl_ext_<name>.
function(pcl_ext_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(pcl_ext_${name} ${ARG_SOURCES})
  target_link_libraries(pcl_ext_${name} PRIVATE ${ARG_DEPENDS})
  target_compile_options(pcl_ext_${name} PRIVATE -Wall -Wextra)
  pcl_ext_share_precompiled_headers(pcl_ext_${name} EXECUTABLES)
  install(TARGETS pcl_ext_${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()

function(pcl_ext_install_package)
  include(CMakePackageConfigHelpers)
  install(EXPORT ${PCL_EXT_EXPORT_SET}
    NAMESPACE pcl_ext::
    DESTINATION ${PCL_EXT_CMAKE_INSTALL_DIR})
  configure_package_config_file(
    ${PROJECT_SOURCE_DIR}/cmake/pcl_extConfig.cmake.in
    ${PROJECT_BINARY_DIR}/pcl_extConfig.cmake
    INSTALL_DESTINATION ${PCL_EXT_CMAKE_INSTALL_DIR})
  write_basic_package_version_file(
    ${PROJECT_BINARY_DIR}/pcl_extConfigVersion.cmake
    VERSION ${PROJECT_VERSION}
    COMPATIBILITY SameMinorVersion)
  install(FILES
    ${PROJECT_BINARY_DIR}/pcl_extConfig.cmake
    ${PROJECT_BINARY_DIR}/pcl_extConfigVersion.cmake
    DESTINATION ${PCL_EXT_CMAKE_INSTALL_DIR})
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/pcl_ext)
endfunction()
