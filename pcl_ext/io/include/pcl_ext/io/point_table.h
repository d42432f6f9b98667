/*
 * pcl_ext: points read from text files, in double precision, and their conversion to
 * clouds.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Points as a reader found them: coordinates in double, optional attributes.
 *
 * Georeferenced coordinates (e.g. RD New x = 119,300 m, UTM y = 5,400,000 m) do not fit
 * a float to the millimetre, so readers keep doubles and the conversion to a PCL cloud
 * subtracts a local origin (see computeLocalOrigin). Each attribute vector is either
 * empty (the file has no such column) or has one entry per point.
 */
struct PointTable {
  std::vector<Eigen::Vector3d> xyz;             ///< coordinates, as in the file
  std::vector<float> intensity;                 ///< intensity, as in the file
  std::vector<std::array<std::uint8_t, 3>> rgb; ///< colour, 0..255 per channel
  std::vector<std::uint32_t> label;             ///< label / class id

  std::size_t
  size () const
  {
    return xyz.size();
  }

  bool
  empty () const
  {
    return xyz.empty();
  }
};

/** \brief Largest |coordinate| that a float holds to better than a millimetre: 2^23 ulp
 * at 8192 m is ~0.98 mm. */
constexpr double kFloatSafeCoordinate = 8192.0;

/** \brief A local origin that makes \a table's coordinates safe in float.
 *
 * Per axis: when some |coordinate| exceeds kFloatSafeCoordinate, the origin is the
 * axis' minimum rounded down to a multiple of \a grid; otherwise it is 0 (local data is
 * left as it is, and heights stay heights). A round origin is easy to note and to add
 * back. \param[in] table the points \param[in] grid rounding step in metres, > 0;
 * default 100
 */
Eigen::Vector3d
computeLocalOrigin (const PointTable& table, double grid = 100.0);

/** \brief Convert to a PCL blob with fields x y z (float32, coordinates minus \a
 * origin) and, when present, intensity (float32), rgb (float32-packed as
 * pcl::PointXYZRGB) and label (uint32); width = number of points, height = 1, dense.
 */
void
toPCLPointCloud2 (const PointTable& table,
                  const Eigen::Vector3d& origin,
                  pcl::PCLPointCloud2& cloud);

/** \brief Convert to a typed cloud: fields of PointT missing from \a table keep their
 * default values, attributes PointT has no field for are dropped. */
template <typename PointT>
void
toPointCloud (const PointTable& table,
              const Eigen::Vector3d& origin,
              pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  toPCLPointCloud2 (table, origin, blob);
  pcl::fromPCLPointCloud2 (blob, cloud);
}
} // namespace io
} // namespace pcl_ext
