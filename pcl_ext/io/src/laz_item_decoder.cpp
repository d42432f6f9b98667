/*
 * pcl_ext: the pieces the LAZ item decoders share: the streaming median, the GPS time
 * decoder and the colour decoder.
 */
#include "laz_item_decoder.h"

namespace pcl_ext {
namespace io {
namespace laz_detail {
namespace {
// The GPS time codes (LASzip compressed format, GPSTIME11 v2 and POINT14 v3): a symbol
// below `multi_max` multiplies the last difference; above it, the codes of "unchanged"
// (v2 only), "full 64-bit time" and "switch to another of the four sequences".
constexpr std::int32_t multi_max = 500;
constexpr std::int32_t multi_minus = -10;
} // namespace

GpsTimeDecoder::GpsTimeDecoder (bool layered)
: layered_ (layered)
, m_multi_ (layered ? multi_max - multi_minus + 5 : multi_max - multi_minus + 6)
, m_0diff_ (layered ? 5 : 6)
, ic_gpstime_ (32, 9)
{}

void
GpsTimeDecoder::reset (std::uint64_t first)
{
  m_multi_.reset();
  m_0diff_.reset();
  ic_gpstime_.reset();
  last_ = next_ = 0;
  for (int i = 0; i < 4; ++i) {
    last_gpstime_[i] = 0;
    last_gpstime_diff_[i] = 0;
    multi_extreme_counter_[i] = 0;
  }
  last_gpstime_[0] = first;
}

void
GpsTimeDecoder::readFull (LazArithmeticDecoder& dec)
{
  next_ = (next_ + 1) & 3;
  const std::int32_t high = ic_gpstime_.decompress (
      dec, static_cast<std::int32_t> (last_gpstime_[last_] >> 32), 8);
  last_gpstime_[next_] =
      (std::uint64_t (static_cast<std::uint32_t> (high)) << 32) | dec.readInt();
  last_ = next_;
  last_gpstime_diff_[last_] = 0;
  multi_extreme_counter_[last_] = 0;
}

void
GpsTimeDecoder::readDifference (LazArithmeticDecoder& dec, std::uint32_t multi)
{
  // multi is 0 or in [2, multi_max - multi_minus]: a multiple of the last difference.
  std::int32_t& last_diff = last_gpstime_diff_[last_];
  std::int32_t& extreme = multi_extreme_counter_[last_];
  std::int32_t diff;
  const auto promote = [&] () {
    if (++extreme > 3) {
      last_diff = diff;
      extreme = 0;
    }
  };
  if (multi == 0) {
    diff = ic_gpstime_.decompress (dec, 0, 7);
    promote();
  }
  else if (multi < static_cast<std::uint32_t> (multi_max)) {
    const std::int32_t m = static_cast<std::int32_t> (multi);
    diff = ic_gpstime_.decompress (dec, wrapMul (m, last_diff), m < 10 ? 2 : 3);
  }
  else if (multi == static_cast<std::uint32_t> (multi_max)) {
    diff = ic_gpstime_.decompress (dec, wrapMul (multi_max, last_diff), 4);
    promote();
  }
  else {
    const std::int32_t m = multi_max - static_cast<std::int32_t> (multi);
    if (m > multi_minus)
      diff = ic_gpstime_.decompress (dec, wrapMul (m, last_diff), 5);
    else {
      diff = ic_gpstime_.decompress (dec, wrapMul (multi_minus, last_diff), 6);
      promote();
    }
  }
  last_gpstime_[last_] += static_cast<std::uint64_t> (static_cast<std::int64_t> (diff));
}

std::uint64_t
GpsTimeDecoder::decode (LazArithmeticDecoder& dec)
{
  // v2 and v3 differ in the numbering of the codes only: v2 has an "unchanged" code in
  // both models, v3 none (the POINT14 layer says whether the time changed).
  const std::uint32_t skip = layered_ ? 0 : 1;
  const std::uint32_t code_full =
      static_cast<std::uint32_t> (multi_max - multi_minus) + 1 + skip;
  for (;;) { // each round decodes a symbol, so a corrupt stream soon ends
    if (last_gpstime_diff_[last_] == 0) {
      const std::uint32_t multi = dec.decodeSymbol (m_0diff_);
      if (multi < skip) // v2: unchanged
        break;
      if (multi == skip) { // a difference that fits 32 bits
        const std::int32_t diff = ic_gpstime_.decompress (dec, 0, 0);
        last_gpstime_diff_[last_] = diff;
        last_gpstime_[last_] +=
            static_cast<std::uint64_t> (static_cast<std::int64_t> (diff));
        multi_extreme_counter_[last_] = 0;
        break;
      }
      if (multi == skip + 1) {
        readFull (dec);
        break;
      }
      last_ = (last_ + multi - skip - 1) & 3;
      continue;
    }
    const std::uint32_t multi = dec.decodeSymbol (m_multi_);
    if (multi == 1) {
      last_gpstime_[last_] += static_cast<std::uint64_t> (static_cast<std::int64_t> (
          ic_gpstime_.decompress (dec, last_gpstime_diff_[last_], 1)));
      multi_extreme_counter_[last_] = 0;
      break;
    }
    if (multi < code_full - skip) {
      readDifference (dec, multi);
      break;
    }
    if (multi < code_full) // v2: unchanged
      break;
    if (multi == code_full) {
      readFull (dec);
      break;
    }
    last_ = (last_ + multi - code_full) & 3;
  }
  return last_gpstime_[last_];
}

RgbDecoder::RgbDecoder()
: m_byte_used_ (128)
, m_rgb_diff_{LazSymbolModel (256),
              LazSymbolModel (256),
              LazSymbolModel (256),
              LazSymbolModel (256),
              LazSymbolModel (256),
              LazSymbolModel (256)}
{}

void
RgbDecoder::reset()
{
  m_byte_used_.reset();
  for (auto& m : m_rgb_diff_)
    m.reset();
}

void
RgbDecoder::decode (LazArithmeticDecoder& dec,
                    const std::uint16_t* last,
                    std::uint16_t* rgb)
{
  // Bits 0-5 of sym: which of the low and high bytes of red, green, blue changed; bit
  // 6: whether green and blue differ from red. Green and blue are predicted from red's
  // change, clamped to a byte; the correction wraps around.
  const std::uint32_t sym = dec.decodeSymbol (m_byte_used_);
  const auto fold = [] (std::int32_t v) {
    return static_cast<std::uint32_t> (v) & 0xFF;
  };
  const auto corr = [&] (int i) {
    return static_cast<std::int32_t> (dec.decodeSymbol (m_rgb_diff_[i]));
  };
  std::uint32_t r_lo = last[0] & 0xFF, r_hi = last[0] >> 8;
  if (sym & 1)
    r_lo = fold (corr (0) + static_cast<std::int32_t> (last[0] & 0xFF));
  if (sym & 2)
    r_hi = fold (corr (1) + static_cast<std::int32_t> (last[0] >> 8));
  rgb[0] = static_cast<std::uint16_t> (r_lo | (r_hi << 8));
  if (!(sym & (1 << 6))) {
    rgb[1] = rgb[2] = rgb[0];
    return;
  }
  std::int32_t diff = static_cast<std::int32_t> (r_lo) - (last[0] & 0xFF);
  std::uint32_t g_lo = last[1] & 0xFF, b_lo = last[2] & 0xFF;
  if (sym & (1 << 2))
    g_lo = fold (corr (2) + clampU8 (diff + (last[1] & 0xFF)));
  if (sym & (1 << 4)) {
    diff = (diff + (static_cast<std::int32_t> (g_lo) - (last[1] & 0xFF))) / 2;
    b_lo = fold (corr (4) + clampU8 (diff + (last[2] & 0xFF)));
  }
  diff = static_cast<std::int32_t> (r_hi) - (last[0] >> 8);
  std::uint32_t g_hi = last[1] >> 8, b_hi = last[2] >> 8;
  if (sym & (1 << 3))
    g_hi = fold (corr (3) + clampU8 (diff + (last[1] >> 8)));
  if (sym & (1 << 5)) {
    diff = (diff + (static_cast<std::int32_t> (g_hi) - (last[1] >> 8))) / 2;
    b_hi = fold (corr (5) + clampU8 (diff + (last[2] >> 8)));
  }
  rgb[1] = static_cast<std::uint16_t> (g_lo | (g_hi << 8));
  rgb[2] = static_cast<std::uint16_t> (b_lo | (b_hi << 8));
}
} // namespace laz_detail
} // namespace io
} // namespace pcl_ext
