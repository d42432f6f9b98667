#!/usr/bin/env python3
"""Pools the scores of pcl_ext_crf_classify -truth logs: sums of true positives, supports
and predictions per class over the logs, then precision, recall and F1 per class, macro F1
and overall accuracy.

    scripts/crf_pool.py [-label NAME] LOG [LOG ...]

Each log's name up to '.classify.log' names its chunk. Prints one line per chunk (F1 per
class), the pooled per-class figures and a last line
'pooled NAME: overall accuracy A, macro F1 M, F1 class1 f1 class2 f2 ...' for tables.
"""
import os
import re
import sys

ROW = re.compile(r"^(\S+)\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)"
                 r"\s+(\d+)\s+(\d+)$")


def f1(p, r):
    return 2 * p * r / (p + r) if p + r > 0 else 0.0


def main(argv):
    label = "all"
    if len(argv) > 2 and argv[1] == "-label":
        label, argv = argv[2], argv[2:]
    logs = argv[1:]
    if not logs:
        print(__doc__)
        return 2
    tp, sup, pred, order = {}, {}, {}, []
    evaluated = 0
    for log in logs:
        chunk = os.path.basename(log).split(".classify.log")[0]
        line = []
        found = False
        for text in open(log):
            m = ROW.match(text.strip())
            if m:
                found = True
                name, s = m.group(1), int(m.group(2))
                p, r = float(m.group(3)), float(m.group(4))
                if name not in tp:
                    order.append(name)
                    tp[name] = sup[name] = pred[name] = 0
                tp[name] += int(m.group(8))
                sup[name] += s
                pred[name] += int(m.group(7))
                line.append(f"{name} {f1(p, r):.3f} ({s})")
            m = re.search(r"\((\d+) points evaluated", text)
            if m:
                evaluated += int(m.group(1))
        if not found:
            print(f"{log}: no scores", file=sys.stderr)
            return 1
        print(f"{chunk}: " + ", ".join(line))
    f1s = []
    for n in order:
        p = tp[n] / pred[n] if pred[n] else 0.0
        r = tp[n] / sup[n] if sup[n] else 0.0
        f1s.append(f1(p, r))
        print(f"  {n}: precision {p:.3f} recall {r:.3f} F1 {f1s[-1]:.3f}")
    oa = sum(tp.values()) / evaluated if evaluated else 0.0
    print(f"pooled {label}: overall accuracy {oa:.4f}, macro F1 {sum(f1s) / len(f1s):.4f}, "
          "F1 " + " ".join(f"{n} {v:.3f}" for n, v in zip(order, f1s)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
