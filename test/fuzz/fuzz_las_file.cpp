/*
 * Fuzz target: pcl_ext::io::LasReader (header, VLR, EVLR and extra-bytes parsing, then
 * the point records read in chunks).
 *
 * Seeds (las_file/): the first points of PDAL's BSD-licensed samples (simple.las,
 * extrabytes.las, test1_4.las, bad_vlr_count.las, the start of
 * garbage_nVariableLength.las), one small file of each point format 0-10, a LAS 1.4
 * file with an EVLR, and malformed headers.
 */
#include <pcl_ext/io/las_reader.h>

#include "fuzz_input_file.h"

#include <cmath>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  using pcl_ext_fuzz::check;
  static pcl_ext_fuzz::InputFile file;
  const std::string& path = file.write (data, size);
  pcl_ext::io::LasReader reader;
  try {
    reader.open (path);
  }
  catch (const pcl_ext::io::ReadError& e) {
    check (e.path() == path, "the error names the file");
    return 0;
  }
  const auto& h = reader.getHeader();
  check (h.pointFormat() >= 0 && h.pointFormat() <= 10, "a known point format");
  check (h.record_length >= pcl_ext::io::lasPointRecordLength (h.pointFormat()),
         "records hold the format");
  check (h.isCompressed() ||
             h.offset_to_point_data + h.point_count * h.record_length <= size,
         "the points lie in the file");
  check (reader.getOrigin().allFinite(), "the origin is finite");

  pcl::PCLPointCloud2 chunk;
  std::uint64_t total = 0;
  try {
    while (const std::size_t n = reader.read (333, chunk)) {
      check (n <= 333 && chunk.width == n && chunk.height == 1, "chunk size");
      check (chunk.data.size() == static_cast<std::size_t> (chunk.point_step) * n,
             "chunk data size");
      for (const auto& f : chunk.fields)
        check (f.offset < chunk.point_step, "fields lie in the point");
      total += n;
    }
  }
  catch (const pcl_ext::io::ReadError& e) {
    check (e.path() == path, "the error names the file");
    return 0;
  }
  check (total == reader.getPointCount(), "every point is read");
  return 0;
}
