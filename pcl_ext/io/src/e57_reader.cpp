/*
 * pcl_ext: E57 files: the scans of the XML section read through their compressed
 * vectors into one table.
 */
#include <pcl_ext/io/e57_reader.h>

#include <pcl_ext/io/e57_format.h>

#include "e57_compressed_vector.h"
#include "e57_paged_file.h"
#include "e57_points.h"

#include <limits>

namespace pcl_ext {
namespace io {
void
loadE57 (const std::string& path, PointTable& table, const E57Options& options)
{
  detail::E57PagedFile file (path);
  std::string coordinate_metadata;
  const std::vector<E57ScanInfo> scans =
      parseE57Xml (file.readXml(), path, &coordinate_metadata);
  if (scans.size() > std::numeric_limits<std::uint16_t>::max() + std::size_t{1})
    throw ReadError (path, 0, "more than 65536 scans");
  detail::TableBuilder out;
  for (std::size_t s = 0; s < scans.size(); ++s) {
    const E57ScanInfo& scan = scans[s];
    ScanStation station;
    station.name = scan.name;
    station.guid = scan.guid;
    station.position = scan.translation;
    station.orientation = scan.rotation;
    station.points_in_scanner_frame = options.keep_scanner_frame;
    out.table.stations.push_back (station);
    const std::string where = "data3D scan " + std::to_string (s) +
                              (scan.name.empty() ? "" : " (" + scan.name + ")");
    detail::E57PointConverter converter (
        scan, options, static_cast<std::uint16_t> (s), path, where);
    detail::decodeE57Points (
        file, scan, where, [&] (const std::vector<double>& values, std::size_t count) {
          converter.convert (values, count, out);
        });
  }
  out.table.coordinate_metadata = std::move (coordinate_metadata);
  table = std::move (out.table);
}
} // namespace io
} // namespace pcl_ext
