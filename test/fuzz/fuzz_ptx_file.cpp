/*
 * Fuzz target: pcl_ext::io::loadPTX and loadPTS and the conversion to a cloud.
 *
 * The first byte chooses the reader: 0 PTX, 1 PTX in the scanner frame, 2 PTS.
 */
#include <pcl_ext/io/ptx_reader.h>

#include "fuzz_input_file.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  using pcl_ext_fuzz::check;
  if (size == 0)
    return 0;
  const std::uint8_t selector = data[0] % 3;
  ++data;
  --size;
  pcl_ext::io::PointTable table;
  try {
    const std::string& path = file.write (data, size);
    if (selector == 2)
      pcl_ext::io::loadPTS (path, table);
    else {
      pcl_ext::io::PtxOptions options;
      options.keep_scanner_frame = selector == 1;
      pcl_ext::io::loadPTX (path, table, options);
    }
  }
  catch (const pcl_ext::io::ReadError&) {
    check (table.empty() && table.stations.empty(),
           "the table is untouched after a ReadError");
    return 0;
  }
  const std::size_t n = table.size();
  check (selector == 2 ? n > 0 : !table.stations.empty(), "a successful read has data");
  check (table.intensity.empty() || table.intensity.size() == n, "intensity size");
  check (table.rgb.empty() || table.rgb.size() == n, "colour size");
  check (table.row.size() == table.column.size(), "row and column sizes");
  check (selector == 2 || table.scan.size() == n, "every PTX point has a station");
  for (std::size_t i = 0; i < n; ++i) {
    check (table.xyz[i].allFinite(), "coordinates are finite");
    check (table.scan.empty() || table.scan[i] < table.stations.size(),
           "station index in range");
    if (!table.row.empty()) {
      const auto& s = table.stations[table.scan[i]];
      check (table.row[i] >= 0 && table.row[i] < s.rows, "row inside the grid");
      check (table.column[i] >= 0 && table.column[i] < s.columns,
             "column inside the grid");
    }
  }
  pcl::PCLPointCloud2 cloud;
  pcl_ext::io::toPCLPointCloud2 (table, pcl_ext::io::computeLocalOrigin (table), cloud);
  check (cloud.data.size() == static_cast<std::size_t> (cloud.point_step) * n,
         "cloud data size");
  return 0;
}
