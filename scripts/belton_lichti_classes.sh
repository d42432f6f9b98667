#!/usr/bin/env bash
# The Belton & Lichti classification with its defaults on scenes it was not tuned on:
# surface and edge F1 of pcl_ext_classify_variance against each scene's `class` field (a
# point is an edge within one scan spacing of a crease whose two faces were scanned, as
# pcl_ext_generate_scene marks it and pcl_ext_evaluate scores it), with the edges
# narrowed to their creases (the default) and as eq. 5 gives them (-wide_edges). One row
# per scene, then the mean of each family.
#
#   scripts/belton_lichti_classes.sh                       # indoor, building, pipes, seeds 4-10
#   SEEDS="1 2" FAMILIES="indoor" scripts/belton_lichti_classes.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"

build_dir="${BUILD_DIR:-$root/build}"
apps="$build_dir/apps"
seeds="${SEEDS:-4 5 6 7 8 9 10}"
families="${FAMILIES:-indoor building pipes}"
threads="${THREADS:-2}"

for app in generate_scene classify_variance evaluate; do
  if [ ! -x "$apps/pcl_ext_$app" ]; then
    echo "Missing $apps/pcl_ext_$app: build it first" \
      "(cmake --build $build_dir --target pcl_ext_$app)." >&2
    exit 1
  fi
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Surface F1 and edge F1 of pcl_ext_classify_variance with the given options.
scores() {
  local cloud="$1"
  shift
  "$apps/pcl_ext_classify_variance" "$cloud" "$work/out.pcd" -threads "$threads" "$@" \
    >"$work/classify.log" 2>&1
  "$apps/pcl_ext_evaluate" -classes "$work/out.pcd" "$cloud" -field lv_class |
    awk '$1 == 1 && $2 == "surface" {s = $7} $1 == 2 && $2 == "edge" {e = $7}
         END {print s, e}'
}

echo "| family | scene | surface F1 | edge F1 | surface F1, -wide_edges | edge F1, -wide_edges |"
echo "|---|---|---|---|---|---|"
for family in $families; do
  extra=()
  [ "$family" = building ] && extra=(-superfluous 2)
  for seed in $seeds; do
    "$apps/pcl_ext_generate_scene" "$family" "$work/scene.pcd" -seed "$seed" \
      -threads "$threads" "${extra[@]}" >/dev/null
    read -r s e < <(scores "$work/scene.pcd")
    read -r ws we < <(scores "$work/scene.pcd" -wide_edges)
    printf "| %s | seed %s | %.3f | %.3f | %.3f | %.3f |\n" "$family" "$seed" "$s" "$e" \
      "$ws" "$we"
    echo "$family $s $e $ws $we" >>"$work/rows.txt"
  done
done
echo
echo "| family | surface F1 | edge F1 | surface F1, -wide_edges | edge F1, -wide_edges |"
echo "|---|---|---|---|---|"
awk '{n[$1]++; s[$1]+=$2; e[$1]+=$3; ws[$1]+=$4; we[$1]+=$5;
      if (!($1 in o)) {o[$1]=++k; f[k]=$1}}
     END {for (i = 1; i <= k; ++i) {x = f[i];
       printf "| %s | %.3f | %.3f | %.3f | %.3f |\n", x, s[x]/n[x], e[x]/n[x],
              ws[x]/n[x], we[x]/n[x]}}' "$work/rows.txt"
