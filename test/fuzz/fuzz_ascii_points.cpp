/*
 * Fuzz target: pcl_ext::io::loadAsciiPoints, parseColumnSpec and the conversion to a
 * cloud.
 *
 * The first byte chooses the column spec: one of a few fixed specs, or (selector 0) the
 * first line of the input, the rest being the file.
 */
#include <pcl_ext/io/ascii_reader.h>

#include "fuzz_input_file.h"

#include <cmath>
#include <stdexcept>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  if (size == 0)
    return 0;
  static const char* const specs[] = {
      "", "x,y,z,i,r,g,b,label", "x y z label _", "_,x,y,z,r,g,b"};
  const std::uint8_t selector = data[0] % 5;
  ++data;
  --size;
  std::string spec;
  if (selector == 0) {
    std::size_t end = 0;
    while (end < size && data[end] != '\n')
      ++end;
    spec.assign (reinterpret_cast<const char*> (data), end);
    try {
      pcl_ext::io::parseColumnSpec (spec);
    }
    catch (const std::invalid_argument&) {
    }
    if (end < size)
      ++end;
    data += end;
    size -= end;
  }
  else
    spec = specs[selector - 1];

  pcl_ext::io::PointTable table;
  try {
    pcl_ext::io::loadAsciiPoints (file.write (data, size), table, spec);
  }
  catch (const pcl_ext::io::ReadError&) {
    pcl_ext_fuzz::check (table.empty(), "the table is untouched after a ReadError");
    return 0;
  }
  using pcl_ext_fuzz::check;
  check (!table.empty(), "a successful read has points");
  check (table.intensity.empty() || table.intensity.size() == table.size(),
         "intensity size");
  check (table.rgb.empty() || table.rgb.size() == table.size(), "colour size");
  check (table.label.empty() || table.label.size() == table.size(), "label size");
  for (const auto& p : table.xyz)
    check (p.allFinite(), "coordinates are finite");

  const Eigen::Vector3d origin = pcl_ext::io::computeLocalOrigin (table);
  check (origin.allFinite(), "the local origin is finite");
  pcl::PCLPointCloud2 cloud;
  pcl_ext::io::toPCLPointCloud2 (table, origin, cloud);
  check (cloud.width == table.size() && cloud.height == 1, "cloud size");
  check (cloud.data.size() == static_cast<std::size_t> (cloud.point_step) * cloud.width,
         "cloud data size");
  return 0;
}
