/*
 * pcl_ext: reading labelled clouds for the CRF apps.
 */
#include "crf_inputs.h"

#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_table.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <cmath>
#include <exception>
#include <iostream>

namespace pcl_ext {
namespace apps {
namespace {
bool
endsWith (const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
         s.compare (s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
} // namespace

void
readCrfAttributes (const pcl::PCLPointCloud2& blob,
                   std::vector<Eigen::Vector3f>* colours,
                   std::vector<float>* intensity)
{
  if (colours) {
    colours->clear();
    if (pcl::getFieldIndex (blob, "rgb") >= 0 ||
        pcl::getFieldIndex (blob, "rgba") >= 0) {
      pcl::PointCloud<pcl::PointXYZRGB> rgb;
      pcl::fromPCLPointCloud2 (blob, rgb);
      colours->resize (rgb.size());
      for (std::size_t i = 0; i < rgb.size(); ++i) {
        const float sum = static_cast<float> (rgb[i].r) + rgb[i].g + rgb[i].b;
        (*colours)[i] =
            sum > 0.f ? Eigen::Vector3f (rgb[i].r / sum, rgb[i].g / sum, rgb[i].b / sum)
                      : Eigen::Vector3f::Constant (1.f / 3.f);
      }
    }
  }
  if (intensity) {
    intensity->clear();
    if (pcl::getFieldIndex (blob, "intensity") >= 0) {
      pcl::PointCloud<pcl::PointXYZI> in;
      pcl::fromPCLPointCloud2 (blob, in);
      intensity->resize (in.size());
      for (std::size_t i = 0; i < in.size(); ++i)
        (*intensity)[i] = std::isfinite (in[i].intensity) ? in[i].intensity : 0.f;
    }
  }
}

std::map<std::uint32_t, std::uint32_t>
crfAsprsCodes (const std::map<std::uint32_t, std::string>& names)
{
  std::map<std::uint32_t, std::uint32_t> codes;
  std::string unmapped;
  for (const auto& [id, name] : names) {
    const int code = asprsClass (name);
    codes[id] = code >= 0 ? static_cast<std::uint32_t> (code) : 1u;
    if (code < 0)
      unmapped += (unmapped.empty() ? "" : ", ") + name;
    std::cout << "  class " << id << " " << name << " -> ASPRS " << codes[id] << '\n';
  }
  if (!unmapped.empty())
    std::cout << "  no ASPRS code for " << unmapped
              << ": written as 1 (unclassified) in Classification\n";
  return codes;
}

ResultField
crfClassField ()
{
  return ResultField (
      "crf_class",
      "class id (1.. in the model's order)",
      "also write the classes as ASPRS codes into the LAS Classification, mapped by "
      "class name (ground 2, vegetation 5, building / facade 6, wire 14, ...; classes "
      "without a code: 1)");
}

bool
loadCrfCloud (const std::string& path,
              const io::ClassMapping* mapping,
              CrfCloud& out,
              std::string& error)
{
  out = CrfCloud();
  try {
    if (endsWith (path, ".xyz_label_conf")) {
      if (!mapping || mapping->empty()) {
        error = path + ": Oakland files need a class mapping (-classes FILE)";
        return false;
      }
      io::PointTable table;
      io::loadOaklandFile (path, table);
      out.file.origin = io::computeLocalOrigin (table);
      out.file.format = io::PointFileFormat::ASCII;
      io::toPCLPointCloud2 (table, out.file.origin, out.file.cloud);
    }
    else
      io::loadPointFile (path, out.file);
  }
  catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  const pcl::PCLPointCloud2& blob = out.file.cloud;
  if (blob.width * blob.height == 0) {
    error = path + ": no points";
    return false;
  }
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::fromPCLPointCloud2 (blob, *xyz);
  out.input.xyz = xyz;
  readCrfAttributes (blob, &out.input.colours, &out.input.intensity);
  if (pcl::getFieldIndex (blob, "label") >= 0) {
    std::string why;
    if (!io::getLabelField (blob, "label", out.labels, &why)) {
      error = path + ": " + why;
      return false;
    }
    if (mapping && !mapping->empty())
      mapping->apply (out.labels);
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
