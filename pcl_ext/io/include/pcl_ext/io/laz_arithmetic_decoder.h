/*
 * pcl_ext: the entropy decoder of LAZ (LASzip) point data.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief LAZ data that cannot be decoded: a stream that ends too early, a value out of
 * its range, an inconsistent table. The file-level reader (makeLazRecordSource) turns
 * it into a ReadError naming the file. */
class LazDataError : public std::runtime_error {
public:
  explicit LazDataError (const std::string& message) : std::runtime_error (message) {}
};

/** \brief Adaptive probability of one binary decision (LASzip's ArithmeticBitModel;
 * Said, "Introduction to arithmetic coding", 2003, section 3.3 "adaptive binary
 * models").
 *
 * The probability of 0 is kept in 13 bits; the counts are halved past 2^13 and the
 * probability is recomputed after 4, 5, 6, ... up to every 64 decisions. */
class LazBitModel {
public:
  LazBitModel() { reset(); }

  /** \brief Back to equiprobable, as at the start of a chunk. */
  void
  reset ();

private:
  friend class LazArithmeticDecoder;
  void
  update ();

  std::uint32_t bit_0_count_;
  std::uint32_t bit_count_;
  std::uint32_t bit_0_prob_;
  std::uint32_t bits_until_update_;
  std::uint32_t update_cycle_;
};

/** \brief Adaptive distribution of \a symbols symbols (LASzip's ArithmeticModel; Said,
 * 2003, section 3.3 "adaptive multi-symbol models").
 *
 * Counts start at one each and are halved past 2^15; the cumulative distribution (15
 * bits) is recomputed after (symbols + 6) / 2 symbols, then each time after 5/4 as
 * many, at most 8 (symbols + 6).
 *
 * Every model keeps a look-up table from the top bits of the scaled value to the range
 * of symbols it can fall in. LASzip's table has about one entry per four symbols and
 * only for more than 16 symbols; this one has about four entries per symbol (at most
 * 4096), so the bisection after the look-up mostly has nothing to do. The table changes
 * only the speed: the decoded symbols are those of the distribution. */
class LazSymbolModel {
public:
  /** \param[in] symbols the alphabet size, 2 to 2048 \throw std::invalid_argument else
   */
  explicit LazSymbolModel (std::uint32_t symbols);

  LazSymbolModel (LazSymbolModel&&) = default;
  LazSymbolModel&
  operator= (LazSymbolModel&&) = default;
  LazSymbolModel (const LazSymbolModel&) = delete;
  LazSymbolModel&
  operator= (const LazSymbolModel&) = delete;

  /** \brief Back to the uniform distribution, as at the start of a chunk. */
  void
  reset ();

  /** \brief The alphabet size. */
  std::uint32_t
  symbols () const
  {
    return symbols_;
  }

private:
  friend class LazArithmeticDecoder;
  void
  update ();

  // What decoding a symbol reads comes first, within one cache line: the cumulative
  // distribution (symbols entries, each below 2^15) and the decoder table (table_size_
  // + 2 entries: the symbols of distribution values from t << table_shift_ are in
  // [decoder_table_[t], decoder_table_[t + 1]]) point into lookup_.
  std::uint16_t* distribution_ = nullptr;
  std::uint16_t* decoder_table_ = nullptr;
  std::uint32_t* symbol_count_ = nullptr;
  std::uint32_t table_shift_ = 0;
  std::uint32_t table_size_ = 0;
  std::uint32_t last_symbol_;
  std::uint32_t symbols_until_update_ = 0;
  std::uint32_t symbols_;
  std::uint32_t total_count_ = 0;
  std::uint32_t update_cycle_ = 0;
  std::vector<std::uint16_t> lookup_;
  std::vector<std::uint32_t> counts_;
  std::shared_ptr<const std::vector<std::uint16_t>> pristine_; ///< lookup_ when fresh
};

/** \brief The range decoder of LAZ (LASzip's ArithmeticDecoder, after Said's FastAC;
 * LASzip compressed format, "arithmetic coder").
 *
 * 32-bit interval (value, length), renormalised a byte at a time, most significant byte
 * first, whenever length drops below 2^24. Reads only inside the buffer given to
 * init(): a read past its end throws LazDataError, as does a raw value out of its
 * range. */
class LazArithmeticDecoder {
public:
  /** \brief Start decoding the bytes [begin, end): reads the first four bytes.
   * \throw LazDataError when there are fewer than four */
  void
  init (const std::uint8_t* begin, const std::uint8_t* end);

  /** \brief Bytes read so far since init(). */
  std::size_t
  bytesRead () const
  {
    return static_cast<std::size_t> (next_ - begin_);
  }

  /** \brief Decode one bit with an adaptive model. */
  std::uint32_t
  decodeBit (LazBitModel& m)
  {
    const std::uint32_t x = m.bit_0_prob_ * (length_ >> 13);
    std::uint32_t bit;
    if (value_ < x) {
      bit = 0;
      length_ = x;
      ++m.bit_0_count_;
    }
    else {
      bit = 1;
      value_ -= x;
      length_ -= x;
    }
    if (length_ < min_length)
      renormalize();
    if (--m.bits_until_update_ == 0)
      m.update();
    return bit;
  }

  /** \brief Decode one symbol with an adaptive model: a value in [0, m.symbols()). */
  std::uint32_t
  decodeSymbol (LazSymbolModel& m)
  {
    std::uint32_t y = length_;
    length_ >>= 15;
    const std::uint32_t dv = value_ / length_;
    std::uint32_t t = dv >> m.table_shift_;
    if (t > m.table_size_) // only in corrupt data: value beyond the interval
      t = m.table_size_;
    std::uint32_t sym = m.decoder_table_[t];
    std::uint32_t n = m.decoder_table_[t + 1] + 1u;
    while (n > sym + 1) {
      const std::uint32_t k = (sym + n) >> 1;
      if (m.distribution_[k] > dv)
        n = k;
      else
        sym = k;
    }
    const std::uint32_t x = m.distribution_[sym] * length_;
    if (sym != m.last_symbol_)
      y = m.distribution_[sym + 1] * length_;
    value_ -= x;
    length_ = y - x;
    if (length_ < min_length)
      renormalize();
    ++m.symbol_count_[sym];
    if (--m.symbols_until_update_ == 0)
      m.update();
    return sym;
  }

  /** \brief Read \a bits (1 to 32) raw bits, uniformly distributed. */
  std::uint32_t
  readBits (unsigned bits)
  {
    if (bits - 1u >= 19u) // 0, or more than 19 bits: checked and split in two
      return readLongBits (bits);
    length_ >>= bits;
    const std::uint32_t sym = value_ / length_;
    value_ -= length_ * sym;
    if (length_ < min_length)
      renormalize();
    if (sym >> bits)
      throwOutOfRange();
    return sym;
  }

  /** \brief Read 16 raw bits. */
  std::uint32_t
  readShort ()
  {
    return readBits (16);
  }

  /** \brief Read 32 raw bits: the low 16 bits first. */
  std::uint32_t
  readInt ()
  {
    const std::uint32_t low = readShort();
    return (readShort() << 16) | low;
  }

private:
  static constexpr std::uint32_t min_length = 0x01000000u;

  void
  renormalize ()
  {
    do {
      if (next_ == end_)
        throwPastEnd();
      value_ = (value_ << 8) | *next_++;
    }
    while ((length_ <<= 8) < min_length);
  }

  std::uint32_t
  readLongBits (unsigned bits);

  [[noreturn]] void
  throwPastEnd () const;

  [[noreturn]] static void
  throwOutOfRange ();

  const std::uint8_t* begin_ = nullptr;
  const std::uint8_t* next_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  std::uint32_t value_ = 0;
  std::uint32_t length_ = 0;
};

/** \brief Decoder of integers predicted from a context (LASzip's IntegerCompressor,
 * decompressing side; LASzip compressed format, "integer compressor").
 *
 * The corrector c = real - prediction is sent as k, the number of its significant bits
 * (one symbol model per context, k in [0, bits]), then c's position in the k-bit
 * interval: one adaptive bit when k = 0 (c is 0 or 1), a symbol model of 2^k symbols
 * when k <= bits_high, else the high bits_high bits through a model and the rest raw.
 * The result wraps around modulo 2^bits. */
class LazIntegerDecompressor {
public:
  /** \param[in] bits the width of the values, 1 to 32 (LASzip's default 16)
   * \param[in] contexts how many contexts choose the model of k (default 1)
   * \param[in] bits_high bits of a large corrector coded through a model (default 8)
   * \param[in] range the number of distinct values when not 2^bits, 0 for 2^bits */
  explicit LazIntegerDecompressor (std::uint32_t bits = 16,
                                   std::uint32_t contexts = 1,
                                   std::uint32_t bits_high = 8,
                                   std::uint32_t range = 0);

  /** \brief Back to the initial models, as at the start of a chunk. */
  void
  reset ();

  /** \brief Decode the value predicted as \a pred in \a context. */
  std::int32_t
  decompress (LazArithmeticDecoder& dec, std::int32_t pred, std::uint32_t context = 0)
  {
    const std::int64_t real =
        static_cast<std::int64_t> (pred) + readCorrector (dec, context);
    // Fold into [0, range) as LASzip does; a 32-bit value simply wraps around.
    std::int64_t folded = real;
    if (folded < 0)
      folded += corr_range_;
    else if (folded >= static_cast<std::int64_t> (corr_range_) && corr_range_ != 0)
      folded -= corr_range_;
    return static_cast<std::int32_t> (static_cast<std::uint32_t> (folded));
  }

  /** \brief The k (significant bits of the corrector) of the last decoded value: LASzip
   * uses it as context for the following coordinates. */
  std::uint32_t
  k () const
  {
    return k_;
  }

private:
  std::int64_t
  readCorrector (LazArithmeticDecoder& dec, std::uint32_t context)
  {
    k_ = dec.decodeSymbol (
        fresh (m_bits_, bits_stale_, context < m_bits_.size() ? context : 0));
    if (k_ == 0) // c is 0 or 1
      return dec.decodeBit (m_corrector0_);
    if (k_ >= 32)
      return corr_min_;
    std::int64_t c;
    LazSymbolModel& m = fresh (m_corrector_, corrector_stale_, k_ - 1);
    if (k_ <= bits_high_)
      c = dec.decodeSymbol (m);
    else {
      const unsigned low_bits = k_ - bits_high_;
      const std::uint32_t high = dec.decodeSymbol (m);
      c = (static_cast<std::int64_t> (high) << low_bits) | dec.readBits (low_bits);
    }
    // c is in [0, 2^k): the upper half stands for [2^(k-1) + 1, 2^k], the lower half
    // for [-(2^k - 1), -2^(k-1)].
    if (c >= (std::int64_t (1) << (k_ - 1)))
      return c + 1;
    return c - ((std::int64_t (1) << k_) - 1);
  }

  /** The model \a i, reset first if reset() was called since its last use: a chunk
   * resets a few hundred models of which it often uses a few. */
  static LazSymbolModel&
  fresh (std::vector<LazSymbolModel>& models,
         std::vector<std::uint8_t>& stale,
         std::size_t i)
  {
    if (stale[i]) {
      models[i].reset();
      stale[i] = 0;
    }
    return models[i];
  }

  std::uint32_t bits_high_;
  std::uint32_t corr_bits_;
  std::uint32_t corr_range_;
  std::int32_t corr_min_;
  std::uint32_t k_ = 0;
  std::vector<LazSymbolModel> m_bits_;
  LazBitModel m_corrector0_;
  std::vector<LazSymbolModel> m_corrector_; // index k - 1 for k = 1 ... corr_bits
  // One byte a flag rather than std::vector<bool>: no bit masking on each decoded
  // value.
  std::vector<std::uint8_t> bits_stale_, corrector_stale_;
};
} // namespace io
} // namespace pcl_ext
