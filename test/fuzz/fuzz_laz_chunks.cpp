/*
 * Fuzz target: pcl_ext::io::LazChunkDecoder (a chunk of each supported item set) and
 * decodeLazChunkTable.
 *
 * Byte 0 chooses what the rest is decoded as: a chunk of one of the item sets below, or
 * (the last choices) the body of a chunk table of fixed or variable chunks. Byte 1
 * gives the number of points (or chunk table entries) to decode, 1 to 256 times 4. The
 * rest, copied to a buffer of exactly its size, is the chunk: decoding must end with
 * records or a LazDataError, never with a read outside it or a hang.
 */
#include <pcl_ext/io/laz_chunk_decoder.h>

#include "fuzz_input_file.h"

#include <vector>

namespace {
using pcl_ext::io::LaszipVlr;
using pcl_ext::io::LazItem;

LaszipVlr
vlrOf (std::uint16_t compressor, std::vector<LazItem> items)
{
  LaszipVlr vlr;
  vlr.compressor = compressor;
  vlr.chunk_size = 50000;
  vlr.items = std::move (items);
  return vlr;
}

const std::vector<LaszipVlr>&
itemSets ()
{
  static const std::vector<LaszipVlr> sets = {
      vlrOf (2, {{6, 20, 2}}),                                  // format 0
      vlrOf (2, {{6, 20, 2}, {7, 8, 2}}),                       // format 1
      vlrOf (2, {{6, 20, 2}, {8, 6, 2}}),                       // format 2
      vlrOf (2, {{6, 20, 2}, {7, 8, 2}, {8, 6, 2}}),            // format 3
      vlrOf (2, {{6, 20, 2}, {7, 8, 2}, {8, 6, 2}, {0, 3, 2}}), // format 3, extra bytes
      vlrOf (3, {{10, 30, 3}}),                                 // format 6
      vlrOf (3, {{10, 30, 3}, {11, 6, 3}}),                     // format 7
      vlrOf (3, {{10, 30, 3}, {12, 8, 3}}),                     // format 8
      vlrOf (3, {{10, 30, 3}, {11, 6, 3}, {14, 2, 3}}),         // format 7, extra bytes
      vlrOf (3, {{10, 30, 4}, {12, 8, 4}, {14, 1, 4}}),         // format 8, v4 items
  };
  return sets;
}
} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  if (size < 2)
    return 0;
  const auto& sets = itemSets();
  const std::size_t choice = data[0] % (sets.size() + 2);
  const std::size_t count = 4 * (std::size_t (data[1]) + 1);
  // An exactly sized copy: a read past the chunk is a heap overflow under ASan.
  const std::vector<std::uint8_t> chunk (data + 2, data + size);
  using pcl_ext_fuzz::check;
  try {
    if (choice >= sets.size()) {
      const auto table =
          pcl_ext::io::decodeLazChunkTable (chunk.data(),
                                            chunk.size(),
                                            static_cast<std::uint32_t> (count),
                                            choice > sets.size());
      check (table.size() == count, "a decoded chunk table has all its entries");
      for (const auto& entry : table)
        check (entry.byte_count > 0, "chunk table entries have bytes");
      return 0;
    }
    pcl_ext::io::LazChunkDecoder decoder (sets[choice]);
    decoder.startChunk (chunk.data(), chunk.size());
    std::vector<std::uint8_t> records (count * decoder.recordLength());
    // In uneven blocks, as a reader asks for them.
    std::size_t done = 0;
    for (std::size_t block = 1; done < count; block = block * 2 + 1) {
      const std::size_t n = std::min (block, count - done);
      decoder.decode (n, records.data() + done * decoder.recordLength());
      done += n;
    }
    check (decoder.bytesUsed() <= chunk.size(), "a chunk uses no byte past its end");
  }
  catch (const pcl_ext::io::LazDataError&) {
  }
  return 0;
}
