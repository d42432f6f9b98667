/*
 * pcl_ext: what every LAZ item decoder offers, and the small pieces they share
 * (little-endian fields, the streaming median of the coordinate differences, the
 * return-number context tables).
 */
#pragma once

#include <pcl_ext/io/laz_arithmetic_decoder.h>
#include <pcl_ext/io/laz_format.h>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace pcl_ext {
namespace io {
namespace laz_detail {
/** \brief The bytes of one layer of a layered chunk. */
struct Layer {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

/** \brief Decodes one item (a fixed group of record bytes) point after point.
 *
 * Pointwise items (v2) share the chunk's decoder; layered items (v3, v4) own one
 * decoder per layer. \a context is the scanner channel the POINT14 item hands to the
 * items after it (LASzip compressed format, "layered chunked": the models of each item
 * are kept per scanner channel). */
class ItemDecoder {
public:
  virtual ~ItemDecoder() = default;

  /** \brief How many layers the item has in a layered chunk; 0 for pointwise items. */
  virtual std::size_t
  layerCount () const = 0;

  /** \brief Start a chunk whose first item, stored raw, is \a item; \a layers holds
   * layerCount() layers (layered items only). */
  virtual void
  startChunk (const std::uint8_t* item, const Layer* layers, unsigned& context) = 0;

  /** \brief Decode the next item of the chunk into \a item. */
  virtual void
  decode (std::uint8_t* item, unsigned& context) = 0;
};

/** \brief The start of a chunk, the same for every layered item: the decoder of each of
 * the \a count \a layers that has bytes starts on them, and \a changed says which did
 * (an empty layer: the field kept its value all through the chunk); every scanner
 * channel's context is marked unused, to be set up again from the chunk's first item.
 * \a decoders and \a changed are indexed by layer (arrays or vectors). */
template <typename Decoders, typename Changed, typename Context>
void
startLayers (const Layer* layers,
             std::size_t count,
             Decoders& decoders,
             Changed& changed,
             std::unique_ptr<Context> (&contexts)[4])
{
  for (std::size_t i = 0; i < count; ++i) {
    changed[i] = layers[i].size > 0;
    if (changed[i])
      decoders[i].init (layers[i].data, layers[i].data + layers[i].size);
  }
  for (auto& c : contexts)
    if (c)
      c->unused = true;
}

/** \brief The decoder of a pointwise (v2) item, reading from \a dec. */
std::unique_ptr<ItemDecoder>
makePointwiseItemDecoder (const LazItem& item, LazArithmeticDecoder& dec);

/** \brief The decoder of a layered (v3 or v4) item. */
std::unique_ptr<ItemDecoder>
makeLayeredItemDecoder (const LazItem& item);

/** \brief The decoder of POINT14 v3 (\a v4 false) or v4 (true). */
std::unique_ptr<ItemDecoder>
makePoint14Decoder (bool v4);

/** \brief The level of return \a r of \a n returns, |n - r| capped at 7: a context of
 * the coordinate differences. LASzip tabulates it twice, as number_return_level
 * (POINT10, 3-bit r and n, where the cap never applies) and number_return_level_8ctx
 * (POINT14, 4-bit r and n); both tables are this function. */
inline unsigned
numberReturnLevel (unsigned n, unsigned r)
{
  const unsigned level = n > r ? n - r : r - n;
  return level < 7u ? level : 7u;
}

inline std::uint16_t
loadU16 (const std::uint8_t* p)
{
  return static_cast<std::uint16_t> (p[0] | (p[1] << 8));
}

inline std::uint32_t
loadU32 (const std::uint8_t* p)
{
  return std::uint32_t (p[0]) | (std::uint32_t (p[1]) << 8) |
         (std::uint32_t (p[2]) << 16) | (std::uint32_t (p[3]) << 24);
}

inline std::uint64_t
loadU64 (const std::uint8_t* p)
{
  return std::uint64_t (loadU32 (p)) | (std::uint64_t (loadU32 (p + 4)) << 32);
}

inline void
storeU16 (std::uint8_t* p, std::uint32_t v)
{
  p[0] = static_cast<std::uint8_t> (v);
  p[1] = static_cast<std::uint8_t> (v >> 8);
}

inline void
storeU32 (std::uint8_t* p, std::uint32_t v)
{
  p[0] = static_cast<std::uint8_t> (v);
  p[1] = static_cast<std::uint8_t> (v >> 8);
  p[2] = static_cast<std::uint8_t> (v >> 16);
  p[3] = static_cast<std::uint8_t> (v >> 24);
}

inline void
storeU64 (std::uint8_t* p, std::uint64_t v)
{
  storeU32 (p, static_cast<std::uint32_t> (v));
  storeU32 (p + 4, static_cast<std::uint32_t> (v >> 32));
}

/** \brief Adds without signed overflow: the coordinates wrap around as LASzip's do. */
inline std::int32_t
wrapAdd (std::int32_t a, std::int32_t b)
{
  return static_cast<std::int32_t> (static_cast<std::uint32_t> (a) +
                                    static_cast<std::uint32_t> (b));
}

/** \brief Multiplies without signed overflow (wrapping, as LASzip's 32-bit products).
 */
inline std::int32_t
wrapMul (std::int32_t a, std::int32_t b)
{
  return static_cast<std::int32_t> (static_cast<std::uint32_t> (a) *
                                    static_cast<std::uint32_t> (b));
}

/** \brief LASzip's U8_CLAMP: to [0, 255]. */
inline std::int32_t
clampU8 (std::int32_t v)
{
  return v <= 0 ? 0 : (v >= 255 ? 255 : v);
}

/** \brief The median of the last five values, updated in place (LASzip's
 * StreamingMedian5): predicts the next x and y difference. */
class StreamingMedian5 {
public:
  void
  reset ()
  {
    for (auto& v : values_)
      v = 0;
    high_ = true;
  }

  void
  add (std::int32_t v)
  {
    std::int32_t* x = values_;
    if (high_) {
      if (v < x[2]) {
        x[4] = x[3];
        x[3] = x[2];
        if (v < x[0]) {
          x[2] = x[1];
          x[1] = x[0];
          x[0] = v;
        }
        else if (v < x[1]) {
          x[2] = x[1];
          x[1] = v;
        }
        else
          x[2] = v;
      }
      else {
        if (v < x[3]) {
          x[4] = x[3];
          x[3] = v;
        }
        else
          x[4] = v;
        high_ = false;
      }
    }
    else {
      if (x[2] < v) {
        x[0] = x[1];
        x[1] = x[2];
        if (x[4] < v) {
          x[2] = x[3];
          x[3] = x[4];
          x[4] = v;
        }
        else if (x[3] < v) {
          x[2] = x[3];
          x[3] = v;
        }
        else
          x[2] = v;
      }
      else {
        if (x[1] < v) {
          x[0] = x[1];
          x[1] = v;
        }
        else
          x[0] = v;
        high_ = true;
      }
    }
  }

  std::int32_t
  get () const
  {
    return values_[2];
  }

private:
  std::int32_t values_[5] = {0, 0, 0, 0, 0};
  bool high_ = true;
};

/** \brief Decodes the 32-bit differences of GPS times (GPSTIME11 v2 and the gps_time
 * layer of POINT14 v3): up to four interleaved time sequences, each with its last
 * difference as prediction. The two versions number their codes differently (\a
 * layered). */
class GpsTimeDecoder {
public:
  explicit GpsTimeDecoder (bool layered);

  /** \brief Start from the time with bit pattern \a first. */
  void
  reset (std::uint64_t first);

  /** \brief Decode the next time; returns its bit pattern. */
  std::uint64_t
  decode (LazArithmeticDecoder& dec);

  /** \brief The bit pattern of the current time. */
  std::uint64_t
  current () const
  {
    return last_gpstime_[last_];
  }

private:
  void
  readDifference (LazArithmeticDecoder& dec, std::uint32_t multi);
  void
  readFull (LazArithmeticDecoder& dec);

  bool layered_;
  LazSymbolModel m_multi_;
  LazSymbolModel m_0diff_;
  LazIntegerDecompressor ic_gpstime_;
  unsigned last_ = 0, next_ = 0;
  std::uint64_t last_gpstime_[4] = {0, 0, 0, 0};
  std::int32_t last_gpstime_diff_[4] = {0, 0, 0, 0};
  std::int32_t multi_extreme_counter_[4] = {0, 0, 0, 0};
};

/** \brief Decodes the colour of RGB12 v2 and RGB14 v3: which bytes changed, then each
 * changed byte as a correction of a prediction from the bytes already decoded. */
class RgbDecoder {
public:
  RgbDecoder();

  void
  reset ();

  /** \brief Decode the colour following \a last (three 16-bit channels) into \a rgb. */
  void
  decode (LazArithmeticDecoder& dec, const std::uint16_t* last, std::uint16_t* rgb);

private:
  LazSymbolModel m_byte_used_;
  LazSymbolModel m_rgb_diff_[6];
};
} // namespace laz_detail
} // namespace io
} // namespace pcl_ext
