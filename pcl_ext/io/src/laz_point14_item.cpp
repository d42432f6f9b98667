/*
 * pcl_ext: the layered LAZ item POINT14 (versions 3 and 4) of point formats 6-10.
 */
#include "laz_item_decoder.h"

#include <array>

namespace pcl_ext {
namespace io {
namespace laz_detail {
namespace {
// Context of the return number r and the number of returns n (4 bits each) of POINT14:
// (n, r) pairs mapped to 6 contexts (LASzip's number_return_map_6ctx). The other
// context, the level, is numberReturnLevel.
const std::uint8_t number_return_map_6ctx[16][16] = {
    {0, 1, 2, 3, 4, 5, 3, 4, 4, 5, 5, 5, 5, 5, 5, 5},
    {1, 0, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
    {2, 1, 2, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3},
    {3, 3, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {3, 3, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5}};

/** The fields of a point format 6 record (ASPRS LAS 1.4 R15, table 13). */
struct Point14 {
  std::int32_t x = 0, y = 0, z = 0;
  std::uint16_t intensity = 0;
  std::uint8_t return_number = 0, number_of_returns = 0;
  std::uint8_t classification_flags = 0, scanner_channel = 0;
  std::uint8_t scan_direction = 0, edge_of_flight_line = 0;
  std::uint8_t classification = 0, user_data = 0;
  std::int16_t scan_angle = 0;
  std::uint16_t point_source_id = 0;
  std::uint64_t gps_time = 0;
  bool gps_time_change = false; // of this point, a context of the next

  void
  load (const std::uint8_t* p)
  {
    x = static_cast<std::int32_t> (loadU32 (p));
    y = static_cast<std::int32_t> (loadU32 (p + 4));
    z = static_cast<std::int32_t> (loadU32 (p + 8));
    intensity = loadU16 (p + 12);
    return_number = p[14] & 0x0F;
    number_of_returns = p[14] >> 4;
    classification_flags = p[15] & 0x0F;
    scanner_channel = (p[15] >> 4) & 3;
    scan_direction = (p[15] >> 6) & 1;
    edge_of_flight_line = p[15] >> 7;
    classification = p[16];
    user_data = p[17];
    scan_angle = static_cast<std::int16_t> (loadU16 (p + 18));
    point_source_id = loadU16 (p + 20);
    gps_time = loadU64 (p + 22);
  }

  void
  store (std::uint8_t* p) const
  {
    storeU32 (p, static_cast<std::uint32_t> (x));
    storeU32 (p + 4, static_cast<std::uint32_t> (y));
    storeU32 (p + 8, static_cast<std::uint32_t> (z));
    storeU16 (p + 12, intensity);
    p[14] = static_cast<std::uint8_t> (return_number | (number_of_returns << 4));
    p[15] =
        static_cast<std::uint8_t> (classification_flags | (scanner_channel << 4) |
                                   (scan_direction << 6) | (edge_of_flight_line << 7));
    p[16] = classification;
    p[17] = user_data;
    storeU16 (p + 18, static_cast<std::uint16_t> (scan_angle));
    storeU16 (p + 20, point_source_id);
    storeU64 (p + 22, gps_time);
  }
};

/** Symbol models of one size made on first use, \a N of them. */
template <std::size_t N>
class LazyModelArray {
public:
  explicit LazyModelArray (std::uint32_t symbols) : symbols_ (symbols) {}

  LazSymbolModel&
  get (std::size_t key)
  {
    auto& m = models_[key];
    if (!m)
      m = std::make_unique<LazSymbolModel> (symbols_);
    return *m;
  }

  void
  reset ()
  {
    for (auto& m : models_)
      m.reset();
  }

private:
  std::uint32_t symbols_;
  std::array<std::unique_ptr<LazSymbolModel>, N> models_;
};

/** The state and models of one scanner channel. */
struct Point14Context {
  bool unused = true;
  Point14 last;
  std::uint16_t last_intensity[8];
  StreamingMedian5 last_x_diff_median5[12];
  StreamingMedian5 last_y_diff_median5[12];
  std::int32_t last_z[8];
  // channel_returns_XY layer
  std::vector<LazSymbolModel> m_changed_values;
  LazSymbolModel m_scanner_channel{3};
  LazyModelArray<16> m_number_of_returns{16};
  LazyModelArray<16> m_return_number{16};
  LazSymbolModel m_return_number_gps_same{13};
  LazIntegerDecompressor ic_dx{32, 2}, ic_dy{32, 22};
  // the other layers
  LazIntegerDecompressor ic_z{32, 20};
  LazyModelArray<64> m_classification{256};
  LazyModelArray<64> m_flags{64};
  LazyModelArray<64> m_user_data{256};
  LazIntegerDecompressor ic_intensity{16, 4};
  LazIntegerDecompressor ic_scan_angle{16, 2};
  LazIntegerDecompressor ic_point_source_id{16};
  GpsTimeDecoder gps{true};

  Point14Context()
  {
    for (int i = 0; i < 8; ++i)
      m_changed_values.emplace_back (128);
  }

  void
  reset (const Point14& first)
  {
    for (auto& m : m_changed_values)
      m.reset();
    m_scanner_channel.reset();
    m_number_of_returns.reset();
    m_return_number.reset();
    m_return_number_gps_same.reset();
    ic_dx.reset();
    ic_dy.reset();
    for (int i = 0; i < 12; ++i) {
      last_x_diff_median5[i].reset();
      last_y_diff_median5[i].reset();
    }
    ic_z.reset();
    m_classification.reset();
    m_flags.reset();
    m_user_data.reset();
    ic_intensity.reset();
    ic_scan_angle.reset();
    ic_point_source_id.reset();
    gps.reset (first.gps_time);
    for (int i = 0; i < 8; ++i) {
      last_z[i] = first.z;
      last_intensity[i] = first.intensity;
    }
    last = first;
    last.gps_time_change = false;
    unused = false;
  }
};

/** POINT14 v3 / v4 (LASzip compressed format, "POINT14 v3"): nine layers, each with its
 * own decoder: channel, returns and x, y (always), then z, classification, flags,
 * intensity, scan angle, user data, point source id and GPS time, each absent when it
 * does not change in the chunk. */
class Point14Layered : public ItemDecoder {
public:
  explicit Point14Layered (bool v4) : v4_ (v4) {}

  std::size_t
  layerCount () const override
  {
    return layer_count;
  }

  void
  startChunk (const std::uint8_t* item, const Layer* layers, unsigned& context) override
  {
    startLayers (layers, layer_count, dec_, changed_, contexts_);
    Point14 first;
    first.load (item);
    current_ = first.scanner_channel;
    initContext (current_, first);
    context = current_;
  }

  void
  decode (std::uint8_t* item, unsigned& context) override
  {
    if (!changed_[xy])
      throw LazDataError ("the POINT14 layer of returns and x, y is empty");
    LazArithmeticDecoder& dec = dec_[xy];
    Point14Context* ctx = contexts_[current_].get();
    {
      const Point14& last = ctx->last;
      const unsigned lpr = (last.return_number == 1 ? 1 : 0) +
                           (last.return_number >= last.number_of_returns ? 2 : 0) +
                           (last.gps_time_change ? 4 : 0);
      const std::uint32_t changed = dec.decodeSymbol (ctx->m_changed_values[lpr]);
      changed_values_ = changed;
    }
    const std::uint32_t changed = changed_values_;
    bool switched = false;
    if (changed & (1 << 6)) { // another scanner channel
      const std::uint32_t diff = dec.decodeSymbol (ctx->m_scanner_channel);
      const unsigned channel = (current_ + diff + 1) % 4;
      if (!contexts_[channel] || contexts_[channel]->unused)
        initContext (channel, ctx->last);
      current_ = channel;
      ctx = contexts_[current_].get();
      ctx->last.scanner_channel = static_cast<std::uint8_t> (channel);
      switched = true;
    }
    // v3 hands the channel to the other items only when it changes (0 otherwise), v4
    // always: the encoder does the same.
    context = (v4_ || switched) ? current_ : 0;

    Point14& p = ctx->last;
    const bool point_source_change = changed & (1 << 5);
    const bool gps_time_change = changed & (1 << 4);
    const bool scan_angle_change = changed & (1 << 3);
    const unsigned last_n = p.number_of_returns;
    const unsigned last_r = p.return_number;
    unsigned n = last_n;
    if (changed & (1 << 2)) {
      n = dec.decodeSymbol (ctx->m_number_of_returns.get (last_n));
      p.number_of_returns = static_cast<std::uint8_t> (n);
    }
    unsigned r = last_r;
    switch (changed & 3) {
    case 1:
      r = (last_r + 1) % 16;
      break;
    case 2:
      r = (last_r + 15) % 16;
      break;
    case 3:
      if (gps_time_change)
        r = dec.decodeSymbol (ctx->m_return_number.get (last_r));
      else
        r = (last_r + dec.decodeSymbol (ctx->m_return_number_gps_same) + 2) % 16;
      break;
    default:
      break;
    }
    p.return_number = static_cast<std::uint8_t> (r);

    const unsigned m = number_return_map_6ctx[n][r];
    const unsigned l = numberReturnLevel (n, r);
    const unsigned cpr = (r == 1 ? 2 : 0) + (r >= n ? 1 : 0);
    const unsigned median = (m << 1) | (gps_time_change ? 1 : 0);

    const std::int32_t dx =
        ctx->ic_dx.decompress (dec, ctx->last_x_diff_median5[median].get(), n == 1);
    p.x = wrapAdd (p.x, dx);
    ctx->last_x_diff_median5[median].add (dx);
    std::uint32_t k_bits = ctx->ic_dx.k();
    const std::int32_t dy =
        ctx->ic_dy.decompress (dec,
                               ctx->last_y_diff_median5[median].get(),
                               (n == 1) + (k_bits < 20 ? (k_bits & ~1u) : 20));
    p.y = wrapAdd (p.y, dy);
    ctx->last_y_diff_median5[median].add (dy);

    if (changed_[z_layer]) {
      k_bits = (ctx->ic_dx.k() + ctx->ic_dy.k()) / 2;
      p.z = ctx->ic_z.decompress (dec_[z_layer],
                                  ctx->last_z[l],
                                  (n == 1) + (k_bits < 18 ? (k_bits & ~1u) : 18));
      ctx->last_z[l] = p.z;
    }
    if (changed_[classification_layer]) {
      const unsigned ccc = ((p.classification & 0x1F) << 1) + (cpr == 3 ? 1 : 0);
      p.classification = static_cast<std::uint8_t> (
          dec_[classification_layer].decodeSymbol (ctx->m_classification.get (ccc)));
    }
    if (changed_[flags_layer]) {
      const unsigned last_flags = (p.edge_of_flight_line << 5) |
                                  (p.scan_direction << 4) | p.classification_flags;
      const std::uint32_t flags =
          dec_[flags_layer].decodeSymbol (ctx->m_flags.get (last_flags));
      p.edge_of_flight_line = (flags >> 5) & 1;
      p.scan_direction = (flags >> 4) & 1;
      p.classification_flags = flags & 0x0F;
    }
    if (changed_[intensity_layer]) {
      std::uint16_t& last_intensity =
          ctx->last_intensity[(cpr << 1) | (gps_time_change ? 1 : 0)];
      last_intensity = static_cast<std::uint16_t> (
          ctx->ic_intensity.decompress (dec_[intensity_layer], last_intensity, cpr));
      p.intensity = last_intensity;
    }
    if (changed_[scan_angle_layer] && scan_angle_change)
      p.scan_angle = static_cast<std::int16_t> (ctx->ic_scan_angle.decompress (
          dec_[scan_angle_layer], p.scan_angle, gps_time_change ? 1 : 0));
    if (changed_[user_data_layer])
      p.user_data = static_cast<std::uint8_t> (
          dec_[user_data_layer].decodeSymbol (ctx->m_user_data.get (p.user_data / 4)));
    if (changed_[point_source_layer] && point_source_change)
      p.point_source_id =
          static_cast<std::uint16_t> (ctx->ic_point_source_id.decompress (
              dec_[point_source_layer], p.point_source_id));
    if (changed_[gps_time_layer] && gps_time_change)
      p.gps_time = ctx->gps.decode (dec_[gps_time_layer]);
    p.store (item);
    p.gps_time_change = gps_time_change;
  }

private:
  enum : std::size_t {
    xy = 0,
    z_layer,
    classification_layer,
    flags_layer,
    intensity_layer,
    scan_angle_layer,
    user_data_layer,
    point_source_layer,
    gps_time_layer,
    layer_count
  };

  void
  initContext (unsigned channel, Point14 first)
  {
    if (!contexts_[channel])
      contexts_[channel] = std::make_unique<Point14Context>();
    contexts_[channel]->reset (first);
  }

  bool v4_;
  LazArithmeticDecoder dec_[layer_count];
  bool changed_[layer_count] = {};
  std::unique_ptr<Point14Context> contexts_[4];
  unsigned current_ = 0;
  std::uint32_t changed_values_ = 0;
};
} // namespace

std::unique_ptr<ItemDecoder>
makePoint14Decoder (bool v4)
{
  return std::make_unique<Point14Layered> (v4);
}
} // namespace laz_detail
} // namespace io
} // namespace pcl_ext
