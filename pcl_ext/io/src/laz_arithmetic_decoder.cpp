/*
 * pcl_ext: the entropy decoder of LAZ point data (models, raw bits, integer decoder).
 */
#include <pcl_ext/io/laz_arithmetic_decoder.h>

#include <algorithm>
#include <map>
#include <mutex>

namespace pcl_ext {
namespace io {
namespace {
// Bit models keep 13-bit probabilities, symbol models 15-bit distributions (LASzip's
// BM__LengthShift and DM__LengthShift); counts are halved past these.
constexpr std::uint32_t bit_length_shift = 13;
constexpr std::uint32_t bit_max_count = 1u << bit_length_shift;
constexpr std::uint32_t symbol_length_shift = 15;
constexpr std::uint32_t symbol_max_count = 1u << symbol_length_shift;

/** One shared copy of the \a lookup of a fresh model of \a symbols symbols: every
 * model of that size starts from the same one, and a chunk start resets hundreds. */
std::shared_ptr<const std::vector<std::uint16_t>>
pristineLookup (std::uint32_t symbols, const std::vector<std::uint16_t>& lookup)
{
  static std::mutex mutex;
  static std::map<std::uint32_t, std::shared_ptr<const std::vector<std::uint16_t>>>
      copies;
  const std::lock_guard<std::mutex> lock (mutex);
  auto& copy = copies[symbols];
  if (!copy)
    copy = std::make_shared<const std::vector<std::uint16_t>> (lookup);
  return copy;
}
} // namespace

void
LazBitModel::reset()
{
  bit_0_count_ = 1;
  bit_count_ = 2;
  bit_0_prob_ = 1u << (bit_length_shift - 1);
  update_cycle_ = bits_until_update_ = 4;
}

void
LazBitModel::update()
{
  if ((bit_count_ += update_cycle_) > bit_max_count) {
    bit_count_ = (bit_count_ + 1) >> 1;
    bit_0_count_ = (bit_0_count_ + 1) >> 1;
    if (bit_0_count_ == bit_count_)
      ++bit_count_;
  }
  const std::uint32_t scale = 0x80000000u / bit_count_;
  bit_0_prob_ = (bit_0_count_ * scale) >> (31 - bit_length_shift);
  update_cycle_ = (5 * update_cycle_) >> 2;
  if (update_cycle_ > 64)
    update_cycle_ = 64;
  bits_until_update_ = update_cycle_;
}

LazSymbolModel::LazSymbolModel (std::uint32_t symbols) : symbols_ (symbols)
{
  if (symbols < 2 || symbols > (1u << 11))
    throw std::invalid_argument (
        "LazSymbolModel: the number of symbols must be in [2, 2048]");
  last_symbol_ = symbols - 1;
  std::uint32_t table_bits = 3;
  while (symbols > (1u << (table_bits - 2)) && table_bits < 12)
    ++table_bits;
  table_size_ = 1u << table_bits;
  table_shift_ = symbol_length_shift - table_bits;
  lookup_.assign (static_cast<std::size_t> (symbols) + table_size_ + 2, 0);
  distribution_ = lookup_.data();
  decoder_table_ = distribution_ + symbols;
  counts_.assign (symbols, 1);
  symbol_count_ = counts_.data();
  // The state of a fresh model, computed once: reset() copies it back.
  update_cycle_ = symbols_;
  update();
  symbols_until_update_ = update_cycle_ = (symbols_ + 6) >> 1;
  pristine_ = pristineLookup (symbols_, lookup_);
}

void
LazSymbolModel::reset()
{
  // As the constructor left it: every count 1, the uniform distribution and its table.
  std::copy (pristine_->begin(), pristine_->end(), lookup_.begin());
  std::fill (counts_.begin(), counts_.end(), 1u);
  total_count_ = symbols_;
  symbols_until_update_ = update_cycle_ = (symbols_ + 6) >> 1;
}

void
LazSymbolModel::update()
{
  if ((total_count_ += update_cycle_) > symbol_max_count) {
    total_count_ = 0;
    for (std::uint32_t n = 0; n < symbols_; ++n)
      total_count_ += (symbol_count_[n] = (symbol_count_[n] + 1) >> 1);
  }
  std::uint32_t sum = 0, s = 0;
  const std::uint32_t scale = 0x80000000u / total_count_;
  for (std::uint32_t k = 0; k < symbols_; ++k) {
    distribution_[k] =
        static_cast<std::uint16_t> ((scale * sum) >> (31 - symbol_length_shift));
    sum += symbol_count_[k];
    const std::uint32_t w = distribution_[k] >> table_shift_;
    while (s < w)
      decoder_table_[++s] = static_cast<std::uint16_t> (k - 1);
  }
  decoder_table_[0] = 0;
  while (s <= table_size_)
    decoder_table_[++s] = static_cast<std::uint16_t> (symbols_ - 1);
  update_cycle_ = (5 * update_cycle_) >> 2;
  const std::uint32_t max_cycle = (symbols_ + 6) << 3;
  if (update_cycle_ > max_cycle)
    update_cycle_ = max_cycle;
  symbols_until_update_ = update_cycle_;
}

void
LazArithmeticDecoder::init (const std::uint8_t* begin, const std::uint8_t* end)
{
  begin_ = next_ = begin;
  end_ = end;
  length_ = 0xFFFFFFFFu;
  if (end - begin < 4)
    throw LazDataError ("the compressed stream has fewer than 4 bytes");
  value_ = (std::uint32_t (next_[0]) << 24) | (std::uint32_t (next_[1]) << 16) |
           (std::uint32_t (next_[2]) << 8) | std::uint32_t (next_[3]);
  next_ += 4;
}

std::uint32_t
LazArithmeticDecoder::readLongBits (unsigned bits)
{
  if (bits == 0 || bits > 32)
    throw std::invalid_argument ("LazArithmeticDecoder::readBits: 1 to 32 bits");
  const std::uint32_t low = readBits (16);
  return (readBits (bits - 16) << 16) | low;
}

void
LazArithmeticDecoder::throwOutOfRange()
{
  throw LazDataError ("a raw value is out of its range");
}

void
LazArithmeticDecoder::throwPastEnd() const
{
  throw LazDataError ("the compressed stream ends too early (" +
                      std::to_string (end_ - begin_) + " bytes)");
}

LazIntegerDecompressor::LazIntegerDecompressor (std::uint32_t bits,
                                                std::uint32_t contexts,
                                                std::uint32_t bits_high,
                                                std::uint32_t range)
: bits_high_ (bits_high)
{
  if (bits == 0 || bits > 32 || contexts == 0 || bits_high == 0 || bits_high > 11)
    throw std::invalid_argument ("LazIntegerDecompressor: invalid parameters");
  if (range != 0) {
    corr_bits_ = 0;
    corr_range_ = range;
    for (std::uint32_t r = range; r != 0; r >>= 1)
      ++corr_bits_;
    if (corr_range_ == (1u << (corr_bits_ - 1)))
      --corr_bits_;
    corr_min_ = -static_cast<std::int32_t> (corr_range_ / 2);
  }
  else if (bits < 32) {
    corr_bits_ = bits;
    corr_range_ = 1u << bits;
    corr_min_ = -static_cast<std::int32_t> (corr_range_ / 2);
  }
  else {
    corr_bits_ = 32;
    corr_range_ = 0;
    corr_min_ = INT32_MIN;
  }
  m_bits_.reserve (contexts);
  for (std::uint32_t i = 0; i < contexts; ++i)
    m_bits_.emplace_back (corr_bits_ + 1);
  m_corrector_.reserve (corr_bits_);
  for (std::uint32_t k = 1; k <= corr_bits_; ++k)
    m_corrector_.emplace_back (1u << (k <= bits_high_ ? k : bits_high_));
  bits_stale_.assign (m_bits_.size(), 0);
  corrector_stale_.assign (m_corrector_.size(), 0);
}

void
LazIntegerDecompressor::reset()
{
  bits_stale_.assign (m_bits_.size(), 1);
  m_corrector0_.reset();
  corrector_stale_.assign (m_corrector_.size(), 1);
  k_ = 0;
}

} // namespace io
} // namespace pcl_ext
