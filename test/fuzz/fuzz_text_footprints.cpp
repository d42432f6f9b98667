/*
 * Fuzz target: pcl_ext::io::loadTextFootprints (id n x1 y1 ... xn yn per line), and
 * loadFootprints, which tells the format from the content when the name has no known
 * extension (the path here has none).
 */
#include "fuzz_footprint_checks.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  const std::string& path = file.write (data, size);
  pcl_ext_fuzz::checkLoad (pcl_ext::io::loadTextFootprints, path);
  pcl_ext_fuzz::checkLoad (pcl_ext::io::loadFootprints, path);
  return 0;
}
