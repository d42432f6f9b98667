#!/usr/bin/env bash
# Leave-one-chunk-out cross-validation of the multi-scale CRF on Oakland's seven part3 chunks:
# for each chunk, pcl_ext_crf_train on the six others, pcl_ext_crf_classify -truth on it; once
# with -mode mcrf and once with -mode node (the same node model, the same options otherwise).
# Scores are pooled over the seven held-out chunks (scripts/crf_pool.py).
#
#   scripts/crf_oakland_cv.sh BUILD_DIR DATA_DIR OUT_DIR [train options]
#
# DATA_DIR holds oakland_part3_*.xyz_label_conf and classes.txt. MODES (default "mcrf node")
# and CHUNKS (default the seven part3 chunks) may be set in the environment. Prints each fold's
# training time and F1 per class, then per mode the pooled figures; writes the models, logs
# and outputs to OUT_DIR/MODE/CHUNK/.
set -euo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,12p' "${BASH_SOURCE[0]}"
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="$1" data="$2" out="$3"
shift 3
chunks="${CHUNKS:-part3_aj part3_ak part3_al part3_am part3_an part3_ao part3_ap}"
modes="${MODES:-mcrf node}"
classes="$data/classes.txt"
for mode in $modes; do
  logs=()
  for held in $chunks; do
    dir="$out/$mode/$held"
    mkdir -p "$dir"
    inputs=()
    for c in $chunks; do
      [ "$c" = "$held" ] || inputs+=("$data/oakland_$c.xyz_label_conf")
    done
    start=$(date +%s.%N)
    "$build/apps/pcl_ext_crf_train" -o "$dir/model.txt" -classes "$classes" "$@" \
      -mode "$mode" "${inputs[@]}" > "$dir/train.log"
    trained=$(date +%s.%N)
    "$build/apps/pcl_ext_crf_classify" "$dir/model.txt" "$data/oakland_$held.xyz_label_conf" \
      "$dir/$held.pcd" -classes "$classes" -truth > "$dir/$held.classify.log"
    done_at=$(date +%s.%N)
    printf '%s, held out %s: training %.1f s, classification %.1f s\n' "$mode" "$held" \
      "$(echo "$trained - $start" | bc)" "$(echo "$done_at - $trained" | bc)"
    logs+=("$dir/$held.classify.log")
  done
  python3 "$here/crf_pool.py" -label "$mode" "${logs[@]}"
done
