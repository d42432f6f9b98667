#!/usr/bin/env bash
# Build pcl_ext and run its tests.
#
#   scripts/test.sh                    # the layout checks (scripts/check_layout.py), then a
#                                      # Release build in build/ and every test (ctest)
#   scripts/test.sh --sanitize         # ASan + UBSan build in build-sanitize/, then every test
#   scripts/test.sh --sanitize-quick   # ASan + UBSan build in build-sanitize-quick/ with the
#                                      # libraries precompiled for the point types these tests
#                                      # use, then the unit tests of the shared machinery (io,
#                                      # common, search, tiling, apps/common) and the fuzz
#                                      # seeds: what reads files and untrusted input
#   scripts/test.sh --fuzz [SECONDS]   # clang libFuzzer build in build-fuzz/, then each fuzz
#                                      # target for SECONDS (default 30) from its seed corpus
#   BUILD_DIR=... BUILD_TYPE=... scripts/test.sh [option]
#
# Installs the Debian packages it needs when missing (apt-get, as root), starts Xvfb when no
# display is set (and stops it), exits non-zero when anything fails.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

mode="${1:-default}"
case "$mode" in
  default|--sanitize|--sanitize-quick|--fuzz) ;;
  -h|--help) sed -n '2,17p' "${BASH_SOURCE[0]}"; exit 0 ;;
  *) echo "unknown option '$mode' (see scripts/test.sh --help)" >&2; exit 2 ;;
esac
build_type="${BUILD_TYPE:-Release}"
jobs="$(pcl_ext_jobs)"

# Unit tests of the sanitized quick run: ctest folders under test/, those of the code that reads
# files and untrusted input (the methods' unit tests and the fuzz seeds of their files, label
# `methods`, the tests on generated scenes, label `quality`, and on real data, label `data`,
# are left to --sanitize, which CI's time does not allow).
quick_dirs=(io common search tiling apps/common fuzz)
# The point types those tests use. Every precompiled type costs each library source about ten
# seconds under the sanitizers; the whole sanitized suite keeps the full list.
quick_point_types="pcl::PointXYZ;pcl::PointXYZRGBNormal"

if [ "$mode" = "--fuzz" ]; then
  seconds="${2:-30}"
  pcl_ext_install_packages "${PCL_EXT_FUZZ_PACKAGES[@]}"
  build_dir="${BUILD_DIR:-$root/build-fuzz}"
  # Optimised, with assertions (Eigen's, Boost's, ours) left on: they are findings too.
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DPCL_EXT_BUILD_FUZZERS=ON -DPCL_EXT_BUILD_TESTS=OFF -DPCL_EXT_BUILD_APPS=OFF \
    -DPCL_EXT_BUILD_BENCHMARKS=OFF -DPCL_EXT_BUILD_VISUALIZATION=OFF
  cmake --build "$build_dir" -j "$jobs" --target pcl_ext_fuzzers
  # shellcheck source=sanitizers.sh
  source "$here/sanitizers.sh"
  status=0
  for corpus in "$root"/test/fuzz/*/; do
    target="$(basename "$corpus")"
    # New inputs go to a scratch corpus; the committed seeds are only read.
    work="$build_dir/test/fuzz/corpus/$target"
    mkdir -p "$work"
    echo "== fuzz_$target: ${seconds} s"
    if ! (cd "$build_dir/test/fuzz" && "./fuzz_$target" -max_total_time="$seconds" \
            -print_final_stats=1 -artifact_prefix="$build_dir/test/fuzz/fuzz_${target}-" \
            "$work" "$corpus"); then
      echo "fuzz_$target FAILED: the crashing input is in $build_dir/test/fuzz/" >&2
      status=1
    fi
  done
  exit "$status"
fi

# Tests and benchmarks on: the folder may have been configured without them (scripts/build.sh).
cmake_args=(-DCMAKE_BUILD_TYPE="$build_type" -DPCL_EXT_BUILD_TESTS=ON -DPCL_EXT_BUILD_BENCHMARKS=ON)
build_dir="${BUILD_DIR:-$root/build}"
timeout=900
if [ "$mode" != default ]; then
  build_dir="${BUILD_DIR:-$root/build-sanitize}"
  cmake_args+=(-DPCL_EXT_SANITIZE=ON -DPCL_EXT_POINT_TYPES=)
  if [ "$mode" = "--sanitize-quick" ]; then
    build_dir="${BUILD_DIR:-$root/build-sanitize-quick}"
    # Each source of these libraries compiled on its own, as without the unity build: what
    # a source fails to include itself shows here.
    cmake_args+=(-DPCL_EXT_POINT_TYPES="$quick_point_types" -DPCL_EXT_SANITIZE_OPTIMIZATION=-O0
                 -DPCL_EXT_UNITY_BUILD=OFF)
  fi
  # The real-data tests (Oakland training, mOSD frames) run several times slower sanitized.
  timeout=2700
  # The sanitizer options for the tests.
  # shellcheck source=sanitizers.sh
  source "$here/sanitizers.sh"
fi

pcl_ext_install_packages
if [ "$mode" = default ]; then
  python3 "$here/check_layout.py"
fi
cmake -S "$root" -B "$build_dir" "${cmake_args[@]}"
if [ "$mode" = "--sanitize-quick" ]; then
  # The unit tests of those folders and what they need, nothing else (test/CMakeLists.txt).
  quick_targets=()
  for d in "${quick_dirs[@]}"; do
    quick_targets+=("pcl_ext_unit_tests_${d//\//_}")
  done
  cmake --build "$build_dir" -j "$jobs" --target "${quick_targets[@]}"
else
  cmake --build "$build_dir" -j "$jobs"
fi

trap pcl_ext_stop_display EXIT
pcl_ext_start_display
cd "$build_dir"
if [ "$mode" = "--sanitize-quick" ]; then
  status=0
  # The labelled tests were not built: their labels leave them out.
  for d in "${quick_dirs[@]}"; do
    ctest --test-dir "test/$d" --output-on-failure -j "$jobs" --timeout "$timeout" \
      -LE 'data|quality|methods' || status=1
  done
  exit "$status"
fi
ctest --output-on-failure -j "$jobs" --timeout "$timeout"
