#!/usr/bin/env python3
"""Checks that the ctest entries of a test program run each of its tests exactly once.

  test_filters_cover.py PROGRAM FILTER...

PROGRAM is a folder's test program (test/CMakeLists.txt, pcl_ext_add_test), FILTER the
--gtest_filter of each of its ctest entries. A test no filter matches would never run; one
that two match would run twice. Exits 1 naming them.
"""
import fnmatch
import subprocess
import sys


def listed(program):
    out = subprocess.run([program, "--gtest_list_tests"], check=True, capture_output=True,
                         text=True).stdout
    names, suite = [], ""
    for line in out.splitlines():
        if not line.strip():
            continue
        if line.startswith(" "):
            names.append(suite + line.split()[0])
        else:
            suite = line.split()[0]
    return names


def matches(name, gtest_filter):
    """gtest's positive filter: patterns joined by ':', with the wildcards * and ?."""
    return any(fnmatch.fnmatchcase(name, pattern) for pattern in gtest_filter.split(":"))


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    program, filters = argv[0], argv[1:]
    runs = {name: 0 for name in listed(program)}
    for gtest_filter in filters:
        for name in runs:
            runs[name] += matches(name, gtest_filter)
    wrong = sorted(name for name, count in runs.items() if count != 1)
    for name in wrong:
        print("%s: %s is run by %d ctest entries" % (program, name, runs[name]))
    print("%s: %d tests, %d ctest entries" % (program, len(runs), len(filters)))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
