#!/usr/bin/env python3
"""Writes the C++ examples of README.md as one source file, so that the build compiles them.

    readme_snippets.py README.md out.cpp

Every ```cpp block becomes a scope of one function, its #include lines go to the top; the
variables the examples take as given (cloud, scan, training_cloud, training_labels) are the
function's parameters.
"""
import re
import sys

readme, output = sys.argv[1], sys.argv[2]
blocks = re.findall(r"^```cpp\n(.*?)^```", open(readme, encoding="utf-8").read(), re.S | re.M)
includes, bodies = ["#include <pcl/point_types.h>"], []
for block in blocks:
    body = []
    for line in block.splitlines():
        if line.startswith("#include"):
            if line not in includes:
                includes.append(line)
        else:
            body.append("  " + line if line else "")
    bodies.append("  {\n" + "\n".join(body) + "\n  }")
source = "\n".join(
    ["// Generated from README.md by test/apps/readme_snippets.py: the README's C++ examples."]
    + includes
    + [
        "",
        "void",
        "readmeExamples (pcl::PointCloud<pcl::PointXYZ>::Ptr cloud,",
        "                pcl::PointCloud<pcl::PointXYZ>::Ptr scan,",
        "                pcl::PointCloud<pcl::PointXYZ>::Ptr training_cloud,",
        "                std::vector<std::uint32_t> training_labels)",
        "{",
    ]
    + bodies
    + ["}", ""]
)
if len(blocks) < 5:
    sys.exit("readme_snippets.py: %s has %d C++ examples, expected one per method"
             % (readme, len(blocks)))
with open(output, "w", encoding="utf-8") as f:
    f.write(source)
