/*
 * pcl_ext: points read from text files, in double precision, and their conversion to
 * clouds.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief One scanner set-up (station) of a terrestrial scan file: where the scanner
 * stood and how it was turned.
 *
 * The pose maps the scanner's own frame into the file's frame: p_file = orientation *
 * p_scanner + position (ASTM E2807 section 8.4.3, the data3D pose; the PTX header's
 * transform). So \a position is the sensor's origin in the file's frame. When a reader
 * was asked to keep the points in the scanner frame, \a points_in_scanner_frame is
 * true: that station's points are then in the scanner's own frame, where the sensor is
 * at the origin, and applying the pose above brings them into the file's frame.
 */
struct ScanStation {
  std::string name; ///< the scan's name, may be empty
  std::string guid; ///< the scan's identifier, may be empty
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< sensor origin, file frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity(); ///< scanner to file
  std::int32_t rows = 0;    ///< grid rows of a structured scan, 0 when unknown
  std::int32_t columns = 0; ///< grid columns of a structured scan, 0 when unknown
  bool points_in_scanner_frame = false; ///< this station's points were not moved
};

/** \brief Points as a reader found them: coordinates in double, optional attributes.
 *
 * Georeferenced coordinates (e.g. RD New x = 119,300 m, UTM y = 5,400,000 m) do not fit
 * a float to the millimetre, so readers keep doubles and the conversion to a PCL cloud
 * subtracts a local origin (see computeLocalOrigin). Each attribute vector is either
 * empty (the file has no such column) or has one entry per point.
 *
 * Terrestrial scan readers (E57, PTX) also fill \a stations, one per scan, and \a scan
 * with each point's station index, so that the scanner position of every point stays
 * known: sensorPosition (table, i) returns it (for normal orientation or incidence
 * angles). \a row and \a column give a point's place in its scan's grid when the file
 * has one (-1 for a point without one in a table mixing gridded and other scans).
 */
struct PointTable {
  std::vector<Eigen::Vector3d> xyz;             ///< coordinates, as in the file
  std::vector<float> intensity;                 ///< intensity, as in the file
  std::vector<std::array<std::uint8_t, 3>> rgb; ///< colour, 0..255 per channel
  std::vector<std::uint32_t> label;             ///< label / class id
  std::vector<std::int32_t> row;                ///< grid row of a structured scan
  std::vector<std::int32_t> column;             ///< grid column of a structured scan
  std::vector<std::uint16_t> scan;              ///< index into \a stations
  std::vector<ScanStation> stations;            ///< the scans the points come from
  /** The coordinate reference system the file declares as text (E57:
   * coordinateMetadata; see textCoordinateSystem), empty when none. */
  std::string coordinate_metadata;

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

/** \brief The sensor position of point \a index, in the frame its coordinates are in.
 *
 * stations[scan[index]].position, or the origin when that station's points were kept in
 * the scanner frame. \return false (and \a position untouched) when the table has no
 * station for the point (no \a scan column, \a index out of range, or an index past
 * \a stations).
 */
bool
sensorPosition (const PointTable& table, std::size_t index, Eigen::Vector3d& position);

/** \brief Convert to a PCL blob with fields x y z (float32, coordinates minus \a
 * origin) and, when present, intensity (float32), rgb (float32-packed as
 * pcl::PointXYZRGB), label (uint32), row and column (int32) and scan (uint16, the
 * station index; the station table itself stays in the PointTable); width = number of
 * points, height = 1, dense.
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
