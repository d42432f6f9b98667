/*
 * Fuzz target: pcl_ext::io::ClassMapping::load (class id, name, source labels per
 * line).
 */
#include <pcl_ext/io/class_mapping.h>

#include "fuzz_input_file.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  pcl_ext::io::ClassMapping mapping;
  mapping.addClass (7, "previous", {7001});
  try {
    mapping.load (file.write (data, size));
  }
  catch (const pcl_ext::io::ReadError&) {
    pcl_ext_fuzz::check (mapping.size() == 1 && mapping.map (7001) == 7,
                         "the mapping is unchanged after a ReadError");
    return 0;
  }
  using pcl_ext_fuzz::check;
  check (!mapping.empty(), "a successful read has classes");
  for (const auto& entry : mapping.names())
    check (entry.first != 0, "class ids are positive");
  return 0;
}
