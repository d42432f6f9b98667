#!/usr/bin/env python3
"""The layout rules of the tree, checked from its files and CMake's dependency graph.

  scripts/check_layout.py [BUILD_DIR]

- the libraries' dependency graph (cmake --graphviz) has no cycle, and no method library
  (features, segmentation, registration, classification) depends on evaluation, simulation,
  visualization or the apps' framework;
- no header of one method module includes another method module's impl/ file;
- no source, header or CMake file in the tree is longer than 600 lines;
- no library code prints (std::cout, std::cerr, printf): libraries report through PCL_ERROR,
  PCL_WARN and PCL_DEBUG;
- every C++ file is formatted as .clang-format says (clang-format --dry-run -Werror).
Exits non-zero and names every breach.
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
METHODS = ["features", "segmentation", "registration", "classification"]
LIBRARY_DIRS = METHODS + ["pcl_ext"]
NOT_FOR_METHODS = {"pcl_ext_evaluation", "pcl_ext_simulation", "pcl_ext_visualization",
                   "pcl_ext_apps_common"}
MAX_LINES = 600


def tracked_files():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    return [f for f in out.splitlines() if os.path.isfile(os.path.join(ROOT, f))]


def dependency_graph(build_dir):
    dot = os.path.join(build_dir, "pcl_ext_dependencies.dot")
    subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "--graphviz=" + dot],
                   check=True, stdout=subprocess.DEVNULL)
    text = open(dot).read()
    names = {m.group(1): m.group(2).split("\\n")[0]
             for m in re.finditer(r'"(node\d+)" \[ label = "([^"]+)"', text)}
    graph = {}
    for m in re.finditer(r'"(node\d+)" -> "(node\d+)"', text):
        a, b = names[m.group(1)], names[m.group(2)]
        if a.startswith("pcl_ext") and b.startswith("pcl_ext"):
            graph.setdefault(a, set()).add(b)
    return graph


def check_graph(graph, errors):
    state = {}

    def visit(node, path):
        state[node] = 1
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                errors.append("dependency cycle: " + " -> ".join(path + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    for method in METHODS:
        for dep in sorted(graph.get("pcl_ext_" + method, ())):
            if dep in NOT_FOR_METHODS:
                errors.append("method library pcl_ext_%s depends on %s" % (method, dep))


def main():
    errors = []
    files = tracked_files()
    code = [f for f in files if re.search(r"\.(h|hpp|cpp)$", f)]
    for f in files:
        if re.search(r"\.(h|hpp|cpp|py|sh|cmake)$|CMakeLists\.txt$", f):
            n = sum(1 for _ in open(os.path.join(ROOT, f), errors="replace"))
            if n > MAX_LINES:
                errors.append("%s: %d lines (at most %d)" % (f, n, MAX_LINES))
    for f in code:
        top = f.split("/")[0]
        if top not in LIBRARY_DIRS:
            continue
        text = open(os.path.join(ROOT, f), errors="replace").read()
        for i, line in enumerate(text.splitlines(), 1):
            if re.search(r"std::(cout|cerr)|(?<![\w:])f?printf\s*\(", line):
                errors.append("%s:%d: library code prints: %s" % (f, i, line.strip()))
            m = re.match(r"\s*#include <pcl_ext/(\w+)/impl/", line)
            if m and top in METHODS and m.group(1) in METHODS and m.group(1) != top:
                errors.append("%s:%d: includes another method module's impl/ file" % (f, i))
    for i in range(0, len(code), 50):
        run = subprocess.run(["clang-format", "--dry-run", "-Werror"] + code[i:i + 50],
                             cwd=ROOT, capture_output=True, text=True)
        if run.returncode != 0:
            for f in sorted(set(re.findall(r"^([^\s:]+\.(?:h|hpp|cpp)):\d+", run.stderr, re.M))):
                errors.append("%s: not formatted (clang-format -i %s)" % (f, f))
    with tempfile.TemporaryDirectory() as build_dir:
        check_graph(dependency_graph(sys.argv[1] if len(sys.argv) > 1 else build_dir), errors)
    for e in errors:
        print(e)
    print("layout: %d problem(s)" % len(errors))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
