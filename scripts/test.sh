#!/usr/bin/env bash
# Build pcl_ext and run every test.
#
#   scripts/test.sh            # Release build in build/, then ctest
#   BUILD_DIR=... scripts/test.sh
#
# Installs the Debian packages it needs when missing (apt-get, as root), starts Xvfb when no
# display is set (and stops it), exits non-zero when anything fails.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

build_dir="${BUILD_DIR:-$root/build}"
build_type="${BUILD_TYPE:-Release}"

pcl_ext_install_packages
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type"
cmake --build "$build_dir" -j "$(pcl_ext_jobs)"

trap pcl_ext_stop_display EXIT
pcl_ext_start_display
cd "$build_dir"
ctest --output-on-failure -j "$(pcl_ext_jobs)" --timeout 900
