/*
 * Tests of the LAZ entropy decoder on hand-made byte sequences: each expected value is
 * worked out from the coder's definition (32-bit interval, 13-bit bit models, 15-bit
 * symbol distributions) in the comment next to it.
 */
#include <pcl_ext/io/laz_arithmetic_decoder.h>

#include <pcl_ext/common/random.h>

#include <gtest/gtest.h>

#include <vector>

using pcl_ext::io::LazArithmeticDecoder;
using pcl_ext::io::LazBitModel;
using pcl_ext::io::LazDataError;
using pcl_ext::io::LazIntegerDecompressor;
using pcl_ext::io::LazSymbolModel;

namespace {
/** A decoder over \a bytes (kept alive by the caller, exactly sized so that a read past
 * the end shows under AddressSanitizer). */
LazArithmeticDecoder
decoderOver (const std::vector<std::uint8_t>& bytes)
{
  LazArithmeticDecoder dec;
  dec.init (bytes.data(), bytes.data() + bytes.size());
  return dec;
}

/** LASzip's adaptive symbol model and symbol decoding written out the plain way: the
 * distribution recomputed on the same schedule, the symbol found by bisecting the whole
 * distribution (multiplying out each boundary), no look-up table. */
class ReferenceSymbolDecoder {
public:
  ReferenceSymbolDecoder (const std::vector<std::uint8_t>& bytes, std::uint32_t symbols)
  : bytes_ (bytes), counts_ (symbols, 1), distribution_ (symbols)
  {
    value_ = (std::uint32_t (bytes[0]) << 24) | (std::uint32_t (bytes[1]) << 16) |
             (std::uint32_t (bytes[2]) << 8) | std::uint32_t (bytes[3]);
    next_ = 4;
    cycle_ = symbols;
    update();
    until_ = cycle_ = (symbols + 6) / 2;
  }

  std::uint32_t
  decode ()
  {
    std::uint32_t sym = 0, x = 0, y = length_, n = symbols();
    length_ >>= 15;
    for (std::uint32_t k = n / 2; k != sym; k = (sym + n) / 2) {
      const std::uint32_t z = length_ * distribution_[k];
      if (z > value_) {
        n = k;
        y = z;
      }
      else {
        sym = k;
        x = z;
      }
    }
    value_ -= x;
    length_ = y - x;
    while (length_ < (1u << 24)) {
      value_ = (value_ << 8) | bytes_.at (next_++);
      length_ <<= 8;
    }
    ++counts_[sym];
    if (--until_ == 0)
      update();
    return sym;
  }

private:
  std::uint32_t
  symbols () const
  {
    return static_cast<std::uint32_t> (counts_.size());
  }

  void
  update ()
  {
    if ((total_ += cycle_) > (1u << 15)) {
      total_ = 0;
      for (auto& c : counts_)
        total_ += (c = (c + 1) / 2);
    }
    const std::uint32_t scale = 0x80000000u / total_;
    std::uint32_t sum = 0;
    for (std::uint32_t k = 0; k < symbols(); ++k) {
      distribution_[k] = (scale * sum) >> 16;
      sum += counts_[k];
    }
    cycle_ = std::min ((5 * cycle_) / 4, (symbols() + 6) * 8);
    until_ = cycle_;
  }

  const std::vector<std::uint8_t>& bytes_;
  std::size_t next_ = 0;
  std::uint32_t value_ = 0, length_ = 0xFFFFFFFFu;
  std::vector<std::uint32_t> counts_, distribution_;
  std::uint32_t total_ = 0, cycle_ = 0, until_ = 0;
};
} // namespace

TEST (LazArithmeticDecoder, NeedsFourBytesToStart)
{
  const std::vector<std::uint8_t> three = {1, 2, 3};
  LazArithmeticDecoder dec;
  EXPECT_THROW (dec.init (three.data(), three.data() + three.size()), LazDataError);
  const std::vector<std::uint8_t> four = {1, 2, 3, 4};
  EXPECT_NO_THROW (dec.init (four.data(), four.data() + four.size()));
  EXPECT_EQ (dec.bytesRead(), 4u);
}

TEST (LazArithmeticDecoder, RawBytesComeBackAsWritten)
{
  // value = 0x12345678, length = 2^32 - 1. readBits(8): length = 0x00FFFFFF, symbol =
  // value / length = 0x12, value = 0x0234568A; length < 2^24 reads byte 0x9A: value =
  // 0x34568A9A, length = 0xFFFFFF00. Next: 0x34568A9A / 0x00FFFFFF = 0x34.
  const std::vector<std::uint8_t> bytes = {0x12, 0x34, 0x56, 0x78, 0x9A, 0xBC, 0, 0};
  LazArithmeticDecoder dec = decoderOver (bytes);
  EXPECT_EQ (dec.readBits (8), 0x12u);
  EXPECT_EQ (dec.bytesRead(), 5u);
  EXPECT_EQ (dec.readBits (8), 0x34u);
  EXPECT_EQ (dec.bytesRead(), 6u);
}

TEST (LazArithmeticDecoder, IntsAreLowHalfFirst)
{
  // readShort: 0x12345678 / 0xFFFF = 0x1234, value = 0x68AC; two bytes renormalise:
  // value = 0x68AC9ABC, length = 0xFFFF0000. Then 0x68AC9ABC / 0xFFFF = 0x68AD. The
  // first 16 bits are the low half.
  const std::vector<std::uint8_t> bytes = {
      0x12, 0x34, 0x56, 0x78, 0x9A, 0xBC, 0xDE, 0, 0};
  LazArithmeticDecoder dec = decoderOver (bytes);
  EXPECT_EQ (dec.readInt(), 0x68AD1234u);
}

TEST (LazArithmeticDecoder, RawValueOutOfRangeIsAnError)
{
  // value = length = 2^32 - 1: readBits(8) gives (2^32 - 1) / 0x00FFFFFF = 256, which
  // no encoder writes.
  const std::vector<std::uint8_t> bytes (8, 0xFF);
  LazArithmeticDecoder dec = decoderOver (bytes);
  EXPECT_THROW (dec.readBits (8), LazDataError);
}

TEST (LazArithmeticDecoder, ReadPastTheEndIsAnError)
{
  const std::vector<std::uint8_t> bytes = {0x12, 0x34, 0x56, 0x78};
  LazArithmeticDecoder dec = decoderOver (bytes);
  // The first raw byte shrinks the interval below 2^24: a fifth byte is needed.
  EXPECT_THROW (dec.readBits (8), LazDataError);
}

TEST (LazArithmeticDecoder, BitWithEquiprobableModel)
{
  // Fresh model: P(0) = 2^12 / 2^13. x = 4096 * ((2^32 - 1) >> 13) = 0x7FFFF000.
  // value 0x80000000 >= x: bit 1, value = 0x1000, length = 0x80000FFF. Then x =
  // 4096 * (0x80000FFF >> 13) = 0x40000000 > value: bit 0.
  const std::vector<std::uint8_t> bytes = {0x80, 0, 0, 0, 0, 0, 0, 0};
  LazArithmeticDecoder dec = decoderOver (bytes);
  LazBitModel m;
  EXPECT_EQ (dec.decodeBit (m), 1u);
  EXPECT_EQ (dec.decodeBit (m), 0u);
  EXPECT_EQ (dec.bytesRead(), 4u);
}

TEST (LazArithmeticDecoder, SymbolWithUniformModelBySearch)
{
  // 4 symbols: distribution k * 2^13, length >> 15 = 0x1FFFF. value
  // 0x40000000 lies in [8192, 16384) * 0x1FFFF: symbol 1; 0xC0000000: symbol 3.
  for (const auto& [lead, expected] :
       std::vector<std::pair<std::uint8_t, std::uint32_t>>{
           {0x00, 0}, {0x40, 1}, {0xC0, 3}}) {
    const std::vector<std::uint8_t> bytes = {lead, 0, 0, 0, 0, 0, 0, 0};
    LazArithmeticDecoder dec = decoderOver (bytes);
    LazSymbolModel m (4);
    EXPECT_EQ (dec.decodeSymbol (m), expected) << int (lead);
  }
}

TEST (LazArithmeticDecoder, SymbolWithUniformModelByTable)
{
  // 16 symbols: distribution k * 2^11; 32 symbols: k * 2^10. value
  // 0x40000000 / 0x1FFFF = 8192: symbol 4 of 16, symbol 8 of 32.
  const std::vector<std::uint8_t> bytes = {0x40, 0, 0, 0, 0, 0, 0, 0};
  LazArithmeticDecoder a = decoderOver (bytes);
  LazSymbolModel m16 (16);
  EXPECT_EQ (a.decodeSymbol (m16), 4u);
  LazArithmeticDecoder b = decoderOver (bytes);
  LazSymbolModel m32 (32);
  EXPECT_EQ (b.decodeSymbol (m32), 8u);
}

TEST (LazArithmeticDecoder, SymbolsAreThoseOfThePlainBisection)
{
  // The decoder's look-up table only says where to start looking: whatever the alphabet
  // and however skewed the model has become, each symbol is the one a plain bisection
  // of the distribution finds. Streams of uniform bytes keep the models near uniform;
  // streams that are mostly zero bytes skew them towards the first symbols.
  for (const std::uint32_t symbols :
       {2u, 3u, 5u, 16u, 17u, 33u, 64u, 256u, 257u, 2048u}) {
    for (const bool skewed : {false, true}) {
      pcl_ext::RandomStream random (symbols * 2 + skewed);
      std::vector<std::uint8_t> bytes (200000);
      for (auto& b : bytes)
        b = (skewed && random.uniform() < 0.9)
                ? 0
                : static_cast<std::uint8_t> (random.next());
      LazArithmeticDecoder dec = decoderOver (bytes);
      LazSymbolModel model (symbols);
      ReferenceSymbolDecoder reference (bytes, symbols);
      for (int i = 0; i < 20000; ++i)
        ASSERT_EQ (dec.decodeSymbol (model), reference.decode())
            << symbols << " symbols, " << (skewed ? "skewed" : "uniform")
            << " stream, symbol " << i;
      // reset() makes the adapted model a fresh one again, as at a chunk's start.
      model.reset();
      LazArithmeticDecoder again = decoderOver (bytes);
      ReferenceSymbolDecoder fresh (bytes, symbols);
      for (int i = 0; i < 2000; ++i)
        ASSERT_EQ (again.decodeSymbol (model), fresh.decode())
            << symbols << " symbols after reset(), symbol " << i;
    }
  }
}

TEST (LazArithmeticDecoder, ModelsAdaptToWhatTheyDecode)
{
  // An all-zero stream decodes bit 0 again and again; as P(0) grows each bit costs less
  // than one, so 2000 bits take far fewer than 250 bytes.
  const std::vector<std::uint8_t> bytes (250, 0);
  LazArithmeticDecoder dec = decoderOver (bytes);
  LazBitModel m;
  for (int i = 0; i < 2000; ++i)
    ASSERT_EQ (dec.decodeBit (m), 0u);
  EXPECT_LT (dec.bytesRead(), 50u);
  // reset() goes back to equiprobable: the next leading 0x80 is a 1 again.
  const std::vector<std::uint8_t> one = {0x80, 0, 0, 0, 0, 0, 0, 0};
  dec.init (one.data(), one.data() + one.size());
  m.reset();
  EXPECT_EQ (dec.decodeBit (m), 1u);
}

TEST (LazArithmeticDecoder, SymbolModelSizes)
{
  EXPECT_THROW (LazSymbolModel (1), std::invalid_argument);
  EXPECT_THROW (LazSymbolModel (2049), std::invalid_argument);
  EXPECT_EQ (LazSymbolModel (2048).symbols(), 2048u);
}

TEST (LazIntegerDecompressor, ZeroStreamRepeatsThePrediction)
{
  // value 0: k = 0, then bit 0: corrector 0.
  const std::vector<std::uint8_t> bytes (16, 0);
  LazArithmeticDecoder dec = decoderOver (bytes);
  LazIntegerDecompressor ic (32, 2);
  EXPECT_EQ (ic.decompress (dec, 123456, 0), 123456);
  EXPECT_EQ (ic.k(), 0u);
  EXPECT_EQ (ic.decompress (dec, -7, 1), -7);
}

TEST (LazIntegerDecompressor, CorrectorOneWrapsSixteenBits)
{
  // 16 bits: k has 17 symbols, distribution[1] = (2^31 / 17 >> 16) = 1927; k = 0 when
  // value < 1927 * 0x1FFFF = 0x0F0DF879. value = 0x0F000000: k = 0, length =
  // 0x0F0DF879. Then x = 4096 * (length >> 13) = 126283776 <= value: bit 1, corrector
  // +1, and 65535 + 1 wraps to 0.
  const std::vector<std::uint8_t> bytes = {0x0F, 0, 0, 0, 0, 0, 0, 0};
  LazArithmeticDecoder dec = decoderOver (bytes);
  LazIntegerDecompressor ic (16);
  EXPECT_EQ (ic.decompress (dec, 65535), 0);
  EXPECT_EQ (ic.k(), 0u);
}

TEST (LazIntegerDecompressor, ThirtyTwoBitsWrapWithoutOverflow)
{
  // Same corrector +1 with 32 bits: k has 33 symbols, distribution[1] = (2^31 / 33) >>
  // 16 = 992; value 0x06000000 < 992 * 0x1FFFF = 130022432 gives k = 0, then x = 4096 *
  // (130022432 >> 13) = 65007616 <= value gives bit 1. INT32_MAX + 1 wraps to
  // INT32_MIN.
  const std::vector<std::uint8_t> bytes = {0x06, 0, 0, 0, 0, 0, 0, 0};
  LazArithmeticDecoder dec = decoderOver (bytes);
  LazIntegerDecompressor ic (32);
  EXPECT_EQ (ic.decompress (dec, INT32_MAX), INT32_MIN);
}

TEST (LazIntegerDecompressor, InvalidParameters)
{
  EXPECT_THROW (LazIntegerDecompressor (0), std::invalid_argument);
  EXPECT_THROW (LazIntegerDecompressor (33), std::invalid_argument);
  EXPECT_THROW (LazIntegerDecompressor (16, 0), std::invalid_argument);
}
