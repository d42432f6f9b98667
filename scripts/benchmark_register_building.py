#!/usr/bin/env python3
"""Khoshelham & Gorte registration with its defaults on generated buildings.

  scripts/benchmark_register_building.py BUILD_DIR [-seeds 6-50] [-noise 0.005]
      [-max_rotation 0.2] [-max_translation 0.05] [-max_mean 0] [-keep DIR] [-- OPTIONS]

For every seed: `pcl_ext_generate_scene building` with that seed and noise (every other
option at its default: the H plan, a random pose with up to 10 degrees of tilt), then
`pcl_ext_register_to_map scan footprint out -transform_out T.txt` with the options after
`--` (none: the defaults). A seed succeeds when the tool exits 0 and the transform it
writes (or, for an ambiguous footprint, one of the candidates it writes) is within the
rotation and translation bounds of the scene's true transform, and the mean distance of
the matched planes (Tables 1-2) is within -max_mean (0: not checked). The translation
error is the displacement of the footprint's centre at half the wall height. Prints one
line per seed and the success rate. With -keep DIR the scenes are kept there and reused
by the next run.
"""
import math
import os
import re
import subprocess
import sys
import tempfile


def parse_args(argv):
    args = {"seeds": "6-50", "noise": "0.005", "max_rotation": "0.2",
            "max_translation": "0.05", "max_mean": "0", "keep": ""}
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    build = argv[0]
    i = 1
    while i < len(argv):
        key = argv[i].lstrip("-")
        if key not in args or i + 1 >= len(argv):
            sys.exit("unknown or incomplete option %s\n%s" % (argv[i], __doc__))
        args[key] = argv[i + 1]
        i += 2
    first, _, last = args["seeds"].partition("-")
    seeds = range(int(first), int(last or first) + 1)
    return build, seeds, args, extra


def read_matrices(path):
    """Every 4 x 4 matrix in a text file ('#' lines separate candidates)."""
    numbers, matrices = [], []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line:
                numbers += [float(v) for v in line.replace(",", " ").split()]
    for i in range(0, len(numbers) - 15, 16):
        matrices.append([numbers[i + 4 * r:i + 4 * r + 4] for r in range(4)])
    return matrices


def apply(t, p):
    return [sum(t[r][c] * p[c] for c in range(3)) + t[r][3] for r in range(3)]


def inverse_rigid(t):
    r = [[t[c][r] for c in range(3)] for r in range(3)]
    x = [-sum(r[i][c] * t[c][3] for c in range(3)) for i in range(3)]
    return [r[0] + [x[0]], r[1] + [x[1]], r[2] + [x[2]], [0, 0, 0, 1]]


def errors(estimate, truth, centre):
    # Rotation: the angle of R_est^T R_true; translation: where each puts the scan
    # point that the truth puts at the footprint's centre.
    trace = sum(estimate[c][r] * truth[c][r] for r in range(3) for c in range(3))
    rotation = math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1.0) / 2.0))))
    p = apply(inverse_rigid(truth), centre)
    q = apply(estimate, p)
    return rotation, math.dist(q, centre)


def footprint_centre(path):
    text = open(path).read()
    values = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:[eE]-?\d+)?", text)]
    xs, ys = values[0::2], values[1::2]
    return [(min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, 5.0]


def main():
    build, seeds, args, extra = parse_args(sys.argv[1:])
    generate = os.path.join(build, "apps", "pcl_ext_generate_scene")
    register = os.path.join(build, "apps", "pcl_ext_register_to_map")
    folder = args["keep"] or tempfile.mkdtemp(prefix="kg_building_")
    os.makedirs(folder, exist_ok=True)
    max_rotation = float(args["max_rotation"])
    max_translation = float(args["max_translation"])
    max_mean = float(args["max_mean"])
    good = 0
    for seed in seeds:
        stem = os.path.join(folder, "building_%s_%d" % (args["noise"], seed))
        if not os.path.exists(stem + ".transform.txt"):  # kept scenes are reused
            subprocess.run([generate, "building", stem + ".pcd", "-seed", str(seed),
                            "-noise", args["noise"]], check=True, capture_output=True)
        out = stem + ".registered.pcd"
        transform = stem + ".estimated.txt"
        for stale in (out, transform):
            if os.path.exists(stale):
                os.remove(stale)
        run = subprocess.run([register, stem + ".pcd", stem + ".footprint.wkt", out,
                              "-transform_out", transform] + extra,
                             capture_output=True, text=True)
        truth = read_matrices(stem + ".transform.txt")[0]
        mean = re.search(r"Plane distances .*?: mean ([0-9.]+)", run.stdout)
        mean = float(mean.group(1)) if mean else float("inf")
        best = (float("inf"), float("inf"))
        if run.returncode == 0 and os.path.exists(transform):
            centre = footprint_centre(stem + ".footprint.wkt")
            for estimate in read_matrices(transform):
                e = errors(estimate, truth, centre)
                if e[0] <= max_rotation and e[1] <= max_translation:
                    best = e
                    break
                best = min(best, e)
        ok = (best[0] <= max_rotation and best[1] <= max_translation and
              (max_mean <= 0 or mean <= max_mean))
        good += ok
        last = (run.stderr.strip().splitlines() or [""])[-1]
        print("seed %3d: exit %d, rotation %8.3f deg, translation %8.3f m, mean plane "
              "distance %.3f m %s%s" % (seed, run.returncode, best[0], best[1], mean,
                                        "ok" if ok else "FAIL",
                                        "" if ok else " | " + last[:100]), flush=True)
    print("%d of %d seeds within %g deg and %g m%s (noise %s m, options: %s)" % (
        good, len(seeds), max_rotation, max_translation,
        " and mean %g m" % max_mean if max_mean > 0 else "", args["noise"],
        " ".join(extra) or "defaults"))
    return 0 if good == len(seeds) else 2


if __name__ == "__main__":
    sys.exit(main())
