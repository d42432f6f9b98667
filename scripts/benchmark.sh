#!/usr/bin/env bash
# Build the segmenter benchmark and write out/benchmarks.md: each pcl_ext segmenter against its
# stock PCL counterpart on the generated indoor scene (points per second, time ratio, peak
# memory per point), with the machine and the date.
#
#   scripts/benchmark.sh                          # 100k, 1M and 5M points; 1 and 2 threads
#   POINTS=100000 THREADS=1 scripts/benchmark.sh  # a quick run
#
# Run it on an otherwise idle machine: the timings are wall times.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

build_dir="${BUILD_DIR:-$root/build-release}"
out_dir="${OUT_DIR:-$root/out}"
points="${POINTS:-100000,1000000,5000000}"
threads="${THREADS:-1,2}"
repeats="${REPEATS:-1}"

pcl_ext_install_packages
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPCL_EXT_BUILD_TESTS=ON
cmake --build "$build_dir" -j "$(pcl_ext_jobs)" --target pcl_ext_benchmark_segmenters

mkdir -p "$out_dir"
report="$out_dir/benchmarks.md"
table="$(mktemp)"
trap 'rm -f "$table"' EXIT
"$build_dir/test/benchmarks/pcl_ext_benchmark_segmenters" \
  -points "$points" -threads "$threads" -repeats "$repeats" | tee "$table"

cpu="$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -n 1)"
memory="$(free -g 2>/dev/null | awk '/^Mem:/ {print $2 " GB"}')"
os="$(. /etc/os-release 2>/dev/null && echo "${PRETTY_NAME:-unknown}")"
pcl="$(dpkg-query -W -f='${Version}' libpcl-dev 2>/dev/null || echo unknown)"
{
  echo "# pcl_ext segmenters against stock PCL"
  echo
  echo "Measured $(date -u +%Y-%m-%d) on ${cpu:-unknown CPU}, $(nproc) cores, ${memory:-? GB},"
  echo "${os}, PCL ${pcl}; best of ${repeats} run(s) per case."
  echo
  echo "Generated \`indoor\` scene (pcl_ext_generate_scene) at each size. Time ratio: pcl_ext"
  echo "time / PCL time (below 1: pcl_ext is faster). B/point: peak resident memory of the run"
  echo "above the loaded cloud, per point. Stock PCL segmenters run on one thread whatever the"
  echo "count (pcl::RegionGrowing's normals use it)."
  echo
  cat "$table"
} > "$report.tmp"
mv "$report.tmp" "$report"
echo "Wrote $report"
