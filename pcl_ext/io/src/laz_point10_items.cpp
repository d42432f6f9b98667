/*
 * pcl_ext: the pointwise LAZ items of point formats 0-5 (POINT10, GPSTIME11, RGB12 and
 * BYTE, version 2).
 */
#include "laz_item_decoder.h"

#include <cstring>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace laz_detail {
namespace {
// Context of the return number r and the number of returns n (3 bits each) of POINT10:
// a map of the (n, r) pairs to 16 contexts (LASzip's number_return_map, completed for
// inconsistent pairs). The other context, the level, is numberReturnLevel.
const std::uint8_t number_return_map[8][8] = {{15, 14, 13, 12, 11, 10, 9, 8},
                                              {14, 0, 1, 3, 6, 10, 10, 9},
                                              {13, 1, 2, 4, 7, 11, 11, 10},
                                              {12, 3, 4, 5, 8, 12, 12, 11},
                                              {11, 6, 7, 8, 9, 13, 13, 12},
                                              {10, 10, 11, 12, 13, 14, 14, 13},
                                              {9, 10, 11, 12, 13, 14, 15, 14},
                                              {8, 9, 10, 11, 12, 13, 14, 15}};

/** A symbol model of 256 symbols per value of a previous byte, made on first use. */
class LazyModels {
public:
  LazSymbolModel&
  get (std::uint8_t key)
  {
    auto& m = models_[key];
    if (!m)
      m = std::make_unique<LazSymbolModel> (256);
    return *m;
  }

  void
  reset ()
  {
    for (auto& m : models_)
      m.reset();
  }

private:
  std::unique_ptr<LazSymbolModel> models_[256];
};

/** POINT10 v2: x, y, z, intensity, return bits, classification, scan angle rank, user
 * data, point source id (LASzip compressed format, "POINT10 v2"). */
class Point10V2 : public ItemDecoder {
public:
  explicit Point10V2 (LazArithmeticDecoder& dec)
  : dec_ (dec)
  , m_changed_values_ (64)
  , ic_intensity_ (16, 4)
  , m_scan_angle_rank_{LazSymbolModel (256), LazSymbolModel (256)}
  , ic_point_source_id_ (16)
  , ic_dx_ (32, 2)
  , ic_dy_ (32, 22)
  , ic_z_ (32, 20)
  {}

  std::size_t
  layerCount () const override
  {
    return 0;
  }

  void
  startChunk (const std::uint8_t* item, const Layer*, unsigned&) override
  {
    for (int i = 0; i < 16; ++i) {
      last_x_diff_median5_[i].reset();
      last_y_diff_median5_[i].reset();
      last_intensity_[i] = 0;
      last_height_[i / 2] = 0;
    }
    m_changed_values_.reset();
    ic_intensity_.reset();
    m_scan_angle_rank_[0].reset();
    m_scan_angle_rank_[1].reset();
    ic_point_source_id_.reset();
    m_bit_byte_.reset();
    m_classification_.reset();
    m_user_data_.reset();
    ic_dx_.reset();
    ic_dy_.reset();
    ic_z_.reset();
    std::memcpy (last_, item, 20);
    last_[12] = last_[13] = 0; // LASzip starts from intensity 0
  }

  void
  decode (std::uint8_t* item, unsigned&) override
  {
    const std::uint32_t changed = dec_.decodeSymbol (m_changed_values_);
    std::uint32_t m, l, n;
    if (changed) {
      if (changed & 32)
        last_[14] =
            static_cast<std::uint8_t> (dec_.decodeSymbol (m_bit_byte_.get (last_[14])));
      const std::uint32_t r = last_[14] & 7;
      n = (last_[14] >> 3) & 7;
      m = number_return_map[n][r];
      l = numberReturnLevel (n, r);
      if (changed & 16) {
        const std::int32_t intensity =
            ic_intensity_.decompress (dec_, last_intensity_[m], m < 3 ? m : 3);
        last_intensity_[m] = static_cast<std::uint16_t> (intensity);
      }
      storeU16 (last_ + 12, last_intensity_[m]);
      if (changed & 8)
        last_[15] = static_cast<std::uint8_t> (
            dec_.decodeSymbol (m_classification_.get (last_[15])));
      if (changed & 4) {
        const std::uint32_t v =
            dec_.decodeSymbol (m_scan_angle_rank_[(last_[14] >> 6) & 1]);
        last_[16] = static_cast<std::uint8_t> (v + last_[16]);
      }
      if (changed & 2)
        last_[17] = static_cast<std::uint8_t> (
            dec_.decodeSymbol (m_user_data_.get (last_[17])));
      if (changed & 1)
        storeU16 (last_ + 18,
                  static_cast<std::uint32_t> (
                      ic_point_source_id_.decompress (dec_, loadU16 (last_ + 18))));
    }
    else {
      const std::uint32_t r = last_[14] & 7;
      n = (last_[14] >> 3) & 7;
      m = number_return_map[n][r];
      l = numberReturnLevel (n, r);
    }

    const std::int32_t dx =
        ic_dx_.decompress (dec_, last_x_diff_median5_[m].get(), n == 1);
    storeU32 (last_,
              static_cast<std::uint32_t> (
                  wrapAdd (static_cast<std::int32_t> (loadU32 (last_)), dx)));
    last_x_diff_median5_[m].add (dx);

    std::uint32_t k_bits = ic_dx_.k();
    const std::int32_t dy =
        ic_dy_.decompress (dec_,
                           last_y_diff_median5_[m].get(),
                           (n == 1) + (k_bits < 20 ? (k_bits & ~1u) : 20));
    storeU32 (last_ + 4,
              static_cast<std::uint32_t> (
                  wrapAdd (static_cast<std::int32_t> (loadU32 (last_ + 4)), dy)));
    last_y_diff_median5_[m].add (dy);

    k_bits = (ic_dx_.k() + ic_dy_.k()) / 2;
    const std::int32_t z = ic_z_.decompress (
        dec_, last_height_[l], (n == 1) + (k_bits < 18 ? (k_bits & ~1u) : 18));
    storeU32 (last_ + 8, static_cast<std::uint32_t> (z));
    last_height_[l] = z;
    std::memcpy (item, last_, 20);
  }

private:
  LazArithmeticDecoder& dec_;
  std::uint8_t last_[20];
  std::uint16_t last_intensity_[16];
  std::int32_t last_height_[8];
  StreamingMedian5 last_x_diff_median5_[16];
  StreamingMedian5 last_y_diff_median5_[16];
  LazSymbolModel m_changed_values_;
  LazIntegerDecompressor ic_intensity_;
  LazSymbolModel m_scan_angle_rank_[2];
  LazIntegerDecompressor ic_point_source_id_;
  LazyModels m_bit_byte_, m_classification_, m_user_data_;
  LazIntegerDecompressor ic_dx_, ic_dy_, ic_z_;
};

/** GPSTIME11 v2: the 8-byte GPS time. */
class GpsTime11V2 : public ItemDecoder {
public:
  explicit GpsTime11V2 (LazArithmeticDecoder& dec) : dec_ (dec), gps_ (false) {}

  std::size_t
  layerCount () const override
  {
    return 0;
  }

  void
  startChunk (const std::uint8_t* item, const Layer*, unsigned&) override
  {
    gps_.reset (loadU64 (item));
  }

  void
  decode (std::uint8_t* item, unsigned&) override
  {
    storeU64 (item, gps_.decode (dec_));
  }

private:
  LazArithmeticDecoder& dec_;
  GpsTimeDecoder gps_;
};

/** RGB12 v2: red, green, blue, 16 bits each. */
class Rgb12V2 : public ItemDecoder {
public:
  explicit Rgb12V2 (LazArithmeticDecoder& dec) : dec_ (dec) {}

  std::size_t
  layerCount () const override
  {
    return 0;
  }

  void
  startChunk (const std::uint8_t* item, const Layer*, unsigned&) override
  {
    rgb_.reset();
    for (int i = 0; i < 3; ++i)
      last_[i] = loadU16 (item + 2 * i);
  }

  void
  decode (std::uint8_t* item, unsigned&) override
  {
    std::uint16_t rgb[3];
    rgb_.decode (dec_, last_, rgb);
    for (int i = 0; i < 3; ++i) {
      last_[i] = rgb[i];
      storeU16 (item + 2 * i, rgb[i]);
    }
  }

private:
  LazArithmeticDecoder& dec_;
  RgbDecoder rgb_;
  std::uint16_t last_[3];
};

/** BYTE v2: extra bytes, each a wrapping difference to the byte before. */
class ByteV2 : public ItemDecoder {
public:
  ByteV2 (LazArithmeticDecoder& dec, std::size_t count) : dec_ (dec), last_ (count)
  {
    models_.reserve (count);
    for (std::size_t i = 0; i < count; ++i)
      models_.emplace_back (256);
  }

  std::size_t
  layerCount () const override
  {
    return 0;
  }

  void
  startChunk (const std::uint8_t* item, const Layer*, unsigned&) override
  {
    for (auto& m : models_)
      m.reset();
    std::memcpy (last_.data(), item, last_.size());
  }

  void
  decode (std::uint8_t* item, unsigned&) override
  {
    for (std::size_t i = 0; i < last_.size(); ++i) {
      last_[i] = static_cast<std::uint8_t> (last_[i] + dec_.decodeSymbol (models_[i]));
      item[i] = last_[i];
    }
  }

private:
  LazArithmeticDecoder& dec_;
  std::vector<std::uint8_t> last_;
  std::vector<LazSymbolModel> models_;
};
} // namespace

std::unique_ptr<ItemDecoder>
makePointwiseItemDecoder (const LazItem& item, LazArithmeticDecoder& dec)
{
  switch (static_cast<LazItemType> (item.type)) {
  case LazItemType::Point10:
    return std::make_unique<Point10V2> (dec);
  case LazItemType::GpsTime11:
    return std::make_unique<GpsTime11V2> (dec);
  case LazItemType::Rgb12:
    return std::make_unique<Rgb12V2> (dec);
  case LazItemType::Byte:
    return std::make_unique<ByteV2> (dec, item.size);
  default:
    throw LazDataError ("no pointwise decoder for item type " +
                        std::to_string (item.type));
  }
}
} // namespace laz_detail
} // namespace io
} // namespace pcl_ext
