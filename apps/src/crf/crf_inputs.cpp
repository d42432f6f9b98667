/*
 * pcl_ext: reading labelled clouds for the CRF apps.
 */
#include "crf_inputs.h"

#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/cloud_io.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <exception>

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
      io::toPCLPointCloud2 (table, io::computeLocalOrigin (table), out.blob);
    }
    else if (!io::loadCloud (path, out.blob)) {
      error = path + ": cannot read the cloud";
      return false;
    }
  }
  catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  if (out.blob.width * out.blob.height == 0) {
    error = path + ": no points";
    return false;
  }
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::fromPCLPointCloud2 (out.blob, *xyz);
  out.input.xyz = xyz;
  if (pcl::getFieldIndex (out.blob, "rgb") >= 0 ||
      pcl::getFieldIndex (out.blob, "rgba") >= 0) {
    pcl::PointCloud<pcl::PointXYZRGB> rgb;
    pcl::fromPCLPointCloud2 (out.blob, rgb);
    out.input.colours.resize (rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
      const float sum = static_cast<float> (rgb[i].r) + rgb[i].g + rgb[i].b;
      out.input.colours[i] =
          sum > 0.f ? Eigen::Vector3f (rgb[i].r / sum, rgb[i].g / sum, rgb[i].b / sum)
                    : Eigen::Vector3f::Constant (1.f / 3.f);
    }
  }
  if (pcl::getFieldIndex (out.blob, "intensity") >= 0) {
    pcl::PointCloud<pcl::PointXYZI> in;
    pcl::fromPCLPointCloud2 (out.blob, in);
    out.input.intensity.resize (in.size());
    for (std::size_t i = 0; i < in.size(); ++i)
      out.input.intensity[i] = std::isfinite (in[i].intensity) ? in[i].intensity : 0.f;
  }
  if (pcl::getFieldIndex (out.blob, "label") >= 0) {
    std::string why;
    if (!io::getLabelField (out.blob, "label", out.labels, &why)) {
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
