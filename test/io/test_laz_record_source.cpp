/*
 * Tests of makeLazRecordSource on small LAZ point data written by the test (one chunk,
 * laz_chunk_bytes.h); then the same data with the table missing, misplaced or lying,
 * the file truncated, and a VLR that is refused.
 */
#include <pcl_ext/io/laz_record_source.h>

#include "laz_chunk_bytes.h"
#include "temp_folder.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <vector>

using pcl_ext::io::makeLazRecordSource;

namespace {
using namespace laz_chunk;

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
