/*
 * Fuzz target: pcl_ext::io::loadWktFootprints (one [id] POLYGON / MULTIPOLYGON per
 * line) and parseWkt.
 */
#include "fuzz_footprint_checks.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  pcl_ext_fuzz::checkLoad (pcl_ext::io::loadWktFootprints, file.write (data, size));
  return 0;
}
