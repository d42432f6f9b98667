/*
 * pcl_ext: LAS point record layouts and their decoding into PCL points.
 */
#include "las_point_layout.h"

#include "las_bytes.h"

#include <algorithm>

namespace pcl_ext {
namespace io {
namespace las {
namespace {
using F = pcl::PCLPointField;

/** The wave packet dimensions (formats 4, 5, 9, 10) starting at byte \a at. */
void
addWavePacket (std::vector<Dimension>& d, std::size_t at)
{
  d.push_back ({"wave_packet_descriptor_index", at, F::UINT8, 0, 0, F::UINT8});
  d.push_back ({"wave_packet_offset", at + 1, F::UINT64, 0, 0, F::UINT64});
  d.push_back ({"wave_packet_size", at + 9, F::UINT32, 0, 0, F::UINT32});
  d.push_back ({"wave_return_location", at + 13, F::FLOAT32, 0, 0, F::FLOAT32});
  d.push_back ({"wave_x_t", at + 17, F::FLOAT32, 0, 0, F::FLOAT32});
  d.push_back ({"wave_y_t", at + 21, F::FLOAT32, 0, 0, F::FLOAT32});
  d.push_back ({"wave_z_t", at + 25, F::FLOAT32, 0, 0, F::FLOAT32});
}

void
addColour (std::vector<Dimension>& d, std::size_t at)
{
  d.push_back ({"red", at, F::UINT16, 0, 0, F::UINT16});
  d.push_back ({"green", at + 2, F::UINT16, 0, 0, F::UINT16});
  d.push_back ({"blue", at + 4, F::UINT16, 0, 0, F::UINT16});
}

/** One field of every record of a block: out = convert (in). */
template <typename In, typename Out, typename Convert>
inline void
column (const std::uint8_t* src,
        std::size_t record_length,
        std::uint8_t* dst,
        std::size_t step,
        std::size_t n,
        Convert convert)
{
  for (std::size_t i = 0; i < n; ++i, src += record_length, dst += step)
    put<Out> (dst, convert (get<In> (src)));
}

template <typename T>
inline void
copyColumn (const std::uint8_t* src,
            std::size_t record_length,
            std::uint8_t* dst,
            std::size_t step,
            std::size_t n)
{
  column<T, T> (src, record_length, dst, step, n, [] (T v) { return v; });
}

template <typename In>
inline void
scaledColumn (const DecodeStep& s,
              const std::uint8_t* src,
              std::size_t record_length,
              std::uint8_t* dst,
              std::size_t step,
              std::size_t n)
{
  const double scale = s.scale, offset = s.offset;
  column<In, double> (src, record_length, dst, step, n, [scale, offset] (In v) {
    return static_cast<double> (v) * scale + offset;
  });
}
} // namespace

std::size_t
typeSize (Type type)
{
  switch (type) {
  case F::INT8:
  case F::UINT8:
    return 1;
  case F::INT16:
  case F::UINT16:
    return 2;
  case F::INT32:
  case F::UINT32:
  case F::FLOAT32:
    return 4;
  default:
    return 8;
  }
}

std::vector<Dimension>
standardDimensions (int format)
{
  std::vector<Dimension> d;
  if (format < 0 || format > 10)
    return d;
  d.push_back ({"intensity", 12, F::UINT16, 0, 0, F::FLOAT32});
  if (format <= 5) {
    d.push_back ({"return_number", 14, F::UINT8, 0, 3, F::UINT8});
    d.push_back ({"number_of_returns", 14, F::UINT8, 3, 3, F::UINT8});
    d.push_back ({"scan_direction_flag", 14, F::UINT8, 6, 1, F::UINT8});
    d.push_back ({"edge_of_flight_line", 14, F::UINT8, 7, 1, F::UINT8});
    d.push_back ({"classification", 15, F::UINT8, 0, 5, F::UINT8});
    d.push_back ({"flags", 15, F::UINT8, 5, 3, F::UINT8});
    d.push_back ({"scan_angle_rank", 16, F::INT8, 0, 0, F::INT8});
    d.push_back ({"user_data", 17, F::UINT8, 0, 0, F::UINT8});
    d.push_back ({"point_source_id", 18, F::UINT16, 0, 0, F::UINT16});
    const bool time = format != 0 && format != 2;
    if (time)
      d.push_back ({"gps_time", 20, F::FLOAT64, 0, 0, F::FLOAT64});
    std::size_t end = time ? 28 : 20;
    if (format == 2 || format == 3 || format == 5) {
      addColour (d, end);
      end += 6;
    }
    if (format == 4 || format == 5)
      addWavePacket (d, end);
    return d;
  }
  d.push_back ({"return_number", 14, F::UINT8, 0, 4, F::UINT8});
  d.push_back ({"number_of_returns", 14, F::UINT8, 4, 4, F::UINT8});
  d.push_back ({"flags", 15, F::UINT8, 0, 4, F::UINT8});
  d.push_back ({"scanner_channel", 15, F::UINT8, 4, 2, F::UINT8});
  d.push_back ({"scan_direction_flag", 15, F::UINT8, 6, 1, F::UINT8});
  d.push_back ({"edge_of_flight_line", 15, F::UINT8, 7, 1, F::UINT8});
  d.push_back ({"classification", 16, F::UINT8, 0, 0, F::UINT8});
  d.push_back ({"user_data", 17, F::UINT8, 0, 0, F::UINT8});
  d.push_back ({"scan_angle", 18, F::INT16, 0, 0, F::INT16});
  d.push_back ({"point_source_id", 20, F::UINT16, 0, 0, F::UINT16});
  d.push_back ({"gps_time", 22, F::FLOAT64, 0, 0, F::FLOAT64});
  std::size_t end = 30;
  if (format == 7 || format == 8 || format == 10) {
    addColour (d, end);
    end += 6;
  }
  if (format == 8 || format == 10) {
    d.push_back ({"nir", end, F::UINT16, 0, 0, F::UINT16});
    end += 2;
  }
  if (format == 9 || format == 10)
    addWavePacket (d, end);
  return d;
}

bool
hasColour (int format, std::size_t* red_offset)
{
  for (const auto& d : standardDimensions (format))
    if (std::string (d.name) == "red") {
      if (red_offset)
        *red_offset = d.offset;
      return true;
    }
  return false;
}

Type
extraBytesFieldType (int base)
{
  static const Type types[] = {F::UINT8,
                               F::UINT8,
                               F::INT8,
                               F::UINT16,
                               F::INT16,
                               F::UINT32,
                               F::INT32,
                               F::UINT64,
                               F::INT64,
                               F::FLOAT32,
                               F::FLOAT64};
  return base >= 0 && base <= 10 ? types[base] : Type (F::UINT8);
}

std::vector<std::string>
extraBytesFieldNames (const std::vector<LasExtraBytesDescriptor>& descriptors,
                      std::vector<std::string>& taken)
{
  std::vector<std::string> names;
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    std::string name = descriptors[i].name.empty() ? "extra_bytes_" + std::to_string (i)
                                                   : descriptors[i].name;
    while (std::find (taken.begin(), taken.end(), name) != taken.end())
      name += "_extra";
    taken.push_back (name);
    names.push_back (name);
  }
  return names;
}

PointLayout
makePointLayout (int format,
                 std::size_t record_length,
                 const std::vector<LasExtraBytesDescriptor>& extra)
{
  PointLayout layout;
  std::vector<std::string> taken;
  auto add = [&layout, &taken] (const std::string& name, Type type, std::size_t count) {
    const std::size_t size = typeSize (type);
    const std::size_t at = (layout.point_step + size - 1) / size * size;
    pcl::PCLPointField f;
    f.name = name;
    f.offset = static_cast<std::uint32_t> (at);
    f.datatype = type;
    f.count = static_cast<std::uint32_t> (count);
    layout.fields.push_back (f);
    layout.point_step = static_cast<std::uint32_t> (at + size * count);
    taken.push_back (name);
    return at;
  };
  auto step = [&layout] (DecodeStep::Kind kind, std::size_t src, std::size_t dst) {
    DecodeStep s;
    s.kind = kind;
    s.src = src;
    s.dst = dst;
    layout.steps.push_back (s);
    return &layout.steps.back();
  };

  for (int axis = 0; axis < 3; ++axis)
    step (DecodeStep::Coordinate,
          4 * axis,
          add (std::string (1, "xyz"[axis]), F::FLOAT32, 1))
        ->axis = axis;
  for (const auto& d : standardDimensions (format)) {
    const std::size_t at = add (d.name, d.field, 1);
    if (d.bits > 0) {
      auto* s = step (DecodeStep::Bits, d.offset, at);
      s->shift = d.shift;
      s->mask = static_cast<std::uint8_t> ((1u << d.bits) - 1);
    }
    else if (d.storage != d.field)
      step (DecodeStep::Intensity, d.offset, at);
    else
      step (DecodeStep::Copy, d.offset, at)->bytes = typeSize (d.field);
  }
  std::size_t red = 0;
  if (hasColour (format, &red))
    step (DecodeStep::Rgb, red, add ("rgb", F::FLOAT32, 1));

  std::size_t src = lasPointRecordLength (format);
  const auto names = extraBytesFieldNames (extra, taken);
  for (std::size_t i = 0; i < extra.size(); ++i) {
    const auto& e = extra[i];
    const int base = e.baseType();
    if (!e.isScaled() || base == 0) {
      const Type type = extraBytesFieldType (base);
      const std::size_t count = base == 0 ? e.size() : e.elements();
      step (DecodeStep::Copy, src, add (names[i], type, count))->bytes = e.size();
    }
    else {
      const std::size_t at = add (names[i], F::FLOAT64, e.elements());
      for (int k = 0; k < e.elements(); ++k) {
        auto* s = step (DecodeStep::Scaled, src + k * e.elementSize(), at + 8 * k);
        s->base = base;
        s->scale = e.hasScale() ? e.scale[k] : 1.0;
        s->offset = e.hasOffset() ? e.offset[k] : 0.0;
      }
    }
    src += e.size();
  }
  for (int axis = 0; axis < 3; ++axis)
    step (DecodeStep::Copy,
          4 * axis,
          add (std::string ("las_") + "xyz"[axis], F::INT32, 1))
        ->bytes = 4;
  if (record_length > src) {
    std::string name = "extra_bytes";
    while (std::find (taken.begin(), taken.end(), name) != taken.end())
      name += "_extra";
    step (DecodeStep::Copy, src, add (name, F::UINT8, record_length - src))->bytes =
        record_length - src;
  }
  // Whole points of 8-byte fields stay aligned from one point to the next.
  layout.point_step = (layout.point_step + 7) / 8 * 8;
  return layout;
}

namespace {
void
decodeSmallBlock (const PointLayout& layout,
                  const CoordinateTransform& transform,
                  int colour_shift,
                  const std::uint8_t* records,
                  std::size_t record_length,
                  std::size_t n,
                  std::uint8_t* out)
{
  const std::size_t ps = layout.point_step;
  for (const auto& s : layout.steps) {
    const std::uint8_t* src = records + s.src;
    std::uint8_t* dst = out + s.dst;
    switch (s.kind) {
    case DecodeStep::Copy:
      switch (s.bytes) {
      case 1:
        copyColumn<std::uint8_t> (src, record_length, dst, ps, n);
        break;
      case 2:
        copyColumn<std::uint16_t> (src, record_length, dst, ps, n);
        break;
      case 4:
        copyColumn<std::uint32_t> (src, record_length, dst, ps, n);
        break;
      case 8:
        copyColumn<std::uint64_t> (src, record_length, dst, ps, n);
        break;
      default:
        for (std::size_t i = 0; i < n; ++i)
          std::memcpy (dst + i * ps, src + i * record_length, s.bytes);
      }
      break;
    case DecodeStep::Bits: {
      const int shift = s.shift;
      const std::uint8_t mask = s.mask;
      column<std::uint8_t, std::uint8_t> (
          src, record_length, dst, ps, n, [shift, mask] (std::uint8_t v) {
            return static_cast<std::uint8_t> ((v >> shift) & mask);
          });
      break;
    }
    case DecodeStep::Intensity:
      column<std::uint16_t, float> (
          src, record_length, dst, ps, n, [] (std::uint16_t v) {
            return static_cast<float> (v);
          });
      break;
    case DecodeStep::Coordinate: {
      const double scale = transform.scale[s.axis], shift = transform.shift[s.axis];
      column<std::int32_t, float> (
          src, record_length, dst, ps, n, [scale, shift] (std::int32_t v) {
            return static_cast<float> (static_cast<double> (v) * scale + shift);
          });
      break;
    }
    case DecodeStep::Rgb:
      for (std::size_t i = 0; i < n; ++i, src += record_length, dst += ps) {
        const std::uint32_t r = get<std::uint16_t> (src) >> colour_shift,
                            g = get<std::uint16_t> (src + 2) >> colour_shift,
                            b = get<std::uint16_t> (src + 4) >> colour_shift;
        put<std::uint32_t> (dst,
                            (std::min (r, 255u) << 16) | (std::min (g, 255u) << 8) |
                                std::min (b, 255u));
      }
      break;
    case DecodeStep::Scaled:
      switch (s.base) {
      case 1:
        scaledColumn<std::uint8_t> (s, src, record_length, dst, ps, n);
        break;
      case 2:
        scaledColumn<std::int8_t> (s, src, record_length, dst, ps, n);
        break;
      case 3:
        scaledColumn<std::uint16_t> (s, src, record_length, dst, ps, n);
        break;
      case 4:
        scaledColumn<std::int16_t> (s, src, record_length, dst, ps, n);
        break;
      case 5:
        scaledColumn<std::uint32_t> (s, src, record_length, dst, ps, n);
        break;
      case 6:
        scaledColumn<std::int32_t> (s, src, record_length, dst, ps, n);
        break;
      case 7:
        scaledColumn<std::uint64_t> (s, src, record_length, dst, ps, n);
        break;
      case 8:
        scaledColumn<std::int64_t> (s, src, record_length, dst, ps, n);
        break;
      case 9:
        scaledColumn<float> (s, src, record_length, dst, ps, n);
        break;
      default:
        scaledColumn<double> (s, src, record_length, dst, ps, n);
      }
      break;
    }
  }
}
} // namespace

void
decodeRecords (const PointLayout& layout,
               const CoordinateTransform& transform,
               int colour_shift,
               const std::uint8_t* records,
               std::size_t record_length,
               std::size_t n,
               std::uint8_t* out)
{
  // One field at a time over a few records: the records and their points stay in the
  // first-level cache while every field is decoded.
  constexpr std::size_t kSmallBlock = 128;
  for (std::size_t first = 0; first < n; first += kSmallBlock)
    decodeSmallBlock (layout,
                      transform,
                      colour_shift,
                      records + first * record_length,
                      record_length,
                      std::min (kSmallBlock, n - first),
                      out + first * layout.point_step);
}
} // namespace las
} // namespace io
} // namespace pcl_ext
