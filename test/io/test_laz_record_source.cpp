/*
 * Tests of makeLazRecordSource on small LAZ point data written by the test: one chunk
 * (a raw record and zero bytes, whose second point follows from the item definitions,
 * see test_laz_chunk_decoder.cpp) with the chunk table of simple.laz, which gives that
 * chunk 17,862 bytes; then the same data with the table missing, misplaced or lying,
 * the file truncated, and a VLR that is refused.
 */
#include <pcl_ext/io/laz_record_source.h>

#include "temp_folder.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <vector>

using pcl_ext::io::makeLazRecordSource;

namespace {
constexpr std::uint64_t point_data_offset = 100;
constexpr std::size_t chunk_bytes = 17862; // what simple.laz's chunk table encodes

void
put (std::vector<std::uint8_t>& v, std::uint64_t x, int bytes)
{
  for (int i = 0; i < bytes; ++i)
    v.push_back (static_cast<std::uint8_t> (x >> (8 * i)));
}

std::vector<std::uint8_t>
vlr (std::uint16_t compressor, std::uint32_t chunk_size, int point_format)
{
  std::vector<std::uint8_t> v;
  put (v, compressor, 2);
  put (v, 0, 2);
  put (v, 0x0003'0403, 4); // LASzip 3.4 revision 3
  put (v, 0, 4);
  put (v, chunk_size, 4);
  put (v, ~std::uint64_t (0), 8);
  put (v, ~std::uint64_t (0), 8);
  if (point_format == 3) {
    put (v, 3, 2);
    for (const std::uint16_t item : {6, 20, 2, 7, 8, 2, 8, 6, 2})
      put (v, item, 2);
  }
  else {
    put (v, 1, 2);
    for (const std::uint16_t item : {10, 30, 3})
      put (v, item, 2);
  }
  return v;
}

std::vector<std::uint8_t>
firstRecord ()
{
  std::vector<std::uint8_t> r (34, 0);
  const std::int32_t xyz[3] = {1000, -2000, 300};
  std::memcpy (r.data(), xyz, 12);
  r[12] = 0x2B; // intensity 555
  r[13] = 0x02;
  r[14] = 1 | (2 << 3);
  r[15] = 2;
  const double gps = 1234.5;
  std::memcpy (r.data() + 20, &gps, 8);
  const std::uint16_t rgb[3] = {0x0102, 0x0304, 0x0506};
  std::memcpy (r.data() + 28, rgb, 6);
  return r;
}

/** The second point a zero stream decodes: z 0, intensity 0, green = blue = red. */
std::vector<std::uint8_t>
secondRecord ()
{
  std::vector<std::uint8_t> r = firstRecord();
  std::memset (r.data() + 8, 0, 6);
  r[30] = r[32] = 0x02;
  r[31] = r[33] = 0x01;
  return r;
}

/** File bytes: filler up to the point data, the table offset, the chunk, the table. */
std::vector<std::uint8_t>
lazBytes (std::int64_t table_offset_field)
{
  std::vector<std::uint8_t> f (point_data_offset, 0);
  put (f, static_cast<std::uint64_t> (table_offset_field), 8);
  const std::vector<std::uint8_t> record = firstRecord();
  f.insert (f.end(), record.begin(), record.end());
  f.resize (point_data_offset + 8 + chunk_bytes, 0);
  put (f, 0, 4); // chunk table version
  put (f, 1, 4); // one chunk
  for (const std::uint8_t b : {0x78, 0x96, 0x05, 0x00, 0x00, 0x00})
    f.push_back (b);
  return f;
}

constexpr std::int64_t table_offset = point_data_offset + 8 + chunk_bytes;

class LazRecordSourceTest : public testing::Test {
protected:
  std::string
  write (const std::string& name, const std::vector<std::uint8_t>& bytes)
  {
    const std::string path = dir_ + "/" + name;
    std::ofstream out (path, std::ios::binary);
    out.write (reinterpret_cast<const char*> (bytes.data()),
               static_cast<std::streamsize> (bytes.size()));
    return path;
  }

  /** Decodes \a count points of format 3 from \a path, 10 at a time. */
  std::vector<std::uint8_t>
  decode (const std::string& path, std::uint64_t count)
  {
    auto source =
        makeLazRecordSource (path, point_data_offset, 3, 34, count, vlr (2, 50000, 3));
    std::vector<std::uint8_t> records (10 * 34);
    std::vector<std::uint8_t> all;
    while (const std::size_t n = source->readRecords (10, records.data()))
      all.insert (all.end(), records.begin(), records.begin() + n * 34);
    return all;
  }

  std::vector<std::uint8_t>
  expectedTwo () const
  {
    std::vector<std::uint8_t> two = firstRecord();
    const std::vector<std::uint8_t> second = secondRecord();
    two.insert (two.end(), second.begin(), second.end());
    return two;
  }

  std::string dir_ = freshFolder ("laz_record_source");
};
} // namespace

TEST_F (LazRecordSourceTest, DecodesThroughTheChunkTable)
{
  const std::string path = write ("table.laz", lazBytes (table_offset));
  EXPECT_EQ (decode (path, 2), expectedTwo());
  EXPECT_EQ (decode (path, 1), firstRecord());
  EXPECT_TRUE (decode (path, 0).empty());
}

TEST_F (LazRecordSourceTest, DecodesWithoutChunkTable)
{
  // The writer stopped before the table: the offset still points at itself.
  std::vector<std::uint8_t> bytes = lazBytes (point_data_offset);
  bytes.resize (table_offset);
  EXPECT_EQ (decode (write ("no_table.laz", bytes), 2), expectedTwo());
}

TEST_F (LazRecordSourceTest, TableOffsetAtTheEndOfAStream)
{
  // -1: the table offset is the file's last 8 bytes.
  std::vector<std::uint8_t> bytes = lazBytes (-1);
  put (bytes, table_offset, 8);
  EXPECT_EQ (decode (write ("streamed.laz", bytes), 2), expectedTwo());
}

TEST_F (LazRecordSourceTest, TableOffsetPastTheEnd)
{
  const std::string path = write ("past.laz", lazBytes (table_offset + 1000));
  expectReadError ([&] { decode (path, 2); }, path, 0, "points outside the point data");
}

TEST_F (LazRecordSourceTest, TruncatedFiles)
{
  std::vector<std::uint8_t> bytes = lazBytes (table_offset);
  bytes.resize (table_offset + 10); // the table's entries cut
  const std::string cut_table = write ("cut_table.laz", bytes);
  expectReadError ([&] { decode (cut_table, 2); }, cut_table, 0, "chunk table");
  bytes.resize (table_offset - 100); // the chunk cut, the table lost
  const std::string cut_chunk = write ("cut_chunk.laz", bytes);
  expectReadError ([&] { decode (cut_chunk, 2); }, cut_chunk, 0, "points outside");
  bytes.resize (point_data_offset + 4); // not even the table offset
  const std::string cut_offset = write ("cut_offset.laz", bytes);
  expectReadError (
      [&] { decode (cut_offset, 2); }, cut_offset, 0, "past the end of the file");
}

TEST_F (LazRecordSourceTest, MorePointsThanTheChunksHold)
{
  const std::string path = write ("count.laz", lazBytes (table_offset));
  expectReadError ([&] { decode (path, 50001); }, path, 0, "more than the 50000");
}

TEST_F (LazRecordSourceTest, LyingChunkTable)
{
  std::vector<std::uint8_t> bytes = lazBytes (table_offset);
  bytes[table_offset + 4] = bytes[table_offset + 5] = bytes[table_offset + 6] =
      bytes[table_offset + 7] = 0xFF; // 4 billion chunks
  const std::string many = write ("many_chunks.laz", bytes);
  expectReadError ([&] { decode (many, 2); }, many, 0, "cannot hold them");
  bytes = lazBytes (table_offset);
  bytes[table_offset] = 1;
  const std::string version = write ("version.laz", bytes);
  expectReadError ([&] { decode (version, 2); }, version, 0, "chunk table version 1");
  // The table says 17,862 bytes; a file with a shorter chunk puts it past the data.
  bytes = lazBytes (table_offset);
  bytes.erase (bytes.begin() + point_data_offset + 8,
               bytes.begin() + point_data_offset + 108);
  put (bytes, 0, 0);
  std::vector<std::uint8_t> shifted = bytes;
  const std::uint64_t new_table = table_offset - 100;
  for (int i = 0; i < 8; ++i)
    shifted[point_data_offset + i] = static_cast<std::uint8_t> (new_table >> (8 * i));
  const std::string short_chunk = write ("short_chunk.laz", shifted);
  expectReadError (
      [&] { decode (short_chunk, 2); }, short_chunk, 0, "end past the point data");
}

TEST_F (LazRecordSourceTest, RefusedVlr)
{
  const std::string path = write ("vlr.laz", lazBytes (table_offset));
  expectReadError (
      [&] {
        makeLazRecordSource (path, point_data_offset, 3, 34, 2, vlr (1, 50000, 3));
      },
      path,
      0,
      "LASzip VLR: pointwise compression without chunks");
  expectReadError (
      [&] {
        makeLazRecordSource (path, point_data_offset, 3, 34, 2, {1, 2, 3});
      },
      path,
      0,
      "LASzip VLR");
}

TEST_F (LazRecordSourceTest, VariableChunksNeedTheTable)
{
  std::vector<std::uint8_t> bytes = lazBytes (point_data_offset);
  const std::string path = write ("variable.laz", bytes);
  expectReadError (
      [&] {
        makeLazRecordSource (
            path, point_data_offset, 6, 30, 2, vlr (3, 0xFFFFFFFFu, 6));
      },
      path,
      0,
      "chunk table is missing");
}

TEST_F (LazRecordSourceTest, MissingFile)
{
  const std::string path = dir_ + "/absent.laz";
  expectReadError ([&] { decode (path, 2); }, path, 0, "cannot open");
}
