/*
 * Tests of the LAZ chunk decoder on hand-made chunks: a raw first record followed by a
 * stream of zero bytes, whose decoding follows from the item definitions (a zero stream
 * decodes every symbol as 0: "nothing changed", every corrector 0), and truncated or
 * inconsistent chunks.
 */
#include <pcl_ext/io/laz_chunk_decoder.h>

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using pcl_ext::io::LaszipVlr;
using pcl_ext::io::LazChunkDecoder;
using pcl_ext::io::LazDataError;

namespace {
LaszipVlr
vlrOf (std::uint16_t compressor, std::vector<pcl_ext::io::LazItem> items)
{
  LaszipVlr vlr;
  vlr.compressor = compressor;
  vlr.chunk_size = 50000;
  vlr.items = std::move (items);
  return vlr;
}

/** A point format 3 record: x y z, intensity, returns 1 of 2, class 2, scan angle -5,
 * user data 7, source 9, GPS time 1234.5, red 0x0102, green 0x0304, blue 0x0506. */
std::vector<std::uint8_t>
format3Record ()
{
  std::vector<std::uint8_t> r (34, 0);
  const std::int32_t xyz[3] = {1000, -2000, 300};
  std::memcpy (r.data(), xyz, 12);
  const std::uint16_t intensity = 555;
  std::memcpy (r.data() + 12, &intensity, 2);
  r[14] = 1 | (2 << 3);
  r[15] = 2;
  r[16] = static_cast<std::uint8_t> (-5);
  r[17] = 7;
  r[18] = 9;
  const double gps = 1234.5;
  std::memcpy (r.data() + 20, &gps, 8);
  const std::uint16_t rgb[3] = {0x0102, 0x0304, 0x0506};
  std::memcpy (r.data() + 28, rgb, 6);
  return r;
}

const LaszipVlr chunkFormat3 = vlrOf (2, {{6, 20, 2}, {7, 8, 2}, {8, 6, 2}});
const LaszipVlr format6 = vlrOf (3, {{10, 30, 3}});
} // namespace

TEST (LazChunkDecoder, PointwiseZeroStreamRepeatsTheFirstRecord)
{
  // Chunk: the raw record, then 64 zero bytes. Point 2 decodes "nothing changed" (x and
  // y differences 0), so it is the first record but for what POINT10 v2 does not carry
  // over: z is predicted from the height of its return level (0 at the chunk start) and
  // the intensity from its return context (0 at the start); RGB12 v2 without a "green
  // and blue differ" bit copies red into green and blue. GPSTIME11 repeats the time.
  const std::vector<std::uint8_t> first = format3Record();
  std::vector<std::uint8_t> chunk = first;
  chunk.resize (first.size() + 64, 0);
  LazChunkDecoder decoder (chunkFormat3);
  ASSERT_EQ (decoder.recordLength(), 34u);
  decoder.startChunk (chunk.data(), chunk.size());
  std::vector<std::uint8_t> out (2 * 34);
  decoder.decode (2, out.data());
  EXPECT_TRUE (std::equal (first.begin(), first.end(), out.begin()));
  std::vector<std::uint8_t> expected = first;
  std::memset (expected.data() + 8, 0, 4);  // z
  std::memset (expected.data() + 12, 0, 2); // intensity
  expected[30] = expected[32] = 0x02;       // green, blue = red
  expected[31] = expected[33] = 0x01;
  EXPECT_EQ (std::vector<std::uint8_t> (out.begin() + 34, out.end()), expected);
  EXPECT_GT (decoder.bytesUsed(), 34u + 4u);
  EXPECT_LE (decoder.bytesUsed(), chunk.size());
}

TEST (LazChunkDecoder, LayeredZeroStreamRepeatsTheFirstRecord)
{
  // Chunk: raw record, point count 2, nine layer sizes (only the returns and x, y layer
  // has bytes: 16 zeros). All else is absent, i.e. unchanged in the chunk: point 2 is
  // point 1.
  std::vector<std::uint8_t> first (30, 0);
  const std::int32_t xyz[3] = {-5, 6, 7};
  std::memcpy (first.data(), xyz, 12);
  first[14] = 1 | (1 << 4);
  first[15] = 0x1 | (0 << 4);
  first[16] = 6;
  const double gps = 99.25;
  std::memcpy (first.data() + 22, &gps, 8);
  std::vector<std::uint8_t> chunk = first;
  const std::uint32_t header[10] = {2, 16, 0, 0, 0, 0, 0, 0, 0, 0};
  chunk.insert (chunk.end(),
                reinterpret_cast<const std::uint8_t*> (header),
                reinterpret_cast<const std::uint8_t*> (header) + sizeof (header));
  chunk.resize (chunk.size() + 16, 0);
  LazChunkDecoder decoder (format6);
  decoder.startChunk (chunk.data(), chunk.size());
  EXPECT_EQ (decoder.statedPointCount(), 2u);
  EXPECT_EQ (decoder.bytesUsed(), chunk.size());
  std::vector<std::uint8_t> out (2 * 30);
  decoder.decode (1, out.data());
  decoder.decode (1, out.data() + 30);
  EXPECT_TRUE (std::equal (first.begin(), first.end(), out.begin()));
  EXPECT_TRUE (std::equal (first.begin(), first.end(), out.begin() + 30));
}

TEST (LazChunkDecoder, TruncatedChunksAreErrors)
{
  LazChunkDecoder decoder (chunkFormat3);
  std::vector<std::uint8_t> out (34 * 100);
  // Shorter than one record.
  std::vector<std::uint8_t> chunk (20, 0);
  decoder.startChunk (chunk.data(), chunk.size());
  EXPECT_THROW (decoder.decode (1, out.data()), LazDataError);
  // A record but no stream to start the decoder.
  chunk = format3Record();
  decoder.startChunk (chunk.data(), chunk.size());
  EXPECT_THROW (decoder.decode (1, out.data()), LazDataError);
  // A stream that ends before the points it should hold: an error, never a read past it
  // (the chunk is exactly sized, so AddressSanitizer would see one).
  chunk.resize (34 + 6, 0);
  decoder.startChunk (chunk.data(), chunk.size());
  EXPECT_THROW (decoder.decode (100, out.data()), LazDataError);
}

TEST (LazChunkDecoder, LayeredHeaderMustFitTheChunk)
{
  LazChunkDecoder decoder (format6);
  std::vector<std::uint8_t> chunk (30 + 4 + 36, 0);
  // Too short for the header.
  EXPECT_THROW (decoder.startChunk (chunk.data(), chunk.size() - 1), LazDataError);
  // A layer that ends past the chunk.
  chunk[34] = 1;
  EXPECT_THROW (decoder.startChunk (chunk.data(), chunk.size()), LazDataError);
  // An empty returns-and-xy layer cannot decode a second point.
  chunk[34] = 0;
  decoder.startChunk (chunk.data(), chunk.size());
  std::vector<std::uint8_t> out (60);
  EXPECT_NO_THROW (decoder.decode (1, out.data()));
  EXPECT_THROW (decoder.decode (1, out.data() + 30), LazDataError);
}

TEST (LazChunkDecoder, DecodeBeforeAnyChunkIsAnError)
{
  LazChunkDecoder decoder (chunkFormat3);
  std::vector<std::uint8_t> out (34);
  EXPECT_THROW (decoder.decode (1, out.data()), LazDataError);
}
