/*
 * pcl_ext: the E57 page checksum and the bytestream bit unpacker.
 */
#include <pcl_ext/io/e57_format.h>

#include <array>
#include <limits>

namespace pcl_ext {
namespace io {
namespace {
std::array<std::uint32_t, 256>
crcTable ()
{
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t crc = i;
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc & 1u) ? (crc >> 1) ^ 0x82F63B78u : crc >> 1;
    table[i] = crc;
  }
  return table;
}
} // namespace

std::uint32_t
crc32c (const std::uint8_t* data, std::size_t size)
{
  static const std::array<std::uint32_t, 256> table = crcTable();
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i)
    crc = table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

unsigned
E57Field::bits() const
{
  if (type == E57FieldType::Float)
    return single_precision ? 32 : 64;
  // maximum - minimum in unsigned arithmetic is exact for every minimum <= maximum.
  std::uint64_t span =
      static_cast<std::uint64_t> (maximum) - static_cast<std::uint64_t> (minimum);
  unsigned bits = 0;
  while (span > 0) {
    ++bits;
    span >>= 1;
  }
  return bits;
}

E57BitUnpacker::E57BitUnpacker (unsigned bits) : bits_ (bits > 64 ? 64 : bits) {}

void
E57BitUnpacker::append (const std::uint8_t* data, std::size_t size)
{
  // Drop whole consumed bytes before growing, so the buffer stays near one packet.
  const std::size_t consumed = static_cast<std::size_t> (position_ / 8);
  if (consumed > 0 && consumed * 2 >= buffer_.size()) {
    buffer_.erase (buffer_.begin(), buffer_.begin() + consumed);
    position_ -= static_cast<std::uint64_t> (consumed) * 8;
  }
  buffer_.insert (buffer_.end(), data, data + size);
}

std::uint64_t
E57BitUnpacker::available() const
{
  if (bits_ == 0)
    return std::numeric_limits<std::uint64_t>::max();
  return bitsLeft() / bits_;
}

std::uint64_t
E57BitUnpacker::next()
{
  if (bits_ == 0)
    return 0;
  const std::size_t byte = static_cast<std::size_t> (position_ / 8);
  const unsigned shift = static_cast<unsigned> (position_ % 8);
  std::uint64_t value = 0;
  const std::size_t count = std::min<std::size_t> (8, buffer_.size() - byte);
  for (std::size_t i = 0; i < count; ++i)
    value |= static_cast<std::uint64_t> (buffer_[byte + i]) << (8 * i);
  value >>= shift;
  if (shift + bits_ > 64)
    value |= static_cast<std::uint64_t> (buffer_[byte + 8]) << (64 - shift);
  if (bits_ < 64)
    value &= (std::uint64_t{1} << bits_) - 1;
  position_ += bits_;
  return value;
}
} // namespace io
} // namespace pcl_ext
