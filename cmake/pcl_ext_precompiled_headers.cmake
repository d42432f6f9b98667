# Precompiled headers. Every source of ours includes PCL's point types and Eigen, which take
# about 3.5 of the 8 to 15 seconds a source compiles in; gtest.h takes 2 more in a test.
# A library precompiles them once for its sources; the tests share one precompiled header, and
# the tools and benchmarks another (a precompiled header is only used with the macros and
# options it was made with, so each group has its own, made by a small provider target with
# the group's flags). -Winvalid-pch reports a source that could not use it (it then parses the
# headers itself: slower, never wrong). The flags that differ between our executables are made
# the same across a group: -fPIC (which PCL's io and visualization targets add to their users)
# and OpenMP (which sets _REENTRANT, a macro the system headers test).
option(PCL_EXT_PRECOMPILED_HEADERS "Precompile the PCL, Eigen and gtest headers" ON)

set(PCL_EXT_PCH_HEADERS <algorithm> <cmath> <cstdint> <memory> <string> <vector>
    <Eigen/Dense> <pcl/point_cloud.h> <pcl/point_types.h>)

# pcl_ext_precompile_headers(<target>): <target> precompiles the common headers for its own
# sources (libraries, and tools of several sources).
function(pcl_ext_precompile_headers target)
  if(PCL_EXT_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${PCL_EXT_PCH_HEADERS})
    target_compile_options(${target} PRIVATE -Winvalid-pch)
  endif()
endfunction()

# pcl_ext_share_precompiled_headers(<target> TESTS|EXECUTABLES): <target> (one source, one
# executable) uses the header precompiled for its group: TESTS (the common headers and gtest,
# flags of a gtest program) or EXECUTABLES (the common headers, flags of a tool).
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
      list(APPEND headers <gtest/gtest.h>)
    else()
      file(APPEND ${PROJECT_BINARY_DIR}/${provider}.cpp "int main () { return 0; }\n")
      add_executable(${provider} EXCLUDE_FROM_ALL ${PROJECT_BINARY_DIR}/${provider}.cpp)
      target_link_libraries(${provider} PRIVATE pcl_ext::common)
    endif()
    target_precompile_headers(${provider} PRIVATE ${headers})
    pcl_ext_align_executable_flags(${provider})
  endif()
  target_precompile_headers(${target} REUSE_FROM ${provider})
  target_compile_options(${target} PRIVATE -Winvalid-pch)
  pcl_ext_align_executable_flags(${target})
endfunction()

function(pcl_ext_align_executable_flags target)
  target_compile_options(${target} PRIVATE -fPIC)
  target_link_libraries(${target} PRIVATE OpenMP::OpenMP_CXX)
endfunction()
