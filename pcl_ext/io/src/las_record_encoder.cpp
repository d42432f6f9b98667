/*
 * pcl_ext: the points of a pcl::PCLPointCloud2 as LAS point records.
 */
#include "las_record_encoder.h"

#include "las_bytes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace pcl_ext {
namespace io {
namespace las {
namespace {
using F = pcl::PCLPointField;

bool
isIntegerType (Type t)
{
  return t != F::FLOAT32 && t != F::FLOAT64;
}

CloudField
findField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  CloudField f;
  for (const auto& field : cloud.fields)
    if (field.name == name) {
      f.offset = field.offset;
      f.type = field.datatype;
      f.count = std::max<std::size_t> (field.count, 1);
      return f;
    }
  return f;
}

double
loadDouble (const std::uint8_t* p, Type type)
{
  switch (type) {
  case F::INT8:
    return get<std::int8_t> (p);
  case F::UINT8:
  case F::BOOL:
    return get<std::uint8_t> (p);
  case F::INT16:
    return get<std::int16_t> (p);
  case F::UINT16:
    return get<std::uint16_t> (p);
  case F::INT32:
    return get<std::int32_t> (p);
  case F::UINT32:
    return get<std::uint32_t> (p);
  case F::INT64:
    return static_cast<double> (get<std::int64_t> (p));
  case F::UINT64:
    return static_cast<double> (get<std::uint64_t> (p));
  case F::FLOAT32:
    return get<float> (p);
  case F::FLOAT64:
    return get<double> (p);
  default:
    return 0.0;
  }
}

/** An integer field's value as the 64 bits of a (u)int64, sign-extended. */
std::uint64_t
loadBits64 (const std::uint8_t* p, Type type)
{
  switch (type) {
  case F::INT8:
    return static_cast<std::uint64_t> (
        static_cast<std::int64_t> (get<std::int8_t> (p)));
  case F::INT16:
    return static_cast<std::uint64_t> (
        static_cast<std::int64_t> (get<std::int16_t> (p)));
  case F::INT32:
    return static_cast<std::uint64_t> (
        static_cast<std::int64_t> (get<std::int32_t> (p)));
  case F::UINT16:
    return get<std::uint16_t> (p);
  case F::UINT32:
    return get<std::uint32_t> (p);
  case F::INT64:
  case F::UINT64:
    return get<std::uint64_t> (p);
  default:
    return get<std::uint8_t> (p);
  }
}

/** Rounded and clamped to T's range (NaN gives 0). */
template <typename T>
T
toInteger (double v)
{
  if (std::isnan (v))
    return 0;
  v = std::round (v);
  if (v <= static_cast<double> (std::numeric_limits<T>::min()))
    return std::numeric_limits<T>::min();
  if (v >= static_cast<double> (std::numeric_limits<T>::max()))
    return std::numeric_limits<T>::max();
  return static_cast<T> (v);
}

void
storeDouble (std::uint8_t* p, Type storage, double v)
{
  switch (storage) {
  case F::INT8:
    put (p, toInteger<std::int8_t> (v));
    break;
  case F::UINT8:
    put (p, toInteger<std::uint8_t> (v));
    break;
  case F::INT16:
    put (p, toInteger<std::int16_t> (v));
    break;
  case F::UINT16:
    put (p, toInteger<std::uint16_t> (v));
    break;
  case F::INT32:
    put (p, toInteger<std::int32_t> (v));
    break;
  case F::UINT32:
    put (p, toInteger<std::uint32_t> (v));
    break;
  case F::INT64:
    put (p, toInteger<std::int64_t> (v));
    break;
  case F::UINT64:
    put (p, toInteger<std::uint64_t> (v));
    break;
  case F::FLOAT32:
    put (p, static_cast<float> (v));
    break;
  default:
    put (p, v);
  }
}

/** The extra-bytes data type of a field of PCL type \a type and \a count elements; 0
 * with \a ok false when there is none. */
std::uint8_t
extraBytesType (Type type, std::size_t count, bool& ok)
{
  static const std::pair<Type, std::uint8_t> bases[] = {{F::UINT8, 1},
                                                        {F::BOOL, 1},
                                                        {F::INT8, 2},
                                                        {F::UINT16, 3},
                                                        {F::INT16, 4},
                                                        {F::UINT32, 5},
                                                        {F::INT32, 6},
                                                        {F::UINT64, 7},
                                                        {F::INT64, 8},
                                                        {F::FLOAT32, 9},
                                                        {F::FLOAT64, 10}};
  ok = false;
  for (const auto& b : bases)
    if (b.first == type) {
      ok = count >= 1 && (count <= 3 || (b.second == 1 && count <= 255));
      if (!ok)
        return 0;
      return count <= 3 ? static_cast<std::uint8_t> (b.second + 10 * (count - 1)) : 0;
    }
  return 0;
}

/** The PCL type and count LasReader gives the field of descriptor \a d. */
std::pair<Type, std::size_t>
readerFieldType (const LasExtraBytesDescriptor& d)
{
  if (d.baseType() == 0)
    return {F::UINT8, d.size()};
  return {d.isScaled() ? Type (F::FLOAT64) : extraBytesFieldType (d.baseType()),
          static_cast<std::size_t> (d.elements())};
}
} // namespace

bool
RecordEncoder::init (const pcl::PCLPointCloud2& cloud,
                     int format,
                     const Eigen::Vector3d& scale,
                     const Eigen::Vector3d& offset,
                     const Eigen::Vector3d& origin,
                     const LasFileInfo* like,
                     std::string& error)
{
  for (const auto& f : cloud.fields)
    if (f.name != "_" &&
        f.offset + typeSize (f.datatype) * std::max<std::uint32_t> (f.count, 1) >
            cloud.point_step) {
      error = "field " + f.name + " lies outside the " +
              std::to_string (cloud.point_step) + "-byte point";
      return false;
    }
  std::vector<std::string> reserved = {"x", "y", "z", "las_x", "las_y", "las_z", "_"};
  for (int a = 0; a < 3; ++a) {
    coordinates_[a] = findField (cloud, reserved[a]);
    integers_[a] = findField (cloud, reserved[3 + a]);
    if (coordinates_[a].type == 0) {
      error = "the cloud has no " + reserved[a] + " field";
      return false;
    }
  }
  for (int a = 0; a < 3; ++a)
    use_integers_[a] = like != nullptr && integers_[a].type == F::INT32;
  scale_ = scale;
  shift_ = offset - origin;
  origin_minus_offset_ = origin - offset;

  const std::vector<Dimension> standard = standardDimensions (format);
  std::vector<std::string> like_taken = {"x", "y", "z"};
  for (const auto& d : standard) {
    const std::string name = d.name;
    reserved.push_back (name);
    like_taken.push_back (name);
    if (name == "red" || name == "green" || name == "blue") {
      colour_ = true;
      if (name == "red")
        red_at_ = d.offset;
      continue;
    }
    Step s;
    s.from = findField (cloud, name);
    s.to = d.offset;
    s.storage = d.storage;
    s.shift = d.shift;
    s.bits = d.bits;
    s.fallback = name == "return_number" || name == "number_of_returns" ? 1.0 : 0.0;
    steps_.push_back (s);
  }
  red_ = findField (cloud, "red");
  green_ = findField (cloud, "green");
  blue_ = findField (cloud, "blue");
  rgb_ = findField (cloud, "rgb");
  if (colour_) {
    like_taken.push_back ("rgb");
    reserved.push_back ("rgb");
  }
  else if (red_.type != 0 && green_.type != 0 && blue_.type != 0)
    reserved.push_back ("rgb");

  std::vector<std::string> like_names;
  if (like != nullptr)
    like_names = extraBytesFieldNames (like->extra_bytes, like_taken);
  std::size_t at = lasPointRecordLength (format);
  std::vector<int> reused;
  CloudField undescribed;
  // The fields that become extra bytes: those \a like describes first, in its order
  // (so that its record is kept when nothing changed), then the others in cloud order.
  std::vector<std::pair<std::string, int>> extra; // field name, index in like or -1
  for (std::size_t j = 0; j < like_names.size(); ++j) {
    const CloudField from = findField (cloud, like_names[j]);
    if (from.type != 0 &&
        std::find (reserved.begin(), reserved.end(), like_names[j]) == reserved.end() &&
        readerFieldType (like->extra_bytes[j]) ==
            std::make_pair (from.type, from.count))
      extra.emplace_back (like_names[j], static_cast<int> (j));
  }
  for (const auto& field : cloud.fields) {
    const bool taken =
        std::find (reserved.begin(), reserved.end(), field.name) != reserved.end() ||
        std::any_of (extra.begin(), extra.end(), [&field] (const auto& e) {
          return e.first == field.name;
        });
    if (taken)
      continue;
    if (field.name == "extra_bytes" && field.datatype == F::UINT8)
      undescribed = findField (cloud, field.name);
    else
      extra.emplace_back (field.name, -1);
  }
  for (const auto& [name, index] : extra) {
    const CloudField from = findField (cloud, name);
    LasExtraBytesDescriptor d;
    if (index >= 0)
      d = like->extra_bytes[index];
    else {
      bool ok = false;
      d.data_type = extraBytesType (from.type, from.count, ok);
      if (!ok) {
        error = "field " + name + " (type " + std::to_string (from.type) + ", count " +
                std::to_string (from.count) + ") cannot be stored as LAS extra bytes";
        return false;
      }
      d.options = d.data_type == 0 ? static_cast<std::uint8_t> (from.count) : 0;
      d.name = name.substr (0, 32);
    }
    reused.push_back (index);
    const int base = d.baseType();
    const std::size_t elements = base == 0 ? d.size() : d.elements();
    const std::size_t element_size = base == 0 ? 1 : d.elementSize();
    const std::size_t from_size = base == 0 ? 1 : d.isScaled() ? 8 : d.elementSize();
    for (std::size_t k = 0; k < elements; ++k) {
      Step s;
      s.from = {from.offset + k * from_size, from.type, 1};
      s.to = at + k * element_size;
      s.storage = extraBytesFieldType (base);
      s.scaled = base != 0 && d.isScaled();
      s.scale = d.hasScale() ? d.scale[k] : 1.0;
      s.offset = d.hasOffset() ? d.offset[k] : 0.0;
      steps_.push_back (s);
    }
    at += d.size();
    descriptors_.push_back (d);
  }
  for (std::size_t k = 0; k < undescribed.count; ++k) {
    Step s;
    s.from = {undescribed.offset + k, F::UINT8, 1};
    s.to = at + k;
    s.storage = F::UINT8;
    steps_.push_back (s);
  }
  record_length_ = at + undescribed.count;
  keeps_like_ = like != nullptr && reused.size() == like->extra_bytes.size();
  for (std::size_t i = 0; keeps_like_ && i < reused.size(); ++i)
    keeps_like_ = reused[i] == static_cast<int> (i);
  if (record_length_ > 65535) {
    error = "records of " + std::to_string (record_length_) +
            " bytes exceed the 65535 a LAS header can state";
    return false;
  }
  return true;
}

bool
RecordEncoder::encode (const std::uint8_t* point,
                       std::uint8_t* record,
                       std::array<std::int32_t, 3>& xyz,
                       std::string& error) const
{
  std::fill_n (record, record_length_, std::uint8_t (0));
  for (int a = 0; a < 3; ++a) {
    const double v = loadDouble (point + coordinates_[a].offset, coordinates_[a].type);
    if (use_integers_[a]) {
      const std::int32_t i = get<std::int32_t> (point + integers_[a].offset);
      if (static_cast<float> (static_cast<double> (i) * scale_[a] + shift_[a]) ==
          static_cast<float> (v)) {
        xyz[a] = i;
        put (record + 4 * a, i);
        continue;
      }
    }
    if (!std::isfinite (v)) {
      error =
          std::string ("coordinate ") + "xyz"[a] +
          " is not a number: LAS has no missing points (an organised cloud keeps them "
          "as NaN); write .pcd or .ply, or drop the non-finite points";
      return false;
    }
    const double r = std::round ((v + origin_minus_offset_[a]) / scale_[a]);
    if (!(r >= -2147483648.0 && r <= 2147483647.0)) {
      error = std::string ("coordinate ") + "xyz"[a] + " = " + std::to_string (v) +
              " (local) does not fit a 32-bit integer at scale " +
              std::to_string (scale_[a]);
      return false;
    }
    xyz[a] = static_cast<std::int32_t> (r);
    put (record + 4 * a, xyz[a]);
  }
  for (const auto& s : steps_) {
    std::uint8_t* to = record + s.to;
    if (s.bits > 0) {
      const double v = s.from.type == 0
                           ? s.fallback
                           : loadDouble (point + s.from.offset, s.from.type);
      const unsigned mask = (1u << s.bits) - 1;
      *to = static_cast<std::uint8_t> (
          *to |
          ((static_cast<unsigned> (toInteger<std::uint8_t> (v)) & mask) << s.shift));
    }
    else if (s.from.type == 0)
      storeDouble (to, s.storage, s.fallback);
    else if (!s.scaled && s.from.type == s.storage) // as it is (NaN payloads too)
      std::memcpy (to, point + s.from.offset, typeSize (s.storage));
    else if (s.scaled)
      storeDouble (to,
                   s.storage,
                   (loadDouble (point + s.from.offset, s.from.type) - s.offset) /
                       s.scale);
    else if ((s.storage == F::UINT64 || s.storage == F::INT64) &&
             isIntegerType (s.from.type))
      put (to, loadBits64 (point + s.from.offset, s.from.type));
    else
      storeDouble (to, s.storage, loadDouble (point + s.from.offset, s.from.type));
  }
  if (colour_) {
    std::array<std::uint16_t, 3> c{};
    if (red_.type != 0 && green_.type != 0 && blue_.type != 0) {
      c[0] = toInteger<std::uint16_t> (loadDouble (point + red_.offset, red_.type));
      c[1] = toInteger<std::uint16_t> (loadDouble (point + green_.offset, green_.type));
      c[2] = toInteger<std::uint16_t> (loadDouble (point + blue_.offset, blue_.type));
    }
    else if (rgb_.type != 0) {
      const std::uint32_t packed = get<std::uint32_t> (point + rgb_.offset);
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<std::uint16_t> (((packed >> (16 - 8 * k)) & 0xFF) * 257);
    }
    for (int k = 0; k < 3; ++k)
      put (record + red_at_ + 2 * k, c[k]);
  }
  return true;
}
} // namespace las
} // namespace io
} // namespace pcl_ext
