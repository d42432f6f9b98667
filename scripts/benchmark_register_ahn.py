#!/usr/bin/env python3
"""Khoshelham & Gorte registration with its defaults on the AHN3 tiles, moved.

  scripts/benchmark_register_ahn.py BUILD_DIR [-data DIR] [-tiles 2386_9702,2397_9705]
      [-keep DIR] [-cases N] [-- OPTIONS]

DIR is the folder amsterdam_ahn3_bgt_footprints of the shared data (default: from the
environment variable PCL_EXT_SHARED_DATA_DIR). Each tile's labelled cloud is turned about
its centre and shifted by each of eight known rigid transforms (yaw up to 5 degrees, tilt
up to 1 degree, shifts up to 3.6 m; the first is the one of the test
RegisterToMapAhn.Tile2397_9705WithTheDefaults), written in RD New with every BGT footprint
of the data set, and given to `pcl_ext_register_to_map cloud footprints out -transform_out
T.txt` with the options after `--` (none: the defaults). The error is that of the written
transform against the truth: the rotation angle, and the displacement of the moved
cloud's centre. Tile 2386_9702 is for tuning, 2397_9705 for the report. Prints one line
per case and the mean per tile. With -cases N (more than 8), the cases after the eight are
drawn from a fixed sequence (splitmix64 from seed 1) in the same ranges: yaw within 5
degrees, a tilt of up to 1 degree about a horizontal axis in any direction, shifts of up to
3.6 m; the result of one case can move by degrees when the cloud moves by a decimetre (the
walls the search matches change), so a mean over many cases says more than eight.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_register_building import errors, inverse_rigid, read_matrices  # noqa: E402

# yaw (degrees), tilt (degrees), tilt axis, shift x, shift y (metres)
PERTURBATIONS = [
    (3.0, 1.0, "x", 2.0, -1.5),
    (-3.0, 0.0, "x", -2.0, 1.0),
    (5.0, 0.5, "y", 1.0, 3.0),
    (-5.0, 1.0, "y", 3.0, 2.0),
    (2.0, 0.7, "x", -3.0, -2.0),
    (-1.0, 0.3, "y", 0.5, -3.5),
    (4.0, 0.0, "x", -1.0, -1.0),
    (-4.0, 1.0, "x", 2.5, 2.5),
]


def splitmix64(state):
    """The next state and a uniform value in [0, 1)."""
    state = (state + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
    z ^= z >> 31
    return state, (z >> 11) / float(1 << 53)


def drawn_perturbations(count):
    """count cases: yaw, tilt, tilt axis direction (degrees from x), shift x, shift y."""
    state, cases = 1, []
    for _ in range(count):
        values = []
        for _ in range(5):
            state, u = splitmix64(state)
            values.append(u)
        shift = 3.6 * math.sqrt(values[3])
        cases.append((10.0 * values[0] - 5.0, values[1], 360.0 * values[2],
                      shift * math.cos(2 * math.pi * values[4]),
                      shift * math.sin(2 * math.pi * values[4])))
    return cases


def tilt_rotation(axis, degrees):
    """A turn by degrees about the x or y axis, or about the horizontal axis at the given
    angle (degrees) from x."""
    if axis in ("x", "y"):
        return rotation(axis, degrees)
    a = math.radians(axis)
    return multiply(rotation("z", math.degrees(a)),
                    multiply(rotation("x", degrees), rotation("z", -math.degrees(a))))


def rotation(axis, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    if axis == "z":
        return [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    if axis == "x":
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    return [[c, 0, s], [0, 1, 0], [-s, 0, c]]


def multiply(a, b):
    n = len(b[0])
    return [[sum(a[r][k] * b[k][c] for k in range(len(b))) for c in range(n)]
            for r in range(len(a))]


def rigid(r, t):
    return [r[0] + [t[0]], r[1] + [t[1]], r[2] + [t[2]], [0, 0, 0, 1]]


def read_cloud(path):
    """x y z label of an ASCII PCD file, and the origin its header says was taken off."""
    origin = [0.0, 0.0, 0.0]
    fields, points = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                m = re.search(r"subtract-origin x=([-0-9.]+) y=([-0-9.]+) z=([-0-9.]+)", line)
                if m:
                    origin = [float(v) for v in m.groups()]
            elif line.startswith("FIELDS"):
                fields = line.split()[1:]
            elif line.startswith("DATA"):
                if line.split()[1] != "ascii":
                    sys.exit("%s: only ASCII PCD files are read here" % path)
                break
        ix, iy, iz, il = (fields.index(k) for k in ("x", "y", "z", "label"))
        for line in f:
            v = line.split()
            if len(v) == len(fields):
                points.append((float(v[ix]), float(v[iy]), float(v[iz]), v[il]))
    return points, origin


def write_footprints(csv, path):
    """The BGT polygons of the data set's CSV as text footprints: id n x1 y1 ... xn yn."""
    number = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
    count = 0
    with open(csv) as f, open(path, "w") as out:
        for line in f:
            a, b = line.find("[["), line.find("]]")
            if a < 0 or b < 0:
                continue
            values = number.findall(line[a:b])
            out.write("%d %d %s\n" % (count, len(values) // 2, " ".join(values)))
            count += 1
    return count


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    build = argv[0]
    args = {"data": os.path.join(os.environ.get("PCL_EXT_SHARED_DATA_DIR", ""),
                                 "amsterdam_ahn3_bgt_footprints"),
            "tiles": "2386_9702,2397_9705", "keep": "", "cases": "8"}
    for i in range(1, len(argv), 2):
        key = argv[i].lstrip("-")
        if key not in args or i + 1 >= len(argv):
            sys.exit("unknown or incomplete option %s\n%s" % (argv[i], __doc__))
        args[key] = argv[i + 1]
    cases = int(args["cases"])
    perturbations = PERTURBATIONS[:cases] + drawn_perturbations(max(0, cases - 8))
    register = os.path.join(build, "apps", "pcl_ext_register_to_map")
    folder = args["keep"] or tempfile.mkdtemp(prefix="kg_ahn_")
    os.makedirs(folder, exist_ok=True)
    footprints = os.path.join(folder, "footprints.txt")
    if write_footprints(os.path.join(args["data"], "bgt_buildings_demo.csv"), footprints) == 0:
        sys.exit("no footprints in %s" % args["data"])
    status = 0
    for tile in args["tiles"].split(","):
        points, origin = read_cloud(os.path.join(args["data"], "ahn_%s.pcd" % tile))
        centre = [sum(p[k] for p in points) / len(points) for k in range(3)]
        rotations, translations = [], []
        for case, (yaw, tilt, axis, dx, dy) in enumerate(perturbations, 1):
            r = multiply(rotation("z", yaw), tilt_rotation(axis, tilt))
            rc = [sum(r[i][k] * centre[k] for k in range(3)) for i in range(3)]
            # Turned about the centre, shifted in plan: the centre keeps its height.
            move = rigid(r, [centre[0] + dx - rc[0], centre[1] + dy - rc[1],
                             centre[2] - rc[2]])
            stem = os.path.join(folder, "%s_%d" % (tile, case))
            with open(stem + ".pcd", "w") as out:
                out.write("VERSION 0.7\nFIELDS x y z label\nSIZE 8 8 8 4\nTYPE F F F U\n"
                          "COUNT 1 1 1 1\nWIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
                          "POINTS %d\nDATA ascii\n" % (len(points), len(points)))
                for x, y, z, label in points:
                    q = [sum(move[i][k] * (x, y, z)[k] for k in range(3)) + move[i][3]
                         + origin[i] for i in range(3)]
                    out.write("%.4f %.4f %.4f %s\n" % (q[0], q[1], q[2], label))
            # The truth takes the moved cloud (in RD New) back.
            shift = rigid(rotation("z", 0), origin)
            unshift = rigid(rotation("z", 0), [-v for v in origin])
            truth = inverse_rigid(multiply(shift, multiply(move, unshift)))
            moved_centre = [sum(move[i][k] * centre[k] for k in range(3)) + move[i][3]
                            + origin[i] for i in range(3)]
            transform = stem + ".estimated.txt"
            if os.path.exists(transform):
                os.remove(transform)
            run = subprocess.run([register, stem + ".pcd", footprints, stem + ".out.pcd",
                                  "-transform_out", transform] + extra,
                                 capture_output=True, text=True)
            if run.returncode != 0 or not os.path.exists(transform):
                print("%s case %d: exit %d | %s" % (tile, case, run.returncode,
                      (run.stderr.strip().splitlines() or [""])[-1][:100]), flush=True)
                status = 2
                continue
            estimate = read_matrices(transform)[0]
            # errors() measures where each transform puts the scan point that the truth
            # puts at the reference: the reference is the truth's image of the centre.
            reference = [sum(truth[i][k] * moved_centre[k] for k in range(3)) + truth[i][3]
                         for i in range(3)]
            rot, trans = errors(estimate, truth, reference)
            # The rotation error split: the tilt (how far the estimate moves the true
            # vertical) and the turn about the vertical.
            e = multiply([row[:3] for row in estimate[:3]],
                         [[truth[c][r] for c in range(3)] for r in range(3)])
            tilt_error = math.degrees(math.acos(max(-1.0, min(1.0, e[2][2]))))
            yaw_error = math.degrees(math.atan2(e[1][0] - e[0][1], e[0][0] + e[1][1]))
            rotations.append(rot)
            translations.append(trans)
            axis_name = axis if isinstance(axis, str) else "%.0f deg" % axis
            print("%s case %d (yaw %+.1f, tilt %.1f about %s, shift %+.1f %+.1f): rotation "
                  "%.2f deg (yaw %+.2f, tilt %.2f), translation %.2f m" % (
                      tile, case, yaw, tilt, axis_name, dx, dy, rot, yaw_error, tilt_error,
                      trans),
                  flush=True)
        if rotations:
            ordered = sorted(rotations)
            median = 0.5 * (ordered[(len(ordered) - 1) // 2] + ordered[len(ordered) // 2])
            within = sum(1 for r, t in zip(rotations, translations) if r < 1.0 and t < 0.5)
            print("%s: mean rotation %.2f deg (median %.2f, worst %.2f), mean translation "
                  "%.2f m (worst %.2f), %d of %d registered, %d within 1 deg and 0.5 m%s" % (
                      tile, sum(rotations) / len(rotations), median, max(rotations),
                      sum(translations) / len(translations), max(translations),
                      len(rotations), len(perturbations), within,
                      " (options: %s)" % " ".join(extra) if extra else ""), flush=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
