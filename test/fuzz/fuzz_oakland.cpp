/*
 * Fuzz target: pcl_ext::io::loadOaklandFile (x y z label confidence per line).
 */
#include <pcl_ext/io/ascii_reader.h>

#include "fuzz_input_file.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  pcl_ext::io::PointTable table;
  try {
    pcl_ext::io::loadOaklandFile (file.write (data, size), table);
  }
  catch (const pcl_ext::io::ReadError&) {
    pcl_ext_fuzz::check (table.empty(), "the table is untouched after a ReadError");
    return 0;
  }
  using pcl_ext_fuzz::check;
  check (!table.empty(), "a successful read has points");
  check (table.label.size() == table.size(), "one label per point");
  check (table.intensity.empty() && table.rgb.empty(), "no other attribute");
  for (const auto& p : table.xyz)
    check (p.allFinite(), "coordinates are finite");
  return 0;
}
