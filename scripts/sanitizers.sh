# Run-time options of a sanitized build (PCL_EXT_SANITIZE=ON): source this file before ctest.
# shellcheck shell=bash
_pcl_ext_supp="$(cd "$(dirname "${BASH_SOURCE[0]}")/../test/sanitizers" && pwd)"
# Any report fails the program that made it; leaks are checked at exit.
# alloc_dealloc_mismatch=0: Debian's PCL is compiled as C++14, where PCL_MAKE_ALIGNED_OPERATOR_NEW
# gives its classes Eigen's operator new (malloc); in our C++17 code Eigen leaves that to the
# language's aligned new, so an object PCL's library creates and our code deletes (a
# pcl::SampleConsensusModelPlane inside pcl::SACSegmentation, the clouds of
# pcl::SupervoxelClustering) is freed with operator delete: a mismatch in name only (both end
# in malloc / free), at every boundary where PCL objects change hands.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:alloc_dealloc_mismatch=0"
export LSAN_OPTIONS="suppressions=${_pcl_ext_supp}/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=${_pcl_ext_supp}/ubsan.supp:print_stacktrace=1:halt_on_error=1"
unset _pcl_ext_supp
