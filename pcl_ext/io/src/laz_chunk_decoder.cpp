/*
 * pcl_ext: decoding one LAZ chunk held in memory, pointwise or layered.
 */
#include <pcl_ext/io/laz_chunk_decoder.h>

#include "laz_item_decoder.h"

#include <cstring>
#include <string>

namespace pcl_ext {
namespace io {
struct LazChunkDecoder::Impl {
  bool layered = false;
  std::size_t record_length = 0;
  std::vector<LazItem> items;
  std::vector<std::size_t> item_offsets;
  LazArithmeticDecoder dec; // the stream of a pointwise chunk
  std::vector<std::unique_ptr<laz_detail::ItemDecoder>> decoders;
  std::vector<laz_detail::Layer> layers; // of all items, in item order
  std::size_t layer_count = 0;

  // The chunk being decoded
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
  bool started = false;    // a chunk was given
  bool first_done = false; // its first (raw) record was output
  std::size_t used = 0;
  std::uint32_t stated_count = 0;
  unsigned context = 0;

  void
  decodeFirst (std::uint8_t* out)
  {
    if (size < record_length)
      throw LazDataError ("the chunk has " + std::to_string (size) +
                          " bytes, fewer than one raw record (" +
                          std::to_string (record_length) + ")");
    std::memcpy (out, data, record_length);
    context = 0;
    if (layered) {
      for (std::size_t i = 0; i < decoders.size(); ++i) {
        const laz_detail::Layer* l = layers.data();
        for (std::size_t j = 0; j < i; ++j)
          l += decoders[j]->layerCount();
        decoders[i]->startChunk (out + item_offsets[i], l, context);
      }
    }
    else {
      for (std::size_t i = 0; i < decoders.size(); ++i)
        decoders[i]->startChunk (out + item_offsets[i], nullptr, context);
      dec.init (data + record_length, data + size);
    }
    first_done = true;
  }

  void
  readLayeredHeader ()
  {
    const std::size_t header = record_length + 4 + 4 * layer_count;
    if (size < header)
      throw LazDataError ("the layered chunk has " + std::to_string (size) +
                          " bytes, fewer than its header (" + std::to_string (header) +
                          ")");
    stated_count = laz_detail::loadU32 (data + record_length);
    std::size_t offset = header;
    for (std::size_t i = 0; i < layer_count; ++i) {
      const std::size_t bytes = laz_detail::loadU32 (data + record_length + 4 + 4 * i);
      if (bytes > size - offset)
        throw LazDataError ("layer " + std::to_string (i) + " of " +
                            std::to_string (bytes) + " bytes ends past the chunk (" +
                            std::to_string (size) + " bytes)");
      layers[i].data = data + offset;
      layers[i].size = bytes;
      offset += bytes;
    }
    used = offset;
  }
};

LazChunkDecoder::LazChunkDecoder (const LaszipVlr& vlr)
: impl_ (std::make_unique<Impl>())
{
  Impl& d = *impl_;
  d.layered =
      vlr.compressor == static_cast<std::uint16_t> (LazCompressor::LayeredChunked);
  d.items = vlr.items;
  for (const auto& item : vlr.items) {
    d.item_offsets.push_back (d.record_length);
    d.record_length += item.size;
    if (d.layered)
      d.decoders.push_back (laz_detail::makeLayeredItemDecoder (item));
    else
      d.decoders.push_back (laz_detail::makePointwiseItemDecoder (item, d.dec));
    d.layer_count += d.decoders.back()->layerCount();
  }
  d.layers.resize (d.layer_count);
}

LazChunkDecoder::~LazChunkDecoder() = default;

std::size_t
LazChunkDecoder::recordLength() const
{
  return impl_->record_length;
}

void
LazChunkDecoder::startChunk (const std::uint8_t* data, std::size_t size)
{
  Impl& d = *impl_;
  d.data = data;
  d.size = size;
  d.started = true;
  d.first_done = false;
  d.used = 0;
  d.stated_count = 0;
  if (d.layered)
    d.readLayeredHeader();
}

void
LazChunkDecoder::decode (std::size_t n, std::uint8_t* out)
{
  Impl& d = *impl_;
  if (!d.started)
    throw LazDataError ("no chunk was started");
  if (n == 0)
    return;
  if (!d.first_done) {
    d.decodeFirst (out);
    out += d.record_length;
    --n;
  }
  const std::size_t count = d.decoders.size();
  for (; n > 0; --n, out += d.record_length)
    for (std::size_t i = 0; i < count; ++i)
      d.decoders[i]->decode (out + d.item_offsets[i], d.context);
}

std::size_t
LazChunkDecoder::bytesUsed() const
{
  const Impl& d = *impl_;
  if (d.layered)
    return d.used;
  if (!d.first_done)
    return 0;
  return d.record_length + d.dec.bytesRead();
}

std::uint32_t
LazChunkDecoder::statedPointCount() const
{
  return impl_->stated_count;
}
} // namespace io
} // namespace pcl_ext
