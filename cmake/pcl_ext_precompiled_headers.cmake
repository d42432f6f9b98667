# Precompiled headers for the executables. Every test parses PCL's point types, Eigen and
# gtest.h, most also PCL's conversions, PCD io and kd-tree, most of the time it compiles in; a
# tool or benchmark the first of these without gtest. The tests share one precompiled header, the tools and benchmarks another (a
# precompiled header is only used with the macros and options it was made with, so each group
# has its own, made by a small provider target with the group's flags). The flags that differ
# between our executables are made the same across a group: -fPIC (which PCL's io and
# visualization targets add to their users) and OpenMP (which sets _REENTRANT, a macro the
# system headers test). -Winvalid-pch reports a source that could not use the header (it then
# parses the headers itself: slower, never wrong). The libraries have none: their sources spend
# their time instantiating templates, and a header precompiled per library cost more than it
# saved.
option(PCL_EXT_PRECOMPILED_HEADERS "Precompile the PCL, Eigen and gtest headers" ON)

set(PCL_EXT_PCH_HEADERS <algorithm> <cmath> <cstdint> <memory> <string> <vector>
    <Eigen/Dense> <pcl/point_cloud.h> <pcl/point_types.h>)
# The tests' header adds what most test files parse besides: PCL's cloud conversions and PCD
# io, its kd-tree search and the standard library's files and streams.
set(PCL_EXT_TEST_PCH_HEADERS <filesystem> <fstream> <map> <random> <sstream>
    <pcl/common/io.h> <pcl/common/point_tests.h> <pcl/conversions.h> <pcl/io/pcd_io.h>
    <pcl/search/kdtree.h> <gtest/gtest.h>)

# pcl_ext_share_precompiled_headers(<target> TESTS|EXECUTABLES): the executable <target> uses
# the header precompiled for its group: TESTS (the common headers and gtest, the flags of a
# gtest program) or EXECUTABLES (the common headers, the flags of a tool).
function(pcl_ext_share_precompiled_headers target group)
  if(NOT PCL_EXT_PRECOMPILED_HEADERS)
    return()
  endif()
  string(TOLOWER "pcl_ext_pch_${group}" provider)
  if(NOT TARGET ${provider})
    file(WRITE ${PROJECT_BINARY_DIR}/${provider}.cpp
         "// Made by CMake: the precompiled header's provider (see cmake/pcl_ext_precompiled_headers.cmake).\n")
    set(headers ${PCL_EXT_PCH_HEADERS})
    if(group STREQUAL "TESTS")
      add_executable(${provider} EXCLUDE_FROM_ALL ${PROJECT_BINARY_DIR}/${provider}.cpp)
      target_link_libraries(${provider} PRIVATE pcl_ext::common GTest::gtest GTest::gtest_main)
      list(APPEND headers ${PCL_EXT_TEST_PCH_HEADERS})
    else()
      file(APPEND ${PROJECT_BINARY_DIR}/${provider}.cpp "int main () { return 0; }\n")
      add_executable(${provider} EXCLUDE_FROM_ALL ${PROJECT_BINARY_DIR}/${provider}.cpp)
      target_link_libraries(${provider} PRIVATE pcl_ext::common)
    endif()
    target_precompile_headers(${provider} PRIVATE ${headers})
    pcl_ext_align_executable_flags(${provider} ${group})
  endif()
  target_precompile_headers(${target} REUSE_FROM ${provider})
  target_compile_options(${target} PRIVATE -Winvalid-pch)
  pcl_ext_align_executable_flags(${target} ${group})
endfunction()

# pcl_ext_align_executable_flags(<target> [TESTS]): the flags every executable of a group shares.
# Test programs are compiled at -O1 in the optimised builds: the code they test is in the
# libraries (built as the build type says) and a test file's time goes to instantiating and
# optimising gtest's and PCL's inline templates, which -O1 does in about half the time of -O3.
# The sanitized builds compile everything at their own level (cmake/pcl_ext_sanitizers.cmake).
function(pcl_ext_align_executable_flags target)
  target_compile_options(${target} PRIVATE -fPIC)
  if(ARGV1 STREQUAL "TESTS" AND NOT PCL_EXT_SANITIZE)
    target_compile_options(${target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:-O1>)
  endif()
  target_link_libraries(${target} PRIVATE OpenMP::OpenMP_CXX)
endfunction()
