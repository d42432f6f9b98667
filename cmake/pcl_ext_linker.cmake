# The linker. The build links some two hundred programs (tests, tools, benchmarks), each
# against PCL, VTK and Boost; LLVM's lld links one of them in about a fifth of GNU ld's time,
# which is most of a build's linking. Used when the compiler accepts -fuse-ld=lld (Debian
# package lld) and CMake has check_linker_flag (3.18); GNU ld otherwise. The option only affects how this project's own targets
# are linked: nothing of it is exported to the packages that use pcl_ext.
option(PCL_EXT_USE_LLD "Link with LLVM's lld when the compiler accepts it" ON)

if(PCL_EXT_USE_LLD AND CMAKE_VERSION VERSION_GREATER_EQUAL 3.18)
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=lld" PCL_EXT_LLD_ACCEPTED)
  if(PCL_EXT_LLD_ACCEPTED)
    add_link_options(-fuse-ld=lld)
  endif()
endif()
