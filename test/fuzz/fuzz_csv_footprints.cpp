/*
 * Fuzz target: pcl_ext::io::loadCsvFootprints (a header row, a WKT or JSON-coordinate
 * geometry column, RFC 4180 quoting).
 */
#include "fuzz_footprint_checks.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  pcl_ext_fuzz::checkLoad (pcl_ext::io::loadCsvFootprints, file.write (data, size));
  return 0;
}
