/*
 * pcl_ext fuzzing: the documented guarantees of the footprint readers.
 */
#pragma once

#include <pcl_ext/io/footprints.h>

#include "fuzz_input_file.h"

namespace pcl_ext_fuzz {
inline void
checkRing (const pcl_ext::io::Ring2d& ring)
{
  check (ring.size() >= 3, "a ring has at least 3 vertices");
  check (ring.front() != ring.back(), "a ring is stored open");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    check (ring[i].allFinite(), "vertices are finite");
    check (ring[i] != ring[(i + 1) % ring.size()], "no consecutive duplicate vertices");
  }
}

inline void
checkFootprints (const std::vector<pcl_ext::io::Footprint>& footprints)
{
  check (!footprints.empty(), "a successful read has footprints");
  for (const auto& f : footprints) {
    check (!f.polygons.empty(), "a footprint has a polygon");
    check (f.line >= 1, "a footprint names its line");
    for (const auto& polygon : f.polygons) {
      checkRing (polygon.outer);
      check (pcl_ext::io::signedArea (polygon.outer) >= 0.0,
             "the outer ring is counter-clockwise");
      for (const auto& hole : polygon.holes) {
        checkRing (hole);
        check (pcl_ext::io::signedArea (hole) <= 0.0, "holes are clockwise");
      }
    }
  }
}

/** Runs \a load on \a path; checks the guarantees on success and that the output is
 * untouched after a ReadError. */
template <typename Load>
void
checkLoad (Load&& load, const std::string& path)
{
  std::vector<pcl_ext::io::Footprint> footprints (1);
  footprints[0].id = "previous";
  try {
    load (path, footprints);
  }
  catch (const pcl_ext::io::ReadError&) {
    check (footprints.size() == 1 && footprints[0].id == "previous",
           "the output is untouched after a ReadError");
    return;
  }
  checkFootprints (footprints);
}
} // namespace pcl_ext_fuzz
