/*
 * Fuzz target: pcl_ext::io::loadE57, parseE57Xml and the conversion to a cloud.
 *
 * The first byte chooses what the rest is: bit 3 set, an XML section for parseE57Xml;
 * otherwise an E57 file, whose page checksums are first recomputed when bit 0 is set
 * (so that mutations reach the XML and the compressed vectors instead of stopping at a
 * bad checksum); bit 1 keeps the scanner frame, bit 2 keeps intensity raw.
 */
#include <pcl_ext/io/e57_format.h>
#include <pcl_ext/io/e57_reader.h>

#include "fuzz_input_file.h"

#include <cmath>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  using pcl_ext_fuzz::check;
  if (size == 0)
    return 0;
  const std::uint8_t selector = data[0];
  ++data;
  --size;
  if (selector & 8u) {
    try {
      const auto scans = pcl_ext::io::parseE57Xml (
          std::string (reinterpret_cast<const char*> (data), size), "fuzz.xml");
      for (const auto& s : scans) {
        check (std::abs (s.rotation.norm() - 1.0) < 1e-9, "the rotation is a unit one");
        for (const auto& f : s.prototype)
          check (f.bits() <= 64, "a field has at most 64 bits");
      }
    }
    catch (const pcl_ext::io::ReadError&) {
    }
    return 0;
  }
  std::vector<std::uint8_t> bytes (data, data + size);
  if (selector & 1u)
    for (std::size_t p = 0; p + 1024 <= bytes.size(); p += 1024) {
      const std::uint32_t crc = pcl_ext::io::crc32c (bytes.data() + p, 1020);
      for (int i = 0; i < 4; ++i)
        bytes[p + 1020 + i] = static_cast<std::uint8_t> (crc >> (24 - 8 * i));
    }
  pcl_ext::io::E57Options options;
  options.keep_scanner_frame = (selector & 2u) != 0;
  options.normalise_intensity = (selector & 4u) == 0;
  pcl_ext::io::PointTable table;
  try {
    pcl_ext::io::loadE57 (file.write (bytes.data(), bytes.size()), table, options);
  }
  catch (const pcl_ext::io::ReadError&) {
    check (table.empty() && table.stations.empty(),
           "the table is untouched after a ReadError");
    return 0;
  }
  const std::size_t n = table.size();
  check (table.intensity.empty() || table.intensity.size() == n, "intensity size");
  check (table.rgb.empty() || table.rgb.size() == n, "colour size");
  check (table.row.empty() || table.row.size() == n, "row size");
  check (table.column.empty() || table.column.size() == n, "column size");
  check (table.scan.size() == n, "every point has a station");
  for (std::size_t i = 0; i < n; ++i) {
    check (table.xyz[i].allFinite(), "coordinates are finite");
    check (table.scan[i] < table.stations.size(), "station index in range");
  }
  pcl::PCLPointCloud2 cloud;
  pcl_ext::io::toPCLPointCloud2 (table, pcl_ext::io::computeLocalOrigin (table), cloud);
  check (cloud.data.size() == static_cast<std::size_t> (cloud.point_step) * n,
         "cloud data size");
  return 0;
}
