/*
 * Tests of the LASzip VLR parsing and the chunk table decoding, on hand-made VLRs and
 * on chunk tables copied from the PDAL samples (simple.laz, lone-star.copc.laz), whose
 * expected entries follow from those files' headers.
 */
#include <pcl_ext/io/laz_format.h>

#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

using pcl_ext::io::decodeLazChunkTable;
using pcl_ext::io::LaszipVlr;
using pcl_ext::io::LazChunk;
using pcl_ext::io::LazDataError;
using pcl_ext::io::parseLaszipVlr;

namespace {
struct Item {
  std::uint16_t type, size, version;
};

/** A LASzip VLR payload: compressor, coder 0, LASzip 3.4.3, chunk size, items. */
std::vector<std::uint8_t>
makeVlr (std::uint16_t compressor,
         std::uint32_t chunk_size,
         const std::vector<Item>& items)
{
  std::vector<std::uint8_t> v;
  const auto put16 = [&] (std::uint32_t x) {
    v.push_back (static_cast<std::uint8_t> (x));
    v.push_back (static_cast<std::uint8_t> (x >> 8));
  };
  const auto put32 = [&] (std::uint32_t x) {
    put16 (x & 0xFFFF);
    put16 (x >> 16);
  };
  put16 (compressor);
  put16 (0);
  v.push_back (3);
  v.push_back (4);
  put16 (3);
  put32 (0);
  put32 (chunk_size);
  for (int i = 0; i < 4; ++i) // number of special EVLRs and their offset: -1
    put32 (0xFFFFFFFFu);
  put16 (static_cast<std::uint32_t> (items.size()));
  for (const auto& item : items) {
    put16 (item.type);
    put16 (item.size);
    put16 (item.version);
  }
  return v;
}

const std::vector<Item> format3 = {{6, 20, 2}, {7, 8, 2}, {8, 6, 2}};
const std::vector<Item> format7 = {{10, 30, 3}, {11, 6, 3}};

/** Expects parseLaszipVlr to refuse with a message containing \a fragment. */
void
expectRefused (const std::vector<std::uint8_t>& payload,
               int format,
               std::size_t record_length,
               const std::string& fragment)
{
  try {
    parseLaszipVlr (payload, format, record_length);
    ADD_FAILURE() << "accepted; expected '" << fragment << "'";
  }
  catch (const LazDataError& e) {
    EXPECT_NE (std::string (e.what()).find (fragment), std::string::npos) << e.what();
  }
}
} // namespace

TEST (LaszipVlr, PointwiseFormat3)
{
  const LaszipVlr vlr = parseLaszipVlr (makeVlr (2, 50000, format3), 3, 34);
  EXPECT_EQ (vlr.compressor, 2);
  EXPECT_EQ (vlr.version_major, 3);
  EXPECT_EQ (vlr.chunk_size, 50000u);
  EXPECT_FALSE (vlr.variableChunks());
  ASSERT_EQ (vlr.items.size(), 3u);
  EXPECT_EQ (vlr.items[1].type, 7);
  EXPECT_EQ (vlr.items[2].size, 6);
  EXPECT_EQ (vlr.recordLength(), 34u);
}

TEST (LaszipVlr, LayeredFormat7WithExtraBytes)
{
  std::vector<Item> items = format7;
  items.push_back ({14, 3, 3});
  const LaszipVlr vlr = parseLaszipVlr (makeVlr (3, 0xFFFFFFFFu, items), 7, 39);
  EXPECT_TRUE (vlr.variableChunks());
  EXPECT_EQ (vlr.recordLength(), 39u);
}

TEST (LaszipVlr, MalformedPayloads)
{
  std::vector<std::uint8_t> v = makeVlr (2, 50000, format3);
  v.pop_back();
  expectRefused (v, 3, 34, "not 34 + 6 per item");
  v = makeVlr (2, 50000, format3);
  v[32] = 2; // announces 2 items, holds 3
  expectRefused (v, 3, 34, "announces 2 items");
  expectRefused (makeVlr (2, 50000, {}), 3, 34, "announces 0 items");
}

TEST (LaszipVlr, UnsupportedCompressorsAndCoders)
{
  expectRefused (makeVlr (0, 50000, format3), 3, 34, "not compressed");
  expectRefused (makeVlr (1, 50000, format3), 3, 34, "compressor 1");
  expectRefused (makeVlr (7, 50000, format3), 3, 34, "unknown LASzip compressor 7");
  std::vector<std::uint8_t> v = makeVlr (2, 50000, format3);
  v[2] = 1;
  expectRefused (v, 3, 34, "unknown LASzip coder 1");
  expectRefused (makeVlr (2, 50000, format7), 7, 36, "layered chunked compressor");
  expectRefused (makeVlr (3, 50000, format3), 3, 34, "pointwise chunked compressor");
}

TEST (LaszipVlr, ItemsMustBeThoseOfThePointFormat)
{
  expectRefused (makeVlr (2, 50000, {{6, 20, 2}, {99, 8, 2}}),
                 1,
                 28,
                 "unknown LASzip item type 99");
  expectRefused (
      makeVlr (2, 50000, {{6, 20, 2}, {8, 6, 2}}), 1, 26, "expects GPSTIME11");
  expectRefused (makeVlr (2, 50000, {{6, 20, 2}}), 1, 20, "needs at least 2");
  expectRefused (makeVlr (2, 50000, {{6, 21, 2}}), 0, 21, "expected 20");
  expectRefused (makeVlr (2, 50000, {{6, 20, 1}}), 0, 20, "version 1 is not supported");
  expectRefused (makeVlr (2, 50000, {{6, 20, 2}}), 0, 22, "record length is 22");
  expectRefused (
      makeVlr (2, 50000, {{6, 20, 2}, {6, 20, 2}}), 0, 40, "unexpected POINT10");
  expectRefused (
      makeVlr (2, 50000, {{6, 20, 2}, {7, 8, 2}, {9, 29, 1}}), 4, 57, "wave packets");
  expectRefused (
      makeVlr (3, 0xFFFFFFFFu, {{10, 30, 3}, {13, 29, 3}}), 9, 59, "wave packets");
  expectRefused (makeVlr (2, 50000, format3), 11, 34, "not a LAS point format");
}

TEST (LazChunkTable, FixedChunksOfSimpleLaz)
{
  // simple.laz: one chunk; its table (at 18203) follows the chunk, which starts after
  // the 8-byte table offset at the point data offset 333: 18203 - 341 = 17862 bytes.
  const std::vector<std::uint8_t> body = {0x78, 0x96, 0x05, 0x00, 0x00, 0x00};
  const std::vector<LazChunk> chunks =
      decodeLazChunkTable (body.data(), body.size(), 1, false);
  ASSERT_EQ (chunks.size(), 1u);
  EXPECT_EQ (chunks[0].byte_count, 17862u);
  EXPECT_EQ (chunks[0].point_count, 0u);
}

TEST (LazChunkTable, VariableChunksOfLoneStarCopc)
{
  // lone-star.copc.laz: 15 chunks of 518,862 points in all, filling the bytes from
  // 1268 (point data offset 1260 + 8) to the table at 2,704,562.
  const std::vector<std::uint8_t> body = {
      0x44, 0x75, 0x1d, 0x7f, 0x75, 0x24, 0x05, 0x45, 0x84, 0x02, 0x7b, 0x1e,
      0xef, 0x6e, 0xb5, 0x71, 0xa9, 0xb3, 0x24, 0x6b, 0x8b, 0xeb, 0x8e, 0x78,
      0x15, 0xde, 0x52, 0x8f, 0xc3, 0x49, 0xbf, 0xd3, 0x96, 0xd4, 0xf3, 0x57,
      0x7a, 0xe1, 0x40, 0x13, 0x4c, 0x29, 0xe4, 0x26, 0xae, 0x74, 0x1c, 0xc7,
      0x9d, 0x1d, 0x8f, 0x43, 0xe2, 0xd6, 0x9c, 0xcb, 0x1b, 0xec, 0x96, 0x3f,
      0x9a, 0xeb, 0xce, 0x65, 0xca, 0x03, 0x1e, 0x6b, 0xd3, 0x90, 0x10, 0x6b,
      0xd4, 0xd3, 0x59, 0xfb, 0xf0, 0x6f, 0x82, 0x53, 0x00, 0x00, 0x00};
  const std::vector<LazChunk> chunks =
      decodeLazChunkTable (body.data(), body.size(), 15, true);
  ASSERT_EQ (chunks.size(), 15u);
  std::uint64_t points = 0, bytes = 0;
  for (const auto& c : chunks) {
    EXPECT_GT (c.point_count, 0u);
    EXPECT_GT (c.byte_count, 0u);
    points += c.point_count;
    bytes += c.byte_count;
  }
  EXPECT_EQ (points, 518862u);
  EXPECT_EQ (bytes, 2704562u - 1268u);
}

TEST (LazChunkTable, TruncatedOrEmptyEntries)
{
  const std::vector<std::uint8_t> body = {0x78, 0x96, 0x05};
  EXPECT_THROW (decodeLazChunkTable (body.data(), body.size(), 1, false), LazDataError);
  // All zeros: every entry repeats the prediction 0, a chunk of no byte.
  const std::vector<std::uint8_t> zeros (16, 0);
  EXPECT_THROW (decodeLazChunkTable (zeros.data(), zeros.size(), 1, false),
                LazDataError);
  // More entries than the bytes can hold end in an error, not a read past them.
  const std::vector<std::uint8_t> simple = {0x78, 0x96, 0x05, 0x00, 0x00, 0x00};
  EXPECT_THROW (decodeLazChunkTable (simple.data(), simple.size(), 1000, false),
                LazDataError);
  EXPECT_TRUE (decodeLazChunkTable (simple.data(), simple.size(), 0, false).empty());
}
