# PCL_EXT_SANITIZE: every target of this build (libraries, apps, tests, benchmarks) with
# AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer, plus the bounds checks
# of libstdc++ (_GLIBCXX_ASSERTIONS, which do not change the ABI). PCL, VTK and the other system
# libraries stay uninstrumented; the run-time options and the suppressions of their reports are
# in scripts/sanitizers.sh and test/sanitizers/ (scripts/test.sh --sanitize sets them up).
#
# Sanitized builds compile at PCL_EXT_SANITIZE_OPTIMIZATION whatever the build type (it comes
# after the type's flags): -O1 by default, the optimisation AddressSanitizer's authors recommend,
# at about half the compile time of -O3 for our Eigen- and PCL-heavy templates (96 s against 53 s
# for the region growing) and close to its run-time speed. The quick sanitized run
# (scripts/test.sh --sanitize-quick) takes -O0: its tests are short, and GCC instruments
# Boost.Geometry's and nlohmann::json's templates at -O0 in a third of the time of -O1 (the
# footprint reader: 20 s against 68 s).
#
# float-cast-overflow is added to GCC's -fsanitize=undefined set: converting a NaN or a huge
# coordinate to an integer cell index is undefined behaviour and a classic point-cloud bug.
#
# PCL_EXT_BUILD_FUZZERS: the libFuzzer targets under test/fuzz (clang only); the libraries are
# then built with -fsanitize=fuzzer-no-link so that the readers are coverage-instrumented.

set(PCL_EXT_SANITIZE_FLAGS "")
set(PCL_EXT_SANITIZE_OPTIMIZATION -O1 CACHE STRING
    "Optimisation flag of the sanitized builds (PCL_EXT_SANITIZE), whatever the build type")
if(PCL_EXT_SANITIZE OR PCL_EXT_BUILD_FUZZERS)
  set(PCL_EXT_SANITIZE_FLAGS -fsanitize=address,undefined,float-cast-overflow
                             -fno-omit-frame-pointer -g1)
  add_compile_options(${PCL_EXT_SANITIZE_FLAGS})
  if(PCL_EXT_SANITIZE)
    add_compile_options(${PCL_EXT_SANITIZE_OPTIMIZATION})
  endif()
  # Under AddressSanitizer Eigen stops trusting malloc's 16-byte alignment and switches to its
  # own aligned allocator, whose blocks cannot be freed by the uninstrumented PCL libraries (nor
  # theirs by us): PointCloud storage crosses that boundary all the time. Keep the allocator PCL
  # was built with; ASan's malloc aligns to 16 bytes as glibc's does.
  add_compile_definitions(_GLIBCXX_ASSERTIONS EIGEN_MALLOC_ALREADY_ALIGNED=1)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()

if(PCL_EXT_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "PCL_EXT_BUILD_FUZZERS needs clang (libFuzzer): configure with "
                        "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
  list(APPEND PCL_EXT_SANITIZE_FLAGS -fsanitize=fuzzer-no-link)
endif()
