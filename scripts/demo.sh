#!/usr/bin/env bash
# Build pcl_ext in Release and run the demo on a generated scene (nothing is downloaded).
# Writes PNG images and a text summary (timings, metrics) to out/.
#
#   scripts/demo.sh [demo options]     e.g. scripts/demo.sh -points 500000
#
# Installs the Debian packages it needs when missing (apt-get, as root) and starts Xvfb for
# the rendering when no display is set.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

build_dir="${BUILD_DIR:-$root/build-release}"
out_dir="${OUT_DIR:-$root/out}"

pcl_ext_install_packages
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPCL_EXT_BUILD_TESTS=OFF
cmake --build "$build_dir" -j "$(pcl_ext_jobs)" --target pcl_ext_demo

trap pcl_ext_stop_display EXIT
pcl_ext_start_display
mkdir -p "$out_dir"
# Real scans next to the project, if any, add optional steps; nothing is downloaded.
data_args=()
[ -d "${PCL_EXT_DATA_DIR:-$root/../shared/data}" ] && data_args=(-data "${PCL_EXT_DATA_DIR:-$root/../shared/data}")
"$build_dir/apps/pcl_ext_demo" "$out_dir" "${data_args[@]}" "$@"
echo "Results in $out_dir:"
ls -1 "$out_dir"
