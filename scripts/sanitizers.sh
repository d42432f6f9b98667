# Run-time options of a sanitized build (PCL_EXT_SANITIZE=ON): source this file before building
# (the build runs the test programs to list their tests) and before ctest.
# shellcheck shell=bash
_pcl_ext_supp="$(cd "$(dirname "${BASH_SOURCE[0]}")/../test/sanitizers" && pwd)"
# Any report fails the program that made it; leaks are checked at exit.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=${_pcl_ext_supp}/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=${_pcl_ext_supp}/ubsan.supp:print_stacktrace=1:halt_on_error=1"
unset _pcl_ext_supp
