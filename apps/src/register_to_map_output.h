/*
 * pcl_ext_register_to_map: writing the transforms and the registered cloud.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>

namespace pcl_ext {
namespace apps {
// Row by row, as PDAL's filters.transformation and CloudCompare read it.
bool
writeTransform (const std::string& path, const Eigen::Matrix4d& t);

// T.txt -> T_candidate_2.txt
std::string
candidatePath (const std::string& path, std::size_t rank);

// Rotation angle (radians) plus the translation difference over 100 m: ranks
// candidates by their distance to a guess, rotation first.
double
poseDistance (const Eigen::Matrix4d& a, const Eigen::Matrix4d& b);

// x y z (FLOAT32, local) of every point moved by \a t; the other fields are kept.
void
transformXyz (const Eigen::Matrix4d& t, pcl::PCLPointCloud2& cloud);
} // namespace apps
} // namespace pcl_ext
