/*
 * pcl_ext: the layered LAZ items after POINT14 (RGB14, RGBNIR14 and BYTE14, versions 3
 * and 4) and the choice of a layered item decoder.
 */
#include "laz_item_decoder.h"

#include <cstring>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace laz_detail {
namespace {
/** The state and models of RGB14 / RGBNIR14 for one scanner channel. */
struct ColourContext {
  bool unused = true;
  std::uint16_t last[4] = {0, 0, 0, 0};
  RgbDecoder rgb;
  LazSymbolModel m_nir_bytes_used{4};
  LazSymbolModel m_nir_diff[2] = {LazSymbolModel (256), LazSymbolModel (256)};
};

/** RGB14 and RGBNIR14 v3 / v4 (LASzip compressed format, "RGB14 v3", "RGBNIR14 v3"):
 * the colour layer, coded as RGB12 v2, and for RGBNIR14 a layer of near infrared, its
 * low and high byte each a wrapping difference to the last. */
class ColourLayered : public ItemDecoder {
public:
  ColourLayered (bool nir, bool v4) : nir_ (nir), v4_ (v4) {}

  std::size_t
  layerCount () const override
  {
    return nir_ ? 2 : 1;
  }

  void
  startChunk (const std::uint8_t* item, const Layer* layers, unsigned& context) override
  {
    startLayers (layers, layerCount(), dec_, changed_, contexts_);
    std::uint16_t first[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < layerCount() + 2; ++i)
      first[i] = loadU16 (item + 2 * i);
    current_ = context & 3;
    initContext (current_, first);
  }

  void
  decode (std::uint8_t* item, unsigned& context) override
  {
    std::uint16_t* last = contexts_[current_]->last;
    if (current_ != context) {
      current_ = context & 3;
      if (!contexts_[current_] || contexts_[current_]->unused) {
        initContext (current_, last);
        last = contexts_[current_]->last;
      }
      else if (v4_)
        last = contexts_[current_]->last;
      // v3 goes on from the previous channel's colour, as its encoder does.
    }
    ColourContext& ctx = *contexts_[current_];
    std::uint16_t rgb[3];
    if (changed_[0]) {
      ctx.rgb.decode (dec_[0], last, rgb);
      std::memcpy (last, rgb, sizeof (rgb));
    }
    else
      std::memcpy (rgb, last, sizeof (rgb));
    for (int i = 0; i < 3; ++i)
      storeU16 (item + 2 * i, rgb[i]);
    if (!nir_)
      return;
    std::uint16_t nir = last[3];
    if (changed_[1]) {
      LazArithmeticDecoder& dec = dec_[1];
      const std::uint32_t sym = dec.decodeSymbol (ctx.m_nir_bytes_used);
      std::uint32_t lo = last[3] & 0xFF, hi = last[3] >> 8;
      if (sym & 1)
        lo = (dec.decodeSymbol (ctx.m_nir_diff[0]) + lo) & 0xFF;
      if (sym & 2)
        hi = (dec.decodeSymbol (ctx.m_nir_diff[1]) + hi) & 0xFF;
      nir = static_cast<std::uint16_t> (lo | (hi << 8));
      last[3] = nir;
    }
    storeU16 (item + 6, nir);
  }

private:
  void
  initContext (unsigned channel, const std::uint16_t* first)
  {
    std::uint16_t copy[4];
    std::memcpy (copy, first, sizeof (copy));
    auto& c = contexts_[channel];
    if (!c)
      c = std::make_unique<ColourContext>();
    c->rgb.reset();
    c->m_nir_bytes_used.reset();
    c->m_nir_diff[0].reset();
    c->m_nir_diff[1].reset();
    std::memcpy (c->last, copy, sizeof (copy));
    c->unused = false;
  }

  bool nir_, v4_;
  LazArithmeticDecoder dec_[2];
  bool changed_[2] = {false, false};
  std::unique_ptr<ColourContext> contexts_[4];
  unsigned current_ = 0;
};

/** The state and models of BYTE14 for one scanner channel. */
struct BytesContext {
  bool unused = true;
  std::vector<std::uint8_t> last;
  std::vector<LazSymbolModel> models;
};

/** BYTE14 v3 / v4 (LASzip compressed format, "BYTE14 v3"): one layer per extra byte,
 * each byte a wrapping difference to the last. */
class BytesLayered : public ItemDecoder {
public:
  BytesLayered (std::size_t count, bool v4)
  : count_ (count), v4_ (v4), dec_ (count), changed_ (count, false)
  {}

  std::size_t
  layerCount () const override
  {
    return count_;
  }

  void
  startChunk (const std::uint8_t* item, const Layer* layers, unsigned& context) override
  {
    startLayers (layers, count_, dec_, changed_, contexts_);
    current_ = context & 3;
    initContext (current_, item);
  }

  void
  decode (std::uint8_t* item, unsigned& context) override
  {
    std::uint8_t* last = contexts_[current_]->last.data();
    if (current_ != context) {
      current_ = context & 3;
      if (!contexts_[current_] || contexts_[current_]->unused) {
        initContext (current_, last);
        last = contexts_[current_]->last.data();
      }
      else if (v4_)
        last = contexts_[current_]->last.data();
    }
    BytesContext& ctx = *contexts_[current_];
    for (std::size_t i = 0; i < count_; ++i) {
      if (changed_[i])
        last[i] =
            static_cast<std::uint8_t> (last[i] + dec_[i].decodeSymbol (ctx.models[i]));
      item[i] = last[i];
    }
  }

private:
  void
  initContext (unsigned channel, const std::uint8_t* first)
  {
    std::vector<std::uint8_t> copy (first, first + count_);
    auto& c = contexts_[channel];
    if (!c) {
      c = std::make_unique<BytesContext>();
      c->models.reserve (count_);
      for (std::size_t i = 0; i < count_; ++i)
        c->models.emplace_back (256);
    }
    for (auto& m : c->models)
      m.reset();
    c->last = std::move (copy);
    c->unused = false;
  }

  std::size_t count_;
  bool v4_;
  std::vector<LazArithmeticDecoder> dec_;
  std::vector<bool> changed_;
  std::unique_ptr<BytesContext> contexts_[4];
  unsigned current_ = 0;
};
} // namespace

std::unique_ptr<ItemDecoder>
makeLayeredItemDecoder (const LazItem& item)
{
  const bool v4 = item.version == 4;
  switch (static_cast<LazItemType> (item.type)) {
  case LazItemType::Point14:
    return makePoint14Decoder (v4);
  case LazItemType::Rgb14:
    return std::make_unique<ColourLayered> (false, v4);
  case LazItemType::RgbNir14:
    return std::make_unique<ColourLayered> (true, v4);
  case LazItemType::Byte14:
    return std::make_unique<BytesLayered> (item.size, v4);
  default:
    throw LazDataError ("no layered decoder for item type " +
                        std::to_string (item.type));
  }
}
} // namespace laz_detail
} // namespace io
} // namespace pcl_ext
