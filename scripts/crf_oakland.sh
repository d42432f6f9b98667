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
python3 - "$out" $test <<'EOF'
import re, sys
out, chunks = sys.argv[1], sys.argv[2:]
tp, sup, pred, order = {}, {}, {}, []
evaluated = 0
def f1(p, r):
    return 2 * p * r / (p + r) if p + r > 0 else 0.0
row = re.compile(r"^(\S+)\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)"
                 r"\s+(\d+)\s+(\d+)$")
for c in chunks:
    line = []
    for text in open(f"{out}/{c}.classify.log"):
        m = row.match(text.strip())
        if m:
            name, s, p, r = m.group(1), int(m.group(2)), float(m.group(3)), float(m.group(4))
            if name not in tp:
                order.append(name)
            tp[name] = tp.get(name, 0) + int(m.group(8))
            sup[name] = sup.get(name, 0) + s
            pred[name] = pred.get(name, 0) + int(m.group(7))
            line.append(f"{name} {f1(p, r):.3f}")
        m = re.search(r"\((\d+) points evaluated", text)
        if m:
            evaluated += int(m.group(1))
    print(f"{c}: " + ", ".join(line))
f1s = []
for n in order:
    p = tp[n] / pred[n] if pred[n] else 0.0
    r = tp[n] / sup[n] if sup[n] else 0.0
    f1s.append(f1(p, r))
    print(f"  {n}: precision {p:.3f} recall {r:.3f} F1 {f1s[-1]:.3f}")
print(f"pooled: overall accuracy {sum(tp.values()) / evaluated:.4f}, "
      f"macro F1 {sum(f1s) / len(f1s):.4f}")
EOF
