/*
 * pcl_ext: the layout of LAZ point data: the LASzip VLR and the chunk table.
 */
#pragma once

#include <pcl_ext/io/laz_arithmetic_decoder.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief The item types of the LASzip VLR (LASzip compressed format, "items"). */
enum class LazItemType : std::uint16_t {
  Byte = 0,          ///< extra bytes of point formats 0-5
  Point10 = 6,       ///< the 20 core bytes of point formats 0-5
  GpsTime11 = 7,     ///< GPS time of point formats 1, 3, 4, 5
  Rgb12 = 8,         ///< colour of point formats 2, 3, 5
  WavePacket13 = 9,  ///< wave packet of point formats 4, 5
  Point14 = 10,      ///< the 30 core bytes of point formats 6-10
  Rgb14 = 11,        ///< colour of point format 7
  RgbNir14 = 12,     ///< colour and near infrared of point formats 8, 10
  WavePacket14 = 13, ///< wave packet of point formats 9, 10
  Byte14 = 14        ///< extra bytes of point formats 6-10
};

/** \brief One item of the LASzip VLR: a group of record bytes and its coding. */
struct LazItem {
  std::uint16_t type = 0;    ///< a LazItemType
  std::uint16_t size = 0;    ///< bytes of the record it covers
  std::uint16_t version = 0; ///< coding version (2: pointwise, 3 and 4: layered)
};

/** \brief The compressors of the LASzip VLR. */
enum class LazCompressor : std::uint16_t {
  None = 0,
  Pointwise = 1,
  PointwiseChunked = 2,
  LayeredChunked = 3
};

/** \brief The payload of the LASzip VLR (user id "laszip encoded", record id 22204;
 * LASzip compressed format, "the LASzip VLR"): 34 bytes and 6 per item. */
struct LaszipVlr {
  std::uint16_t compressor = 0; ///< a LazCompressor
  std::uint16_t coder = 0;      ///< 0: arithmetic coder
  std::uint8_t version_major = 0;
  std::uint8_t version_minor = 0;
  std::uint16_t version_revision = 0;
  std::uint32_t options = 0;
  std::uint32_t chunk_size = 0; ///< points a chunk; 0xFFFFFFFF (or 0): variable
  std::vector<LazItem> items;

  /** \brief Chunks of variable point counts, given by the chunk table (as in COPC). */
  bool
  variableChunks () const
  {
    return chunk_size == 0xFFFFFFFFu || chunk_size == 0;
  }

  /** \brief The bytes of a record: the sum of the item sizes. */
  std::size_t
  recordLength () const;
};

/** \brief Parse the LASzip VLR payload and check that pcl_ext can decode it for the
 * given point format.
 *
 * Accepted: the pointwise chunked compressor with POINT10, GPSTIME11, RGB12 and BYTE
 * items of version 2 for point formats 0-3; the layered chunked compressor with
 * POINT14, RGB14, RGBNIR14 and BYTE14 items of version 3 or 4 (2 is read as 3, as
 * LASzip does) for point formats 6-8. The items must be those of the point format, in
 * its order, with a BYTE item for the extra bytes, and must add up to \a record_length.
 * \param[in] payload the VLR's data
 * \param[in] point_format the LAS point format, 0-10 (compression bits cleared)
 * \param[in] record_length the header's point record length
 * \throw LazDataError naming what is wrong or unsupported: a size that is not 34 + 6 n,
 * a compressor other than 2 and 3, another coder, unknown or missing items, v1 items,
 * wave packets (point formats 4, 5, 9, 10), item sizes that do not match the record
 * length */
LaszipVlr
parseLaszipVlr (const std::vector<std::uint8_t>& payload,
                int point_format,
                std::size_t record_length);

/** \brief One entry of the chunk table. */
struct LazChunk {
  std::uint64_t point_count = 0; ///< points in the chunk (variable chunks only, else 0)
  std::uint64_t byte_count = 0;  ///< compressed bytes of the chunk
};

/** \brief Decode the body of a chunk table: the arithmetic-coded entries after its
 * 8-byte header (version 0, chunk count; LASzip compressed format, "chunk table").
 *
 * Each entry is predicted from the previous one with a 32-bit integer decoder of two
 * contexts: the point count (variable chunks only, context 0), then the byte count
 * (context 1). \param[in] data the bytes after the header, up to the end of the file
 * \param[in] size their number
 * \param[in] chunk_count the chunk count of the header
 * \param[in] variable_chunks whether the entries hold point counts
 * \throw LazDataError when the bytes end too early or a chunk has no byte */
std::vector<LazChunk>
decodeLazChunkTable (const std::uint8_t* data,
                     std::size_t size,
                     std::uint32_t chunk_count,
                     bool variable_chunks);
} // namespace io
} // namespace pcl_ext
