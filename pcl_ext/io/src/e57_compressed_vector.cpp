/*
 * pcl_ext: E57 compressed vectors: section header, data packets, bytestreams.
 */
#include "e57_compressed_vector.h"

#include <algorithm>
#include <cstring>

namespace pcl_ext {
namespace io {
namespace detail {
namespace {
constexpr std::uint8_t kCompressedVectorSection = 1;
constexpr std::uint8_t kIndexPacket = 0, kDataPacket = 1, kEmptyPacket = 2;
constexpr std::uint64_t kSectionHeaderSize = 32;

/** Turns raw bytestream values into field values. */
class FieldDecoder {
public:
  explicit FieldDecoder (const E57Field& field)
  : field_ (field)
  , unpacker_ (field.bits())
  , span_ (static_cast<std::uint64_t> (field.maximum) -
           static_cast<std::uint64_t> (field.minimum))
  {}

  E57BitUnpacker&
  unpacker ()
  {
    return unpacker_;
  }

  /** The next value; false when an integer lies outside the declared range. */
  bool
  next (double& value)
  {
    const std::uint64_t raw = unpacker_.next();
    if (field_.type == E57FieldType::Float) {
      if (field_.single_precision) {
        const std::uint32_t bits = static_cast<std::uint32_t> (raw);
        float f;
        std::memcpy (&f, &bits, 4);
        value = f;
      }
      else
        std::memcpy (&value, &raw, 8);
      return true;
    }
    if (raw > span_)
      return false;
    const std::int64_t v = static_cast<std::int64_t> (
        static_cast<std::uint64_t> (field_.minimum) + raw); // in [minimum, maximum]
    value = static_cast<double> (v);
    if (field_.type == E57FieldType::ScaledInteger)
      value = value * field_.scale + field_.offset;
    return true;
  }

private:
  const E57Field& field_;
  E57BitUnpacker unpacker_;
  std::uint64_t span_;
};
} // namespace

void
decodeE57Points (E57PagedFile& file,
                 const E57ScanInfo& scan,
                 const std::string& where,
                 const E57RecordSink& sink)
{
  const auto fail = [&] (const std::string& message) {
    file.fail (where + ": " + message);
  };
  const std::uint64_t physical_size =
      file.logicalSize() / kE57PagePayload * kE57PageSize;
  const auto inFile = [&] (std::uint64_t physical) {
    return physical < physical_size && physical % kE57PageSize < kE57PagePayload;
  };
  if (!inFile (scan.file_offset))
    fail ("fileOffset " + std::to_string (scan.file_offset) +
          " is not inside the file");
  const std::uint64_t start = e57LogicalOffset (scan.file_offset);
  if (file.logicalSize() - start < kSectionHeaderSize)
    fail ("the compressed-vector section header goes past the end of the file");
  std::uint8_t head[kSectionHeaderSize];
  file.read (start, head, sizeof (head));
  if (head[0] != kCompressedVectorSection)
    fail ("invalid compressed-vector section header (section id " +
          std::to_string (head[0]) + ", expected 1)");
  const std::uint64_t length = readLE (head + 8, 8);
  const std::uint64_t data_offset = readLE (head + 16, 8);
  if (length < kSectionHeaderSize || length > file.logicalSize() - start)
    fail ("the compressed-vector section length " + std::to_string (length) +
          " does not fit in the file");
  const std::uint64_t end = start + length;
  if (scan.record_count == 0)
    return;

  std::uint64_t bits_per_record = 0;
  for (const auto& f : scan.prototype)
    bits_per_record += f.bits();
  if (bits_per_record == 0)
    fail ("every field of the prototype is constant; the record count cannot be "
          "checked against the data");
  const std::uint64_t capacity = (length - kSectionHeaderSize) * 8 / bits_per_record;
  if (scan.record_count > capacity)
    fail ("recordCount " + std::to_string (scan.record_count) +
          " exceeds what the section can hold (at most " + std::to_string (capacity) +
          " records of " + std::to_string (bits_per_record) + " bits)");
  if (!inFile (data_offset) ||
      e57LogicalOffset (data_offset) < start + kSectionHeaderSize ||
      e57LogicalOffset (data_offset) >= end)
    fail ("the data offset " + std::to_string (data_offset) +
          " is not inside the compressed-vector section");

  std::vector<FieldDecoder> fields;
  fields.reserve (scan.prototype.size());
  for (const auto& f : scan.prototype)
    fields.emplace_back (f);
  const std::size_t width = fields.size();
  std::vector<std::uint8_t> packet;
  std::vector<double> values;
  std::uint64_t done = 0;
  std::uint64_t position = e57LogicalOffset (data_offset);
  while (done < scan.record_count) {
    if (end - position < 4)
      fail ("recordCount " + std::to_string (scan.record_count) +
            " exceeds the data: the section ends after " + std::to_string (done) +
            " records");
    std::uint8_t packet_head[4];
    file.read (position, packet_head, 4);
    const std::uint64_t packet_length = readLE (packet_head + 2, 2) + 1;
    if (packet_length > end - position)
      fail ("a packet of " + std::to_string (packet_length) +
            " bytes at logical offset " + std::to_string (position) +
            " goes past the end of the section");
    const std::uint8_t type = packet_head[0];
    if (type == kDataPacket) {
      packet.resize (static_cast<std::size_t> (packet_length));
      file.read (position, packet.data(), packet.size());
      if (packet.size() < 6)
        fail ("a data packet is shorter than its header");
      const std::size_t streams = static_cast<std::size_t> (readLE (&packet[4], 2));
      if (streams != width && streams != 0)
        fail ("a data packet has " + std::to_string (streams) + " bytestreams, the " +
              "prototype " + std::to_string (width) + " fields");
      std::size_t at = 6 + 2 * streams;
      if (at > packet.size())
        fail ("a data packet's bytestream table goes past the packet");
      for (std::size_t s = 0; s < streams; ++s) {
        const std::size_t n = static_cast<std::size_t> (readLE (&packet[6 + 2 * s], 2));
        if (n > packet.size() - at)
          fail ("a bytestream goes past the end of its data packet");
        fields[s].unpacker().append (packet.data() + at, n);
        at += n;
      }
      std::uint64_t ready = scan.record_count - done;
      for (auto& f : fields)
        ready = std::min (ready, f.unpacker().available());
      values.resize (static_cast<std::size_t> (ready) * width);
      for (std::size_t r = 0; r < ready; ++r)
        for (std::size_t c = 0; c < width; ++c)
          if (!fields[c].next (values[r * width + c]))
            fail ("a value of " + scan.prototype[c].name +
                  " lies outside its declared minimum and maximum");
      if (ready > 0)
        sink (values, static_cast<std::size_t> (ready));
      done += ready;
    }
    else if (type != kIndexPacket && type != kEmptyPacket)
      fail ("unknown packet type " + std::to_string (type));
    position += packet_length;
  }
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
