#!/usr/bin/env bash
# The tiled Belton & Lichti classification and segmentation of a large generated project of
# scans, as LAS files on disk: time, points per second and peak memory per process, written
# to out/benchmark_tiles.md with the machine and the date.
#
#   scripts/benchmark_tiles.sh                        # 20 million points
#   POINTS=100000000 scripts/benchmark_tiles.sh       # 100 million: five scans, 4 GB of LAS
#   RANKS=2 scripts/benchmark_tiles.sh                # under mpirun, 2 ranks of 1 thread
#
# The scans are pcl_ext_generate_scene's `street` (seeds from SEED, default 1), made once in
# OUT_DIR. Run it on an otherwise idle machine: the timings are wall times.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
# shellcheck source=common.sh
source "$here/common.sh"

build_dir="${BUILD_DIR:-$root/build}"
out_dir="${OUT_DIR:-$root/out}"
points="${POINTS:-20000000}"
seed="${SEED:-1}"
ranks="${RANKS:-1}"

pcl_ext_install_packages time
if [ ! -x "$build_dir/apps/pcl_ext_tiles" ]; then
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build_dir" -j "$(pcl_ext_jobs)" --target pcl_ext_tiles \
    pcl_ext_generate_scene pcl_ext_convert
fi
apps="$build_dir/apps"
mkdir -p "$out_dir"
# A project of scans of at most 20 million points each (what the generator holds in memory),
# streets side by side 100 m apart, seeds SEED, SEED + 1, ...
per_scan=20000000
scans=$(((points + per_scan - 1) / per_scan))
inputs=()
count=0
for i in $(seq 0 $((scans - 1))); do
  n=$((points / scans))
  scan="$out_dir/street_${n}_$((seed + i))_$((100 * i)).las"
  if [ ! -e "$scan" ]; then
    "$apps/pcl_ext_generate_scene" street "$out_dir/street.pcd" -points "$n" \
      -seed "$((seed + i))" -offset "$((100 * i)),0,0"
    "$apps/pcl_ext_convert" "$out_dir/street.pcd" "$scan"
    rm -f "$out_dir/street.pcd"
  fi
  inputs+=("$scan")
  count=$((count + $(od -An -t u8 -j 247 -N 8 "$scan" | tr -d ' '))) # LAS 1.4 point count
done

launch=()
threads=0
if [ "$ranks" -gt 1 ]; then
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$ranks")
  threads=1
fi
rows="$(mktemp)"
trap 'rm -f "$rows"' EXIT
for method in classify_variance segment_variance; do
  output="$out_dir/tiles_${method}.las"
  log="$out_dir/tiles_${method}.log"
  /usr/bin/time -f "%e %M" -o "$log.time" \
    "${launch[@]}" "$apps/pcl_ext_tiles" "$method" "${inputs[@]}" "$output" -threads "$threads" \
    | tee "$log"
  read -r seconds kilobytes < "$log.time"
  # Per process: the tool's own summary lines ("peak memory N MB"), the largest.
  peak="$(sed -n 's/.*peak memory \([0-9]*\) MB.*/\1/p' "$log" | sort -n | tail -n 1)"
  tiles="$(sed -n 's/^\([0-9]*\) tiles (.*/\1/p' "$log" | head -n 1)"
  echo "| \`$method\` | $count | ${tiles:-?} | $ranks | $seconds s | $(awk -v n="$count" -v s="$seconds" 'BEGIN { printf "%.0f", n / s }') | ${peak:-?} MB |" >> "$rows"
  rm -f "$output"
done

cpu="$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -n 1)"
memory="$(free -g 2>/dev/null | awk '/^Mem:/ {print $2 " GB"}')"
{
  echo "# pcl_ext_tiles on a large scan"
  echo
  echo "Measured $(date -u +%Y-%m-%d) on ${cpu:-unknown CPU}, $(nproc) cores, ${memory:-? GB}."
  echo "$scans scan(s) of \`pcl_ext_generate_scene street -points $((points / scans))\`, seeds $seed to"
  echo "$((seed + scans - 1)), 100 m apart, written as LAS; each method with its defaults (tile"
  echo "size, halo, thresholds from the data)."
  echo
  echo "| method | points | tiles | processes | wall | points/s | peak memory per process |"
  echo "|---|---|---|---|---|---|---|"
  cat "$rows"
} > "$out_dir/benchmark_tiles.md"
echo "Wrote $out_dir/benchmark_tiles.md"
