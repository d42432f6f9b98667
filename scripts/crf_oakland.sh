#!/usr/bin/env bash
# Trains the multi-scale CRF on Oakland chunks with pcl_ext_crf_train, classifies other chunks
# with pcl_ext_crf_classify -truth (which scores them as pcl_ext_evaluate -classes does) and
# pools the scores (sums of true positives, supports and predictions over the chunks).
#
#   scripts/crf_oakland.sh BUILD_DIR DATA_DIR OUT_DIR "TRAIN_CHUNKS" "TEST_CHUNKS" [train options]
#
# Chunks are Oakland names such as part3_am; DATA_DIR holds oakland_<chunk>.xyz_label_conf and
# classes.txt. Prints the training time, one line per test chunk and the pooled overall
# accuracy, macro F1 and per-class precision, recall and F1; writes the model and the outputs
# to OUT_DIR.
set -euo pipefail
if [ $# -lt 5 ]; then
  sed -n '2,11p' "${BASH_SOURCE[0]}"
  exit 2
fi
build="$1" data="$2" out="$3" train="$4" test="$5"
shift 5
mkdir -p "$out"
classes="$data/classes.txt"
inputs=()
for c in $train; do inputs+=("$data/oakland_$c.xyz_label_conf"); done
start=$(date +%s)
"$build/apps/pcl_ext_crf_train" -o "$out/model.txt" -classes "$classes" "$@" "${inputs[@]}" \
  > "$out/train.log"
echo "training: $(($(date +%s) - start)) s"
for c in $test; do
  "$build/apps/pcl_ext_crf_classify" "$out/model.txt" "$data/oakland_$c.xyz_label_conf" \
    "$out/$c.pcd" -classes "$classes" -truth > "$out/$c.classify.log"
done
logs=()
for c in $test; do logs+=("$out/$c.classify.log"); done
python3 "$(dirname "${BASH_SOURCE[0]}")/crf_pool.py" "${logs[@]}"
