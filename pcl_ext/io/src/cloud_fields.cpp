/*
 * pcl_ext: reading and writing one named field of a pcl::PCLPointCloud2.
 */
#include <pcl_ext/io/cloud_fields.h>

#include "cloud_repack.h"

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace pcl_ext {
namespace io {
namespace {
std::size_t
typeSize (std::uint8_t type)
{
  switch (type) {
  case pcl::PCLPointField::INT8:
  case pcl::PCLPointField::UINT8:
    return 1;
  case pcl::PCLPointField::INT16:
  case pcl::PCLPointField::UINT16:
    return 2;
  case pcl::PCLPointField::FLOAT64:
    return 8;
  default:
    return 4;
  }
}
} // namespace

bool
getLabelField (const pcl::PCLPointCloud2& cloud,
               const std::string& name,
               std::vector<std::uint32_t>& labels,
               std::string* error)
{
  const auto fail = [error] (const std::string& message) {
    if (error)
      *error = message;
    return false;
  };
  const int f = pcl::getFieldIndex (cloud, name);
  if (f < 0) {
    std::string names;
    for (const auto& field : cloud.fields)
      names += (names.empty() ? "" : " ") + field.name;
    return fail ("no field '" + name + "' (fields: " + names + ")");
  }
  const pcl::PCLPointField& field = cloud.fields[f];
  if (field.datatype < pcl::PCLPointField::INT8 ||
      field.datatype > pcl::PCLPointField::FLOAT64)
    return fail ("field '" + name + "' has an unsupported type");
  const std::size_t n = static_cast<std::size_t> (cloud.width) * cloud.height;
  if (n > 0 && (cloud.point_step < field.offset + typeSize (field.datatype) ||
                cloud.data.size() < n * cloud.point_step))
    return fail ("the cloud's data is shorter than its " + std::to_string (n) +
                 " points");
  std::vector<std::uint32_t> result (n);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = detail::readNumber (
        cloud.data.data() + i * cloud.point_step + field.offset, field.datatype);
    if (std::isnan (v) || v < 0.0)
      result[i] = 0;
    else if (v != std::floor (v) || v > std::numeric_limits<std::uint32_t>::max())
      return fail ("field '" + name + "' of point " + std::to_string (i) + " holds " +
                   std::to_string (v) +
                   ", which is not a label (a whole number below 2^32)");
    else
      result[i] = static_cast<std::uint32_t> (v);
  }
  labels = std::move (result);
  return true;
}

namespace {
/** Writes 4-byte values into field \a name of type \a datatype (UINT32 or FLOAT32):
 * in place when it already is one such value, otherwise replacing it (or, when absent,
 * appending it) and repacking the points. */
template <typename T>
bool
setScalarField (pcl::PCLPointCloud2& cloud,
                const std::string& name,
                std::uint8_t datatype,
                const std::vector<T>& values)
{
  static_assert (sizeof (T) == 4, "4-byte fields only");
  const std::size_t n = static_cast<std::size_t> (cloud.width) * cloud.height;
  if (values.size() != n)
    return false;
  const int f = pcl::getFieldIndex (cloud, name);
  if (f >= 0 && cloud.fields[f].datatype == datatype && cloud.fields[f].count == 1) {
    for (std::size_t i = 0; i < n; ++i)
      std::memcpy (cloud.data.data() + i * cloud.point_step + cloud.fields[f].offset,
                   &values[i],
                   4);
    return true;
  }
  // Repack: every other field keeps its bytes, the new one goes last.
  std::vector<pcl::PCLPointField> fields;
  std::vector<std::uint32_t> old_offsets;
  std::uint32_t step = 0;
  for (std::size_t i = 0; i < cloud.fields.size(); ++i) {
    if (static_cast<int> (i) == f)
      continue;
    pcl::PCLPointField field = cloud.fields[i];
    old_offsets.push_back (field.offset);
    field.offset = step;
    step += static_cast<std::uint32_t> (typeSize (field.datatype) *
                                        std::max<std::uint32_t> (field.count, 1));
    fields.push_back (field);
  }
  pcl::PCLPointField added;
  added.name = name;
  added.offset = step;
  added.datatype = datatype;
  added.count = 1;
  step += 4;
  std::vector<std::uint8_t> data (n * step);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* src = cloud.data.data() + i * cloud.point_step;
    std::uint8_t* dst = data.data() + i * step;
    for (std::size_t k = 0; k < fields.size(); ++k)
      std::memcpy (dst + fields[k].offset,
                   src + old_offsets[k],
                   typeSize (fields[k].datatype) *
                       std::max<std::uint32_t> (fields[k].count, 1));
    std::memcpy (dst + added.offset, &values[i], 4);
  }
  fields.push_back (added);
  cloud.fields = std::move (fields);
  cloud.point_step = step;
  cloud.row_step = step * cloud.width;
  cloud.data = std::move (data);
  return true;
}
} // namespace

bool
setLabelField (pcl::PCLPointCloud2& cloud,
               const std::string& name,
               const std::vector<std::uint32_t>& labels)
{
  return setScalarField (cloud, name, pcl::PCLPointField::UINT32, labels);
}

bool
setFloatField (pcl::PCLPointCloud2& cloud,
               const std::string& name,
               const std::vector<float>& values)
{
  return setScalarField (cloud, name, pcl::PCLPointField::FLOAT32, values);
}
} // namespace io
} // namespace pcl_ext
