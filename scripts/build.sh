#!/usr/bin/env bash
# Build pcl_ext's libraries and tools (Release, no tests or benchmarks) in build/: what the
# README's quick start needs. scripts/test.sh builds the same folder with the tests.
#
#   scripts/build.sh
#   BUILD_DIR=... scripts/build.sh
#
# Installs the Debian packages it needs when missing (apt-get, as root).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

build_dir="${BUILD_DIR:-$root/build}"
pcl_ext_install_packages
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DPCL_EXT_BUILD_TESTS=OFF -DPCL_EXT_BUILD_BENCHMARKS=OFF
cmake --build "$build_dir" -j "$(pcl_ext_jobs)"
echo "The tools are in $build_dir/apps/."
