/*
 * pcl_ext: numeric access to the fields of a pcl::PCLPointCloud2 and rebuilding its
 * coordinate fields.
 */
#include "cloud_repack.h"

#include <pcl/common/io.h>

#include <algorithm>
#include <cstring>
#include <limits>

namespace pcl_ext {
namespace io {
namespace detail {
namespace {
template <typename T>
double
load (const std::uint8_t* data)
{
  T value;
  std::memcpy (&value, data, sizeof (T));
  return static_cast<double> (value);
}
} // namespace

double
readNumber (const std::uint8_t* data, std::uint8_t datatype)
{
  switch (datatype) {
  case pcl::PCLPointField::INT8:
    return load<std::int8_t> (data);
  case pcl::PCLPointField::UINT8:
    return load<std::uint8_t> (data);
  case pcl::PCLPointField::INT16:
    return load<std::int16_t> (data);
  case pcl::PCLPointField::UINT16:
    return load<std::uint16_t> (data);
  case pcl::PCLPointField::INT32:
    return load<std::int32_t> (data);
  case pcl::PCLPointField::UINT32:
    return load<std::uint32_t> (data);
  case pcl::PCLPointField::FLOAT32:
    return load<float> (data);
  case pcl::PCLPointField::FLOAT64:
    return load<double> (data);
  default:
    return std::numeric_limits<double>::quiet_NaN();
  }
}

bool
readCoordinates (const pcl::PCLPointCloud2& cloud, std::vector<Eigen::Vector3d>& xyz)
{
  const pcl::PCLPointField* fields[3] = {};
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    const int index = pcl::getFieldIndex (cloud, names[axis]);
    if (index < 0)
      return false;
    fields[axis] = &cloud.fields[index];
    if (fields[axis]->offset + pcl::getFieldSize (fields[axis]->datatype) >
        cloud.point_step)
      return false;
  }
  const std::size_t rows = cloud.height, columns = cloud.width;
  if (rows > 0 && cloud.data.size() < (rows - 1) * std::size_t (cloud.row_step) +
                                          columns * std::size_t (cloud.point_step))
    return false;
  xyz.resize (rows * columns);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c) {
      const std::uint8_t* point =
          cloud.data.data() + r * cloud.row_step + c * cloud.point_step;
      Eigen::Vector3d& p = xyz[r * columns + c];
      for (int axis = 0; axis < 3; ++axis)
        p[axis] = readNumber (point + fields[axis]->offset, fields[axis]->datatype);
    }
  return true;
}

void
rebuildCoordinates (const pcl::PCLPointCloud2& cloud,
                    const std::vector<Eigen::Vector3d>& xyz,
                    const Eigen::Vector3d& shift,
                    std::uint8_t datatype,
                    const std::vector<std::string>& drop,
                    pcl::PCLPointCloud2& result)
{
  const std::uint32_t size = datatype == pcl::PCLPointField::FLOAT64 ? 8 : 4;
  pcl::PCLPointCloud2 out;
  out.header = cloud.header;
  out.width = cloud.width;
  out.height = cloud.height;
  out.is_bigendian = cloud.is_bigendian;
  out.is_dense = cloud.is_dense;
  const char* names[3] = {"x", "y", "z"};
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    pcl::PCLPointField f;
    f.name = names[axis];
    f.offset = axis * size;
    f.datatype = datatype;
    f.count = 1;
    out.fields.push_back (f);
  }
  std::vector<const pcl::PCLPointField*> kept;
  std::uint32_t offset = 3 * size;
  for (const auto& f : cloud.fields) {
    if (f.name == "x" || f.name == "y" || f.name == "z" ||
        std::find (drop.begin(), drop.end(), f.name) != drop.end())
      continue;
    pcl::PCLPointField copy = f;
    copy.offset = offset;
    offset += pcl::getFieldSize (f.datatype) * std::max<std::uint32_t> (f.count, 1);
    out.fields.push_back (copy);
    kept.push_back (&f);
  }
  out.point_step = offset;
  out.row_step = out.point_step * out.width;
  out.data.assign (std::size_t (out.row_step) * out.height, 0);
  for (std::size_t r = 0; r < cloud.height; ++r)
    for (std::size_t c = 0; c < cloud.width; ++c) {
      const std::uint8_t* in =
          cloud.data.data() + r * cloud.row_step + c * cloud.point_step;
      std::uint8_t* o = out.data.data() + r * out.row_step + c * out.point_step;
      const Eigen::Vector3d& p = xyz[r * cloud.width + c];
      for (int axis = 0; axis < 3; ++axis) {
        const double v = p[axis] + shift[axis];
        if (size == 8)
          std::memcpy (o + axis * 8, &v, 8);
        else {
          const float f = static_cast<float> (v);
          std::memcpy (o + axis * 4, &f, 4);
        }
      }
      for (std::size_t k = 0; k < kept.size(); ++k) {
        const pcl::PCLPointField& from = *kept[k];
        const pcl::PCLPointField& to = out.fields[3 + k];
        std::memcpy (o + to.offset,
                     in + from.offset,
                     pcl::getFieldSize (from.datatype) *
                         std::max<std::uint32_t> (from.count, 1));
      }
    }
  result = std::move (out);
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
