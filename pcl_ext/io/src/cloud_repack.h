/*
 * pcl_ext: numeric access to the fields of a pcl::PCLPointCloud2 and rebuilding its
 * coordinate fields (inside pcl_ext::io only).
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace detail {
/** The value at \a data of PCL type \a datatype (pcl::PCLPointField::INT8 ...
 * FLOAT64), as a double; NaN for an unknown type. */
double
readNumber (const std::uint8_t* data, std::uint8_t datatype);

/** The x y z of every point of \a cloud (any numeric type) as doubles, row-major.
 * \return false when a coordinate field is missing or the data is shorter than the
 * cloud's size */
bool
readCoordinates (const pcl::PCLPointCloud2& cloud, std::vector<Eigen::Vector3d>& xyz);

/** \a cloud rebuilt with x y z first, of type \a datatype (FLOAT32 or FLOAT64),
 * holding \a xyz[i] + \a shift, followed by the other fields in their order (fields
 * named in \a drop left out). Width, height, header and is_dense are kept. */
void
rebuildCoordinates (const pcl::PCLPointCloud2& cloud,
                    const std::vector<Eigen::Vector3d>& xyz,
                    const Eigen::Vector3d& shift,
                    std::uint8_t datatype,
                    const std::vector<std::string>& drop,
                    pcl::PCLPointCloud2& result);
} // namespace detail
} // namespace io
} // namespace pcl_ext
