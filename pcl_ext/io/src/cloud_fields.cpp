/*
 * pcl_ext: reading and writing one named field of a pcl::PCLPointCloud2.
 */
#include <pcl_ext/io/cloud_fields.h>

#include "cloud_repack.h"

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

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
bool
unionOfFields (const std::vector<pcl::PCLPointCloud2>& layouts,
               pcl::PCLPointCloud2& result,
               std::string& error)
{
  result = pcl::PCLPointCloud2();
  std::uint32_t offset = 0;
  for (const auto& layout : layouts)
    for (const auto& f : layout.fields) {
      const auto seen =
          std::find_if (result.fields.begin(),
                        result.fields.end(),
                        [&f] (const auto& g) { return g.name == f.name; });
      const std::uint32_t count = std::max<std::uint32_t> (f.count, 1);
      if (seen != result.fields.end()) {
        if (seen->datatype != f.datatype ||
            std::max<std::uint32_t> (seen->count, 1) != count) {
          error = "the field '" + f.name + "' has two types (" +
                  std::to_string (pcl::getFieldSize (seen->datatype)) + " and " +
                  std::to_string (pcl::getFieldSize (f.datatype)) +
                  " bytes, or counts " + std::to_string (seen->count) + " and " +
                  std::to_string (f.count) + ")";
          return false;
        }
        continue;
      }
      pcl::PCLPointField copy = f;
      copy.offset = offset;
      copy.count = count;
      offset += pcl::getFieldSize (f.datatype) * count;
      result.fields.push_back (copy);
    }
  result.point_step = offset;
  return true;
}

namespace {
/** \a v (a whole number within the type's range) stored as PCL type \a datatype. */
void
writeNumber (double v, std::uint8_t datatype, std::uint8_t* out)
{
  const auto put = [out] (auto value) { std::memcpy (out, &value, sizeof (value)); };
  switch (datatype) {
  case pcl::PCLPointField::INT8:
    put (static_cast<std::int8_t> (v));
    break;
  case pcl::PCLPointField::UINT8:
    put (static_cast<std::uint8_t> (v));
    break;
  case pcl::PCLPointField::INT16:
    put (static_cast<std::int16_t> (v));
    break;
  case pcl::PCLPointField::UINT16:
    put (static_cast<std::uint16_t> (v));
    break;
  case pcl::PCLPointField::INT32:
    put (static_cast<std::int32_t> (v));
    break;
  case pcl::PCLPointField::UINT32:
    put (static_cast<std::uint32_t> (v));
    break;
  case pcl::PCLPointField::FLOAT64:
    put (v);
    break;
  default:
    put (static_cast<float> (v));
  }
}

/** The field \a name of \a cloud (pcl::getFieldIndex), or null. */
const pcl::PCLPointField*
findField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  const int index = pcl::getFieldIndex (cloud, name);
  return index < 0 ? nullptr : &cloud.fields[static_cast<std::size_t> (index)];
}
} // namespace

void
conformToFields (const pcl::PCLPointCloud2& cloud,
                 const pcl::PCLPointCloud2& fields,
                 pcl::PCLPointCloud2& result)
{
  pcl::PCLPointCloud2 out;
  out.header = cloud.header;
  out.width = cloud.width;
  out.height = cloud.height;
  out.is_bigendian = cloud.is_bigendian;
  out.is_dense = cloud.is_dense;
  out.fields = fields.fields;
  out.point_step = fields.point_step;
  out.row_step = out.point_step * out.width;
  out.data.assign (std::size_t (out.row_step) * out.height, 0);
  // Colour in the other form: packed rgb from red green blue, or the reverse.
  const pcl::PCLPointField* packed = findField (cloud, "rgb");
  if (!packed)
    packed = findField (cloud, "rgba");
  const pcl::PCLPointField* channels[3] = {
      findField (cloud, "red"), findField (cloud, "green"), findField (cloud, "blue")};
  const bool has_channels = channels[0] && channels[1] && channels[2];
  std::vector<std::pair<const pcl::PCLPointField*, const pcl::PCLPointField*>> copies;
  std::vector<std::pair<const pcl::PCLPointField*, int>> from_packed; // channel 0-2
  const pcl::PCLPointField* packed_target = nullptr;
  for (const auto& f : out.fields) {
    if (const auto* from = findField (cloud, f.name))
      copies.emplace_back (from, &f);
    else if (packed && (f.name == "red" || f.name == "green" || f.name == "blue"))
      from_packed.emplace_back (&f, f.name == "red" ? 0 : (f.name == "green" ? 1 : 2));
    else if (has_channels && (f.name == "rgb" || f.name == "rgba") &&
             pcl::getFieldSize (f.datatype) == 4)
      packed_target = &f;
  }
  const std::size_t n = static_cast<std::size_t> (cloud.width) * cloud.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* in = cloud.data.data() + i * cloud.point_step;
    std::uint8_t* o = out.data.data() + i * out.point_step;
    for (const auto& [from, to] : copies)
      std::memcpy (o + to->offset,
                   in + from->offset,
                   pcl::getFieldSize (from->datatype) *
                       std::max<std::uint32_t> (from->count, 1));
    if (!from_packed.empty()) {
      std::uint32_t rgb;
      std::memcpy (&rgb, in + packed->offset, 4);
      for (const auto& [to, channel] : from_packed) {
        const double byte = (rgb >> (16 - 8 * channel)) & 0xFFu;
        const double v = pcl::getFieldSize (to->datatype) == 1 ? byte : byte * 257.0;
        writeNumber (v, to->datatype, o + to->offset);
      }
    }
    if (packed_target) {
      std::uint32_t rgb = 0;
      for (int c = 0; c < 3; ++c) {
        const double v =
            detail::readNumber (in + channels[c]->offset, channels[c]->datatype);
        const double scale =
            pcl::getFieldSize (channels[c]->datatype) == 1 ? 1.0 : 257.0;
        const std::uint32_t byte = static_cast<std::uint32_t> (
            std::clamp (std::isfinite (v) ? v / scale : 0.0, 0.0, 255.0) + 0.5);
        rgb |= std::min<std::uint32_t> (byte, 255u) << (16 - 8 * c);
      }
      std::memcpy (o + packed_target->offset, &rgb, 4);
    }
  }
  result = std::move (out);
}
} // namespace io
} // namespace pcl_ext
