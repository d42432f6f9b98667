/*
 * pcl_ext: the LASzip VLR and the chunk table of LAZ point data.
 */
#include <pcl_ext/io/laz_format.h>

#include <string>

namespace pcl_ext {
namespace io {
namespace {
std::uint16_t
u16 (const std::uint8_t* p)
{
  return static_cast<std::uint16_t> (p[0] | (p[1] << 8));
}

std::uint32_t
u32 (const std::uint8_t* p)
{
  return std::uint32_t (u16 (p)) | (std::uint32_t (u16 (p + 2)) << 16);
}

const char*
itemName (std::uint16_t type)
{
  switch (static_cast<LazItemType> (type)) {
  case LazItemType::Byte:
    return "BYTE";
  case LazItemType::Point10:
    return "POINT10";
  case LazItemType::GpsTime11:
    return "GPSTIME11";
  case LazItemType::Rgb12:
    return "RGB12";
  case LazItemType::WavePacket13:
    return "WAVEPACKET13";
  case LazItemType::Point14:
    return "POINT14";
  case LazItemType::Rgb14:
    return "RGB14";
  case LazItemType::RgbNir14:
    return "RGBNIR14";
  case LazItemType::WavePacket14:
    return "WAVEPACKET14";
  case LazItemType::Byte14:
    return "BYTE14";
  }
  return nullptr;
}

/** The fixed items of a point format, in record order (ASPRS LAS 1.4 R15, 2.6-2.16). */
std::vector<LazItemType>
formatItems (int point_format)
{
  using T = LazItemType;
  switch (point_format) {
  case 0:
    return {T::Point10};
  case 1:
    return {T::Point10, T::GpsTime11};
  case 2:
    return {T::Point10, T::Rgb12};
  case 3:
    return {T::Point10, T::GpsTime11, T::Rgb12};
  case 4:
    return {T::Point10, T::GpsTime11, T::WavePacket13};
  case 5:
    return {T::Point10, T::GpsTime11, T::Rgb12, T::WavePacket13};
  case 6:
    return {T::Point14};
  case 7:
    return {T::Point14, T::Rgb14};
  case 8:
    return {T::Point14, T::RgbNir14};
  case 9:
    return {T::Point14, T::WavePacket14};
  case 10:
    return {T::Point14, T::RgbNir14, T::WavePacket14};
  default:
    return {};
  }
}

std::uint16_t
fixedItemSize (LazItemType type)
{
  switch (type) {
  case LazItemType::Point10:
    return 20;
  case LazItemType::GpsTime11:
    return 8;
  case LazItemType::Rgb12:
  case LazItemType::Rgb14:
    return 6;
  case LazItemType::WavePacket13:
  case LazItemType::WavePacket14:
    return 29;
  case LazItemType::Point14:
    return 30;
  case LazItemType::RgbNir14:
    return 8;
  default:
    return 0;
  }
}
} // namespace

std::size_t
LaszipVlr::recordLength() const
{
  std::size_t length = 0;
  for (const auto& item : items)
    length += item.size;
  return length;
}

LaszipVlr
parseLaszipVlr (const std::vector<std::uint8_t>& payload,
                int point_format,
                std::size_t record_length)
{
  if (payload.size() < 34 || (payload.size() - 34) % 6 != 0)
    throw LazDataError ("the LASzip VLR has " + std::to_string (payload.size()) +
                        " bytes, not 34 + 6 per item");
  const std::uint8_t* p = payload.data();
  LaszipVlr vlr;
  vlr.compressor = u16 (p);
  vlr.coder = u16 (p + 2);
  vlr.version_major = p[4];
  vlr.version_minor = p[5];
  vlr.version_revision = u16 (p + 6);
  vlr.options = u32 (p + 8);
  vlr.chunk_size = u32 (p + 12);
  const std::size_t item_count = u16 (p + 32);
  if (item_count == 0 || item_count != (payload.size() - 34) / 6)
    throw LazDataError ("the LASzip VLR announces " + std::to_string (item_count) +
                        " items but holds " +
                        std::to_string ((payload.size() - 34) / 6));
  for (std::size_t i = 0; i < item_count; ++i) {
    const std::uint8_t* q = p + 34 + 6 * i;
    vlr.items.push_back ({u16 (q), u16 (q + 2), u16 (q + 4)});
  }

  if (vlr.compressor == static_cast<std::uint16_t> (LazCompressor::None))
    throw LazDataError ("the LASzip VLR says the points are not compressed");
  if (vlr.compressor == static_cast<std::uint16_t> (LazCompressor::Pointwise))
    throw LazDataError (
        "pointwise compression without chunks (compressor 1) is not supported");
  if (vlr.compressor != static_cast<std::uint16_t> (LazCompressor::PointwiseChunked) &&
      vlr.compressor != static_cast<std::uint16_t> (LazCompressor::LayeredChunked))
    throw LazDataError ("unknown LASzip compressor " + std::to_string (vlr.compressor));
  if (vlr.coder != 0)
    throw LazDataError ("unknown LASzip coder " + std::to_string (vlr.coder));

  const std::vector<LazItemType> expected = formatItems (point_format);
  if (expected.empty())
    throw LazDataError ("point format " + std::to_string (point_format) +
                        " is not a LAS point format (0-10)");
  const bool layered = point_format >= 6;
  if (layered !=
      (vlr.compressor == static_cast<std::uint16_t> (LazCompressor::LayeredChunked)))
    throw LazDataError (std::string ("point format ") + std::to_string (point_format) +
                        (layered ? " needs the layered chunked compressor (3)"
                                 : " needs the pointwise chunked compressor (2)"));

  std::size_t total = 0;
  for (std::size_t i = 0; i < vlr.items.size(); ++i) {
    const LazItem& item = vlr.items[i];
    const char* name = itemName (item.type);
    if (!name)
      throw LazDataError ("unknown LASzip item type " + std::to_string (item.type));
    const auto type = static_cast<LazItemType> (item.type);
    const LazItemType extra = layered ? LazItemType::Byte14 : LazItemType::Byte;
    if (i < expected.size()) {
      if (type != expected[i])
        throw LazDataError ("item " + std::to_string (i) + " is " + name +
                            ", point format " + std::to_string (point_format) +
                            " expects " +
                            itemName (static_cast<std::uint16_t> (expected[i])));
      if (item.size != fixedItemSize (type))
        throw LazDataError (std::string (name) + " item of " +
                            std::to_string (item.size) + " bytes, expected " +
                            std::to_string (fixedItemSize (type)));
    }
    else if (i > expected.size() || type != extra || item.size == 0)
      throw LazDataError (std::string ("unexpected ") + name +
                          " item after the items of point format " +
                          std::to_string (point_format));
    if (type == LazItemType::WavePacket13 || type == LazItemType::WavePacket14)
      throw LazDataError ("wave packets (point formats 4, 5, 9, 10) are not supported");
    if (!layered && item.version != 2)
      throw LazDataError (std::string (name) + " version " +
                          std::to_string (item.version) +
                          " is not supported (only version 2)");
    if (layered && (item.version < 2 || item.version > 4))
      throw LazDataError (std::string (name) + " version " +
                          std::to_string (item.version) +
                          " is not supported (only versions 3 and 4)");
    total += item.size;
  }
  if (vlr.items.size() < expected.size())
    throw LazDataError ("the LASzip VLR has " + std::to_string (vlr.items.size()) +
                        " items, point format " + std::to_string (point_format) +
                        " needs at least " + std::to_string (expected.size()));
  if (total != record_length)
    throw LazDataError ("the LASzip items cover " + std::to_string (total) +
                        " bytes, the record length is " +
                        std::to_string (record_length));
  return vlr;
}

std::vector<LazChunk>
decodeLazChunkTable (const std::uint8_t* data,
                     std::size_t size,
                     std::uint32_t chunk_count,
                     bool variable_chunks)
{
  std::vector<LazChunk> chunks;
  if (chunk_count == 0)
    return chunks;
  LazArithmeticDecoder dec;
  dec.init (data, data + size);
  LazIntegerDecompressor ic (32, 2);
  std::uint32_t last_points = 0, last_bytes = 0;
  for (std::uint32_t i = 0; i < chunk_count; ++i) {
    LazChunk chunk;
    if (variable_chunks) {
      last_points = static_cast<std::uint32_t> (
          ic.decompress (dec, static_cast<std::int32_t> (last_points), 0));
      chunk.point_count = last_points;
    }
    last_bytes = static_cast<std::uint32_t> (
        ic.decompress (dec, static_cast<std::int32_t> (last_bytes), 1));
    chunk.byte_count = last_bytes;
    if (chunk.byte_count == 0)
      throw LazDataError ("chunk " + std::to_string (i) +
                          " of the chunk table has no byte");
    chunks.push_back (chunk);
  }
  return chunks;
}
} // namespace io
} // namespace pcl_ext
