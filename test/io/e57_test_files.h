/*
 * Small E57 files made in the tests: bit-packed bytestreams, data packets,
 * compressed-vector sections and the paged file with its checksums (ASTM E2807
 * sections 9.3 - 9.9), written independently of the reader.
 */
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace e57_test {
using Bytes = std::vector<std::uint8_t>;

/** CRC-32C bit by bit (the reader uses a table). */
inline std::uint32_t
slowCrc32c (const std::uint8_t* data, std::size_t size)
{
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int b = 0; b < 8; ++b)
      crc = (crc & 1u) ? (crc >> 1) ^ 0x82F63B78u : crc >> 1;
  }
  return crc ^ 0xFFFFFFFFu;
}

inline void
putLE (Bytes& out, std::uint64_t v, int bytes)
{
  for (int i = 0; i < bytes; ++i)
    out.push_back (static_cast<std::uint8_t> (v >> (8 * i)));
}

/** Packs values of \a bits bits, least significant bit first. */
class BitPacker {
public:
  explicit BitPacker (unsigned bits) : bits_ (bits) {}

  void
  add (std::uint64_t v)
  {
    for (unsigned b = 0; b < bits_; ++b, ++count_) {
      if (count_ % 8 == 0)
        bytes_.push_back (0);
      if ((v >> b) & 1u)
        bytes_.back() |= static_cast<std::uint8_t> (1u << (count_ % 8));
    }
  }

  void
  addDouble (double d)
  {
    std::uint64_t v;
    std::memcpy (&v, &d, 8);
    add (v);
  }

  const Bytes&
  bytes () const
  {
    return bytes_;
  }

private:
  unsigned bits_;
  std::uint64_t count_ = 0;
  Bytes bytes_;
};

/** A data packet (section 9.8) holding one buffer per bytestream, padded to 4 bytes. */
inline Bytes
dataPacket (const std::vector<Bytes>& streams)
{
  std::size_t length = 6 + 2 * streams.size();
  for (const auto& s : streams)
    length += s.size();
  length = (length + 3) / 4 * 4;
  Bytes p;
  p.push_back (1); // data packet
  p.push_back (0);
  putLE (p, length - 1, 2);
  putLE (p, streams.size(), 2);
  for (const auto& s : streams)
    putLE (p, s.size(), 2);
  for (const auto& s : streams)
    p.insert (p.end(), s.begin(), s.end());
  p.resize (length, 0);
  return p;
}

/** Physical offset of logical offset \a logical. */
inline std::uint64_t
physical (std::uint64_t logical)
{
  return logical / 1020 * 1024 + logical % 1020;
}

/** Builds the logical byte stream of a file (the 48-byte header first), then pages it.
 */
class FileBuilder {
public:
  FileBuilder() : logical_ (48, 0) {}

  /** Appends a compressed-vector section (section 9.7) of \a packets; returns its
   * physical offset (the fileOffset of its XML). */
  std::uint64_t
  addSection (const std::vector<Bytes>& packets)
  {
    const std::uint64_t start = logical_.size();
    std::uint64_t length = 32;
    for (const auto& p : packets)
      length += p.size();
    logical_.push_back (1); // compressed vector section
    logical_.resize (logical_.size() + 7, 0);
    putLE (logical_, length, 8);
    putLE (logical_, physical (start + 32), 8);
    putLE (logical_, 0, 8); // no index packet
    for (const auto& p : packets)
      logical_.insert (logical_.end(), p.begin(), p.end());
    return physical (start);
  }

  /** The paged file with \a xml as its XML section. */
  std::string
  finish (const std::string& xml)
  {
    const std::uint64_t xml_logical = logical_.size();
    logical_.insert (logical_.end(), xml.begin(), xml.end());
    const std::size_t pages = (logical_.size() + 1019) / 1020;
    logical_.resize (pages * 1020, 0);
    Bytes head;
    for (char c : std::string ("ASTM-E57"))
      head.push_back (static_cast<std::uint8_t> (c));
    putLE (head, 1, 4);
    putLE (head, 0, 4);
    putLE (head, pages * 1024, 8);
    putLE (head, physical (xml_logical), 8);
    putLE (head, xml.size(), 8);
    putLE (head, 1024, 8);
    std::copy (head.begin(), head.end(), logical_.begin());
    std::string file;
    for (std::size_t p = 0; p < pages; ++p) {
      const std::uint8_t* page = logical_.data() + p * 1020;
      file.append (reinterpret_cast<const char*> (page), 1020);
      const std::uint32_t crc = slowCrc32c (page, 1020);
      for (int s = 24; s >= 0; s -= 8) // most significant byte first
        file.push_back (static_cast<char> ((crc >> s) & 0xFFu));
    }
    return file;
  }

private:
  Bytes logical_;
};

/** Recomputes the checksum of every page of \a file (after a test edited it). */
inline void
resealPages (std::string& file)
{
  for (std::size_t p = 0; p + 1024 <= file.size(); p += 1024) {
    const std::uint32_t crc =
        slowCrc32c (reinterpret_cast<const std::uint8_t*> (file.data() + p), 1020);
    for (int i = 0; i < 4; ++i)
      file[p + 1020 + i] = static_cast<char> ((crc >> (24 - 8 * i)) & 0xFFu);
  }
}

/** The XML section around the given data3D children. */
inline std::string
e57Xml (const std::string& data3d)
{
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<e57Root type=\"Structure\" "
         "xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\">\n"
         "<formatName type=\"String\"><![CDATA[ASTM E57 3D Imaging Data File]]>"
         "</formatName>\n<data3D type=\"Vector\" allowHeterogeneousChildren=\"1\">\n" +
         data3d + "</data3D>\n</e57Root>\n";
}
} // namespace e57_test
