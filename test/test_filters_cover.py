#!/usr/bin/env python3
"""Checks that the ctest entries of a test program run each of its tests exactly once.

  test_filters_cover.py PROGRAM FILTER...

PROGRAM is a folder's test program (test/CMakeLists.txt, pcl_ext_add_test), FILTER the
--gtest_filter of each of its ctest entries. A test no filter matches would never run; one
that two match would run twice. Exits 1 naming them.
"""
import subprocess
import sys


def listed(program, gtest_filter=None):
    command = [program, "--gtest_list_tests"]
    if gtest_filter is not None:
        command.append("--gtest_filter=" + gtest_filter)
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    names, suite = [], ""
    for line in out.splitlines():
        if not line.strip():
            continue
        if line.startswith(" "):
            names.append(suite + line.split()[0])
        else:
            suite = line.split()[0]
    return names


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    program, filters = argv[0], argv[1:]
    runs = {name: 0 for name in listed(program)}
    for gtest_filter in filters:
        for name in listed(program, gtest_filter):
            runs[name] += 1
    wrong = sorted(name for name, count in runs.items() if count != 1)
    for name in wrong:
        print("%s: %s is run by %d ctest entries" % (program, name, runs[name]))
    print("%s: %d tests, %d ctest entries" % (program, len(runs), len(filters)))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
