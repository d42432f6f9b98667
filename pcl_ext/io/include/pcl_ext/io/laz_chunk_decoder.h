/*
 * pcl_ext: decoding the chunks of LAZ point data held in memory.
 */
#pragma once

#include <pcl_ext/io/laz_format.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Decodes the chunks of LAZ point data into raw LAS point records (LASzip
 * compressed format, "pointwise chunked" and "layered chunked" compressors).
 *
 * Pointwise chunk: the first record raw, then one arithmetic-coded stream in which the
 * items of each record follow each other (POINT10, GPSTIME11, RGB12, BYTE v2). Layered
 * chunk: the first record raw, the point count (uint32), the byte count of every layer
 * of every item (uint32 each; POINT14 has nine layers, RGB14 one, RGBNIR14 two, BYTE14
 * one per byte), then the layers one after the other, each its own arithmetic-coded
 * stream.
 *
 * A chunk is decoded a few records at a time, so that no more than the caller's buffer
 * is needed however many points the chunk claims. Every read stays inside the chunk's
 * bytes; corrupt data gives LazDataError (or wrong records), never a read past the end.
 *
 * \code
 * LazChunkDecoder decoder (parseLaszipVlr (vlr_payload, 3, 34));
 * decoder.startChunk (chunk.data(), chunk.size());
 * decoder.decode (1000, records.data()); // the first 1000 records of the chunk
 * \endcode */
class LazChunkDecoder {
public:
  /** \param[in] vlr the LASzip VLR, as parseLaszipVlr returns it */
  explicit LazChunkDecoder (const LaszipVlr& vlr);
  ~LazChunkDecoder();
  LazChunkDecoder (const LazChunkDecoder&) = delete;
  LazChunkDecoder&
  operator= (const LazChunkDecoder&) = delete;

  /** \brief The bytes of a record. */
  std::size_t
  recordLength () const;

  /** \brief Start the chunk held in [data, data + size). The bytes must stay valid
   * while its records are decoded. A layered chunk's header is read here.
   * \throw LazDataError when the chunk is shorter than its header says */
  void
  startChunk (const std::uint8_t* data, std::size_t size);

  /** \brief Decode the next \a n records of the chunk into \a out (n times
   * recordLength() bytes). \throw LazDataError on corrupt or truncated data */
  void
  decode (std::size_t n, std::uint8_t* out);

  /** \brief The bytes of the chunk used so far: the whole chunk for a layered chunk
   * (known from its header); the first record and the bytes read by the decoder for a
   * pointwise chunk, which tells where the next chunk starts when there is no chunk
   * table. */
  std::size_t
  bytesUsed () const;

  /** \brief The point count a layered chunk states in its header (0 for pointwise
   * chunks, which do not state it). */
  std::uint32_t
  statedPointCount () const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace io
} // namespace pcl_ext
