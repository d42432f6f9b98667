/*
 * pcl_ext_tiles: several inputs in one output: their fields, and their coordinate
 * reference system.
 */
#include "input_fields.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/las_crs.h>
#include <pcl_ext/tiling/point_file_chunks.h>

#include <iostream>

namespace pcl_ext {
namespace apps {
bool
unionOfInputFields (const std::vector<std::string>& inputs, pcl::PCLPointCloud2& layout)
{
  std::vector<pcl::PCLPointCloud2> layouts;
  for (const auto& input : inputs) {
    tiling::PointFileChunks file;
    file.open (input);
    pcl::PCLPointCloud2 first;
    file.read (1, first);
    layouts.emplace_back();
    layouts.back().fields = first.fields;
    layouts.back().point_step = first.point_step;
    std::string error;
    if (!io::unionOfFields (layouts, layout, error)) {
      std::cerr << "\nError: " << input
                << " and the inputs before it cannot go into one "
                << "output: " << error << ".\n";
      return false;
    }
  }
  return true;
}

bool
sameCoordinateSystem (const std::vector<std::string>& inputs)
{
  io::LasCoordinateSystem first;
  std::string first_input, without;
  for (const auto& input : inputs) {
    tiling::PointFileChunks file;
    file.open (input);
    const auto& description = file.getDescription();
    const io::LasCoordinateSystem crs =
        description.las ? io::lasCoordinateSystem (*description.las)
                        : io::textCoordinateSystem (description.coordinate_metadata);
    if (!crs.declared()) {
      without = without.empty() ? input : without;
      continue;
    }
    if (!first.declared()) {
      first = crs;
      first_input = input;
      continue;
    }
    const io::CrsMatch match = io::matchCoordinateSystems (first, crs);
    if (match == io::CrsMatch::Different) {
      std::cerr << "\nError: " << input << " declares " << crs.describe() << " and "
                << first_input << " " << first.describe()
                << ": inputs in different coordinate reference systems cannot go "
                   "into one output; reproject them into one first.\n";
      return false;
    }
    if (match == io::CrsMatch::Unknown)
      std::cerr << "\nWarning: " << input << " declares " << crs.describe() << " and "
                << first_input << " " << first.describe()
                << "; taken to be one CRS, the latter's, which the output declares.\n";
  }
  if (first.declared() && !without.empty())
    std::cerr << "\nWarning: " << without << " declares no coordinate reference "
              << "system; it is taken to be " << first_input << "'s, "
              << first.describe() << ", which the output declares.\n";
  return true;
}

bool
hasLayout (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointCloud2& layout)
{
  if (cloud.point_step != layout.point_step ||
      cloud.fields.size() != layout.fields.size())
    return false;
  for (std::size_t i = 0; i < cloud.fields.size(); ++i) {
    const auto& a = cloud.fields[i];
    const auto& b = layout.fields[i];
    if (a.name != b.name || a.offset != b.offset || a.datatype != b.datatype ||
        a.count != b.count)
      return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
