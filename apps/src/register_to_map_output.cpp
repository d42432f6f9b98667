/*
 * pcl_ext_register_to_map: writing the transforms and the registered cloud.
 */
#include "register_to_map_output.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace pcl_ext {
namespace apps {
// Row by row, as PDAL's filters.transformation and CloudCompare read it.
bool
writeTransform (const std::string& path, const Eigen::Matrix4d& t)
{
  std::FILE* file = std::fopen (path.c_str(), "w");
  if (!file) {
    std::cerr << "Error: cannot write " << path << ".\n";
    return false;
  }
  for (int r = 0; r < 4; ++r)
    std::fprintf (
        file, "%.17g %.17g %.17g %.17g\n", t (r, 0), t (r, 1), t (r, 2), t (r, 3));
  return std::fclose (file) == 0;
}

// T.txt -> T_candidate_2.txt
std::string
candidatePath (const std::string& path, std::size_t rank)
{
  const std::size_t dot = path.find_last_of ('.');
  const std::size_t slash = path.find_last_of ("/\\");
  const bool has_extension =
      dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = has_extension ? path.substr (0, dot) : path;
  return stem + "_candidate_" + std::to_string (rank) +
         (has_extension ? path.substr (dot) : std::string());
}

// Rotation angle (radians) plus the translation difference over 100 m: ranks
// candidates by their distance to a guess, rotation first.
double
poseDistance (const Eigen::Matrix4d& a, const Eigen::Matrix4d& b)
{
  const Eigen::Matrix3d r =
      a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>();
  const double cosine = std::min (1.0, std::max (-1.0, 0.5 * (r.trace() - 1.0)));
  return std::acos (cosine) +
         (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).norm() / 100.0;
}

// x y z (FLOAT32, local) of every point moved by \a t; the other fields are kept.
void
transformXyz (const Eigen::Matrix4d& t, pcl::PCLPointCloud2& cloud)
{
  int offset[3] = {-1, -1, -1};
  for (const auto& f : cloud.fields)
    for (int c = 0; c < 3; ++c)
      if (f.name == std::string (1, "xyz"[c]) &&
          f.datatype == pcl::PCLPointField::FLOAT32)
        offset[c] = static_cast<int> (f.offset);
  if (offset[0] < 0 || offset[1] < 0 || offset[2] < 0)
    return;
  for (std::size_t i = 0; i < cloud.width * cloud.height; ++i) {
    std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    float v[3];
    for (int c = 0; c < 3; ++c)
      std::memcpy (&v[c], point + offset[c], sizeof (float));
    const Eigen::Vector3d x =
        t.topLeftCorner<3, 3>() * Eigen::Vector3d (v[0], v[1], v[2]) +
        t.topRightCorner<3, 1>();
    for (int c = 0; c < 3; ++c) {
      const float value = static_cast<float> (x[c]);
      std::memcpy (point + offset[c], &value, sizeof (float));
    }
  }
}
} // namespace apps
} // namespace pcl_ext
