/*
 * pcl_ext: the point records of a LAZ file, read and decompressed one chunk at a time.
 */
#include <pcl_ext/io/laz_chunk_decoder.h>
#include <pcl_ext/io/laz_format.h>
#include <pcl_ext/io/laz_record_source.h>
#include <pcl_ext/io/read_error.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace pcl_ext {
namespace io {
namespace {
std::uint64_t
u64 (const std::uint8_t* p)
{
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i)
    v = (v << 8) | p[i];
  return v;
}

std::uint32_t
u32 (const std::uint8_t* p)
{
  return std::uint32_t (p[0]) | (std::uint32_t (p[1]) << 8) |
         (std::uint32_t (p[2]) << 16) | (std::uint32_t (p[3]) << 24);
}

/** Layers of a layered chunk: nine for POINT14, one for RGB14, two for RGBNIR14, one
 * per byte for BYTE14. */
std::size_t
layerCount (const LaszipVlr& vlr)
{
  std::size_t count = 0;
  for (const auto& item : vlr.items) {
    switch (static_cast<LazItemType> (item.type)) {
    case LazItemType::Point14:
      count += 9;
      break;
    case LazItemType::RgbNir14:
      count += 2;
      break;
    case LazItemType::Byte14:
      count += item.size;
      break;
    default:
      count += 1;
    }
  }
  return count;
}

/** LAZ point data: an int64 offset of the chunk table, the chunks, the chunk table
 * (LASzip compressed format, "chunk table"). With the table, each chunk is read whole
 * from its offset; without (the offset points at itself: the writer stopped before
 * writing it), the chunks follow each other and each ends where its decoding ends. */
class LazRecordSource : public LasRecordSource {
public:
  LazRecordSource (const std::string& path,
                   std::uint64_t point_data_offset,
                   int point_format,
                   std::size_t record_length,
                   std::uint64_t point_count,
                   const std::vector<std::uint8_t>& laszip_vlr)
  : path_ (path)
  , vlr_ (parseVlr (laszip_vlr, point_format, record_length))
  , decoder_ (vlr_)
  , record_length_ (record_length)
  , point_count_ (point_count)
  {
    file_.open (path, std::ios::binary);
    if (!file_)
      fail ("cannot open");
    file_.seekg (0, std::ios::end);
    file_size_ = static_cast<std::uint64_t> (file_.tellg());
    if (point_count_ == 0)
      return;
    if (point_data_offset > file_size_ || file_size_ - point_data_offset < 8)
      fail ("the point data (offset " + std::to_string (point_data_offset) +
            ") is past the end of the file (" + std::to_string (file_size_) +
            " bytes)");
    data_begin_ = point_data_offset + 8;
    std::uint8_t field[8];
    readAt (point_data_offset, field, 8);
    std::uint64_t table = u64 (field);
    if (table ==
        ~std::uint64_t (0)) { // written to a stream: the offset is the last 8 bytes
      readAt (file_size_ - 8, field, 8);
      table = u64 (field);
    }
    if (table == point_data_offset) { // no chunk table
      if (vlr_.variableChunks())
        fail ("the chunk table is missing, and the chunks have variable sizes");
      data_end_ = file_size_;
      next_offset_ = data_begin_;
      return;
    }
    if (table < data_begin_ || table > file_size_ || file_size_ - table < 8)
      fail ("the chunk table offset " + std::to_string (table) +
            " points outside the point data (" + std::to_string (data_begin_) + " to " +
            std::to_string (file_size_) + ")");
    data_end_ = table;
    readChunkTable (table);
  }

  std::size_t
  readRecords (std::size_t n, std::uint8_t* out) override
  {
    std::size_t done = 0;
    while (done < n && points_done_ < point_count_) {
      if (chunk_remaining_ == 0)
        loadChunk();
      const std::size_t m = static_cast<std::size_t> (
          std::min<std::uint64_t> (n - done, chunk_remaining_));
      try {
        decoder_.decode (m, out + done * record_length_);
      }
      catch (const LazDataError& e) {
        fail ("chunk " + std::to_string (chunk_index_) + ": " + e.what());
      }
      done += m;
      chunk_remaining_ -= m;
      points_done_ += m;
      if (chunk_remaining_ == 0 && chunks_.empty())
        next_offset_ = chunk_offset_ + decoder_.bytesUsed();
    }
    return done;
  }

private:
  [[noreturn]] void
  fail (const std::string& message) const
  {
    throw ReadError (path_, 0, message);
  }

  LaszipVlr
  parseVlr (const std::vector<std::uint8_t>& payload,
            int point_format,
            std::size_t record_length)
  {
    try {
      return parseLaszipVlr (payload, point_format, record_length);
    }
    catch (const LazDataError& e) {
      fail (std::string ("LASzip VLR: ") + e.what());
    }
  }

  void
  readAt (std::uint64_t offset, std::uint8_t* out, std::size_t size)
  {
    file_.clear();
    file_.seekg (static_cast<std::streamoff> (offset));
    file_.read (reinterpret_cast<char*> (out), static_cast<std::streamsize> (size));
    if (!file_ || static_cast<std::size_t> (file_.gcount()) != size)
      fail ("cannot read " + std::to_string (size) + " bytes at offset " +
            std::to_string (offset));
  }

  void
  readChunkTable (std::uint64_t table)
  {
    std::uint8_t header[8];
    readAt (table, header, 8);
    if (u32 (header) != 0)
      fail ("unknown chunk table version " + std::to_string (u32 (header)));
    const std::uint32_t count = u32 (header + 4);
    // Every chunk starts with a raw record: this bounds the count before anything is
    // made.
    const std::uint64_t data_size = data_end_ - data_begin_;
    if (count == 0 || count > data_size / std::max<std::size_t> (record_length_, 1))
      fail ("the chunk table lists " + std::to_string (count) +
            " chunks, the point data (" + std::to_string (data_size) +
            " bytes) cannot hold them");
    const std::uint64_t body =
        std::min<std::uint64_t> (file_size_ - table - 8, 64 + 32ull * count);
    std::vector<std::uint8_t> bytes (static_cast<std::size_t> (body));
    readAt (table + 8, bytes.data(), bytes.size());
    try {
      chunks_ = decodeLazChunkTable (
          bytes.data(), bytes.size(), count, vlr_.variableChunks());
    }
    catch (const LazDataError& e) {
      fail (std::string ("chunk table: ") + e.what());
    }
    std::uint64_t bytes_total = 0, points_total = 0;
    for (auto& chunk : chunks_) {
      bytes_total += chunk.byte_count;
      if (!vlr_.variableChunks())
        chunk.point_count = vlr_.chunk_size;
      points_total += chunk.point_count;
    }
    if (bytes_total > data_size)
      fail ("the chunk table's chunks (" + std::to_string (bytes_total) +
            " bytes) end past the point data (" + std::to_string (data_size) +
            " bytes)");
    if (points_total < point_count_)
      fail ("the header's " + std::to_string (point_count_) +
            " points are more than the " + std::to_string (points_total) +
            " the chunks hold");
    next_offset_ = data_begin_;
  }

  void
  loadChunk ()
  {
    if (!chunks_.empty()) {
      while (next_chunk_ < chunks_.size() && chunks_[next_chunk_].point_count == 0)
        next_offset_ += chunks_[next_chunk_++].byte_count;
      if (next_chunk_ >= chunks_.size())
        fail ("the chunks end after " + std::to_string (points_done_) + " of " +
              std::to_string (point_count_) + " points");
      const LazChunk& chunk = chunks_[next_chunk_];
      buffer_.resize (static_cast<std::size_t> (chunk.byte_count));
      chunk_offset_ = next_offset_;
      readAt (chunk_offset_, buffer_.data(), buffer_.size());
      next_offset_ += chunk.byte_count;
      chunk_index_ = next_chunk_++;
      chunk_remaining_ = std::min (chunk.point_count, point_count_ - points_done_);
    }
    else {
      // No chunk table: the chunk starts where the last one ended.
      if (next_offset_ >= data_end_)
        fail ("the point data ends after " + std::to_string (points_done_) + " of " +
              std::to_string (point_count_) + " points");
      chunk_offset_ = next_offset_;
      chunk_index_ = sequential_chunks_++;
      chunk_remaining_ =
          std::min<std::uint64_t> (vlr_.chunk_size, point_count_ - points_done_);
      const std::uint64_t available = data_end_ - chunk_offset_;
      std::uint64_t size;
      if (vlr_.compressor ==
          static_cast<std::uint16_t> (LazCompressor::LayeredChunked)) {
        const std::uint64_t header = record_length_ + 4 + 4 * layerCount (vlr_);
        if (available < header)
          fail ("chunk " + std::to_string (chunk_index_) + " is truncated");
        buffer_.resize (static_cast<std::size_t> (header));
        readAt (chunk_offset_, buffer_.data(), buffer_.size());
        size = header;
        for (std::size_t i = 0; i < layerCount (vlr_); ++i)
          size += u32 (buffer_.data() + record_length_ + 4 + 4 * i);
        size = std::min (size, available);
      }
      else {
        // The chunk's size is unknown: read what the arithmetic coder can use at most
        // (records rarely compress to more than their raw size).
        size = std::min<std::uint64_t> (available,
                                        chunk_remaining_ * record_length_ * 2 + 4096);
      }
      buffer_.resize (static_cast<std::size_t> (size));
      readAt (chunk_offset_, buffer_.data(), buffer_.size());
    }
    try {
      decoder_.startChunk (buffer_.data(), buffer_.size());
    }
    catch (const LazDataError& e) {
      fail ("chunk " + std::to_string (chunk_index_) + ": " + e.what());
    }
  }

  std::string path_;
  LaszipVlr vlr_;
  LazChunkDecoder decoder_;
  std::size_t record_length_;
  std::uint64_t point_count_;
  std::ifstream file_;
  std::uint64_t file_size_ = 0;
  std::uint64_t data_begin_ = 0, data_end_ = 0;
  std::vector<LazChunk> chunks_; // empty: no chunk table
  std::size_t next_chunk_ = 0;
  std::size_t sequential_chunks_ = 0;
  std::size_t chunk_index_ = 0;
  std::uint64_t next_offset_ = 0, chunk_offset_ = 0;
  std::uint64_t chunk_remaining_ = 0;
  std::uint64_t points_done_ = 0;
  std::vector<std::uint8_t> buffer_;
};
} // namespace

std::unique_ptr<LasRecordSource>
makeLazRecordSource (const std::string& path,
                     std::uint64_t point_data_offset,
                     int point_format,
                     std::size_t record_length,
                     std::uint64_t point_count,
                     const std::vector<std::uint8_t>& laszip_vlr)
{
  return std::make_unique<LazRecordSource> (
      path, point_data_offset, point_format, record_length, point_count, laszip_vlr);
}
} // namespace io
} // namespace pcl_ext
