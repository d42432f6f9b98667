#!/usr/bin/env bash
# The Belton & Lichti segmentation with its defaults against stock PCL region growing and
# CGAL's plane region growing, on scenes it was not tuned on: mean best IoU per scene, one
# row per scene, then the mean of each family.
#
#   scripts/belton_lichti_table.sh                 # indoor, building, pipes, street at
#                                                  # seeds 4-10, and the mOSD learn frames
#   SEEDS="4 5" FAMILIES="indoor pipes" scripts/belton_lichti_table.sh
#   SEGMENT_OPTIONS="-preset derived" scripts/belton_lichti_table.sh
#
# pcl_ext: `pcl_ext_segment_variance in out $SEGMENT_OPTIONS` (none: the defaults), scored
# by pcl_ext_evaluate.
# PCL: pcl::NormalEstimationOMP + pcl::RegionGrowing through pcl_ext_compare_segmenters,
# set as PCL's region growing tutorial sets them: normals of the 50 nearest neighbours,
# growing over the 30 nearest, smoothness 3 degrees, curvature threshold 1.0, segments of
# at least 50 points.
# CGAL: Shape_detection::Region_growing with Least_squares_plane_fit_region through
# pcl_ext_compare_segmenters (-methods cgal_planes), its documented defaults (PCA normals
# and growing over the 12 nearest, 25 degrees), distance to the plane twice the point
# spacing, segments of at least 50 points (CGAL's column is empty in a build without CGAL).
# The mOSD frames are read from $PCL_EXT_SHARED_DATA_DIR/mosd_object_segmentation when
# the folder exists (truth field 'label'). PCL_FROM=<an earlier table of this script>
# takes the PCL column from it instead of running PCL again (the scenes are the same for
# a seed, and the PCL pipeline does not change with pcl_ext); CGAL_FROM=<an earlier
# table> takes the CGAL column from it in the same way.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"

build_dir="${BUILD_DIR:-$root/build}"
apps="$build_dir/apps"
seeds="${SEEDS:-4 5 6 7 8 9 10}"
families="${FAMILIES:-indoor building pipes street}"
threads="${THREADS:-1}"
mosd_dir="${PCL_EXT_SHARED_DATA_DIR:-}/mosd_object_segmentation"

family="" name=""
for app in generate_scene segment_variance evaluate compare_segmenters; do
  if [ ! -x "$apps/pcl_ext_$app" ]; then
    echo "Missing $apps/pcl_ext_$app: build it first" \
      "(cmake --build $build_dir --target pcl_ext_$app)." >&2
    exit 1
  fi
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Mean best IoU of pcl_ext_segment_variance with its defaults.
ours() {
  local cloud="$1" truth_field="$2"
  # shellcheck disable=SC2086 # the options are words
  "$apps/pcl_ext_segment_variance" "$cloud" "$work/out.pcd" -output_field result \
    -threads "$threads" ${SEGMENT_OPTIONS:-} >"$work/ours.log" 2>&1
  "$apps/pcl_ext_evaluate" "$work/out.pcd" "$cloud" -segments -field result \
    -truth_field "$truth_field" -rows 0 | awk '/^ *mean best IoU/ {print $4}'
}

# Mean best IoU of pcl::RegionGrowing as the issue's baseline sets it.
theirs() {
  local cloud="$1" truth_field="$2"
  if [ -n "${PCL_FROM:-}" ]; then
    awk -F' *[|] *' -v f="$family" -v s="$name" '$2 == f && $3 == s {print $5}' \
      "$PCL_FROM"
    return
  fi
  "$apps/pcl_ext_compare_segmenters" "$cloud" -truth_field "$truth_field" \
    -methods region_growing -normal_k 50 -k 30 -angle 3 -curvature 1.0 -min_size 50 \
    -threads "$threads" | awk '$1 == "region_growing" {print $5}'
}

# Mean best IoU of CGAL's plane region growing (nothing without CGAL).
cgal() {
  local cloud="$1" truth_field="$2"
  if [ -n "${CGAL_FROM:-}" ]; then
    awk -F' *[|] *' -v f="$family" -v s="$name" '$2 == f && $3 == s {print $6}' \
      "$CGAL_FROM"
    return
  fi
  "$apps/pcl_ext_compare_segmenters" "$cloud" -truth_field "$truth_field" \
    -methods cgal_planes -plane_distance 2 -min_size 50 -threads "$threads" 2>/dev/null |
    awk '$1 == "cgal_planes" {print $5}' || true
}

row() {
  family="$1" name="$2"
  local cloud="$3" truth_field="$4" a b c
  a="$(ours "$cloud" "$truth_field")"
  b="$(theirs "$cloud" "$truth_field")"
  c="$(cgal "$cloud" "$truth_field")"
  awk -v f="$family" -v s="$name" -v a="$a" -v b="$b" -v c="${c:-nan}" \
    'BEGIN {printf "| %s | %s | %.3f | %.3f | %.3f | %+.3f | %+.3f |\n", f, s, a, b, c,
            a - b, a - c}'
  echo "$family $a $b ${c:-nan}" >>"$work/rows.txt"
}

echo "| family | scene | pcl_ext_segment_variance | pcl::RegionGrowing | CGAL region growing |" \
  "difference (PCL) | difference (CGAL) |"
echo "|---|---|---|---|---|---|---|"
for family in $families; do
  extra=()
  [ "$family" = building ] && extra=(-superfluous 2)
  for seed in $seeds; do
    "$apps/pcl_ext_generate_scene" "$family" "$work/scene.pcd" -seed "$seed" \
      -threads "$threads" "${extra[@]}" >/dev/null
    row "$family" "seed $seed" "$work/scene.pcd" segment
  done
done
if [ -d "$mosd_dir" ]; then
  for frame in learn0 learn20 learn35; do
    [ -f "$mosd_dir/$frame.pcd" ] && row mOSD "$frame" "$mosd_dir/$frame.pcd" label
  done
fi
echo
echo "| family | pcl_ext_segment_variance | pcl::RegionGrowing | CGAL region growing |" \
  "difference (PCL) | difference (CGAL) |"
echo "|---|---|---|---|---|---|"
awk '{n[$1]++; a[$1]+=$2; b[$1]+=$3; c[$1]+=$4; if (!($1 in o)) {o[$1]=++k; f[k]=$1}}
     END {for (i = 1; i <= k; ++i) {x = f[i];
       printf "| %s | %.3f | %.3f | %.3f | %+.3f | %+.3f |\n", x, a[x]/n[x], b[x]/n[x],
              c[x]/n[x], (a[x]-b[x])/n[x], (a[x]-c[x])/n[x]}}' \
  "$work/rows.txt"
