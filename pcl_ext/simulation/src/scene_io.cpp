/*
 * pcl_ext: saving and loading synthetic scenes with their ground truth.
 */
#include <pcl_ext/simulation/scene_io.h>
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/io/file_output.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>

#include <cstring>
#include <iomanip>
#include <sstream>

namespace pcl_ext {
namespace simulation {
namespace {
// Keep only \a names (in that order) of \a in.
void
selectFields (const pcl::PCLPointCloud2& in,
              const std::vector<std::string>& names,
              pcl::PCLPointCloud2& out)
{
  out = pcl::PCLPointCloud2();
  out.header = in.header;
  out.height = in.height;
  out.width = in.width;
  out.is_bigendian = in.is_bigendian;
  out.is_dense = in.is_dense;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> copies; // source offset, size
  std::uint32_t offset = 0;
  for (const auto& name : names)
    for (const auto& f : in.fields)
      if (f.name == name) {
        pcl::PCLPointField g = f;
        g.offset = offset;
        const std::uint32_t size = pcl::getFieldSize (f.datatype) * f.count;
        copies.emplace_back (f.offset, size);
        offset += size;
        out.fields.push_back (g);
      }
  out.point_step = offset;
  const std::size_t n = static_cast<std::size_t> (in.width) * in.height;
  out.row_step = out.point_step * out.width;
  out.data.resize (n * out.point_step);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* src = &in.data[i * in.point_step];
    std::uint8_t* dst = &out.data[i * out.point_step];
    for (const auto& c : copies) {
      std::memcpy (dst, src + c.first, c.second);
      dst += c.second;
    }
  }
}

void
renameField (pcl::PCLPointCloud2& blob, const std::string& from, const std::string& to)
{
  for (auto& f : blob.fields)
    if (f.name == from)
      f.name = to;
}
} // namespace

std::string
pathStem (const std::string& path)
{
  const std::size_t slash = path.find_last_of ('/');
  const std::size_t dot = path.find_last_of ('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return path;
  return path.substr (0, dot);
}

void
sceneToPointCloud2 (const SyntheticScene& scene, pcl::PCLPointCloud2& blob)
{
  pcl::PCLPointCloud2 full;
  pcl::toPCLPointCloud2 (scene.cloud, full);
  std::vector<std::string> names{"x", "y", "z"};
  if (scene.has_rgb)
    names.push_back ("rgb");
  if (scene.has_intensity)
    names.push_back ("intensity");
  names.insert (names.end(), {"segment", "object", "point_class"});
  if (scene.has_label)
    names.push_back ("label");
  selectFields (full, names, blob);
  renameField (blob, "point_class", "class");
}

std::string
footprintToWkt (const std::vector<Eigen::Vector2d>& footprint)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision (6) << "POLYGON((";
  for (std::size_t i = 0; i <= footprint.size() && !footprint.empty(); ++i) {
    const auto& q = footprint[i % footprint.size()];
    out << (i ? ", " : "") << q.x() << ' ' << q.y();
  }
  out << "))\n";
  return out.str();
}

std::string
matrixToText (const Eigen::Matrix4d& matrix)
{
  std::ostringstream out;
  out << std::setprecision (17);
  for (int r = 0; r < 4; ++r)
    out << matrix (r, 0) << ' ' << matrix (r, 1) << ' ' << matrix (r, 2) << ' '
        << matrix (r, 3) << '\n';
  return out.str();
}

bool
saveScene (const std::string& path, const SyntheticScene& scene, bool ascii)
{
  pcl::PCLPointCloud2 blob;
  sceneToPointCloud2 (scene, blob);
  if (!io::saveCloud (path, blob, ascii))
    return false;
  if (scene.footprint.empty())
    return true;
  const std::string stem = pathStem (path);
  return io::writeTextFile (stem + ".footprint.wkt",
                            footprintToWkt (scene.footprint)) &&
         io::writeTextFile (stem + ".transform.txt", matrixToText (scene.scan_to_map));
}

bool
loadScene (const std::string& path, pcl::PointCloud<SimulatedPoint>& cloud)
{
  cloud.clear();
  pcl::PCLPointCloud2 blob;
  if (!io::loadCloud (path, blob))
    return false;
  renameField (blob, "class", "point_class");
  // Scenes without colour, intensity or labels lack those fields: that is not worth a
  // warning.
  const auto level = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  pcl::fromPCLPointCloud2 (blob, cloud);
  pcl::console::setVerbosityLevel (level);
  return true;
}
} // namespace simulation
} // namespace pcl_ext
