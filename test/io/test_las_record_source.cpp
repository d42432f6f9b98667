/*
 * LasRecordSource, the interface the LAS reader reads its records through: readRecords
 * gives the records in order whatever the block size, fewer than asked only at the
 * end, and nothing after it. Checked on the LAZ decoder (laz_chunk_bytes.h); the
 * uncompressed file's source is the reader's own and is checked by test_las_reader.cpp.
 */
#include <pcl_ext/io/las_record_source.h>
#include <pcl_ext/io/laz_record_source.h>

#include "laz_chunk_bytes.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {
using namespace laz_chunk;

constexpr std::size_t kRecordLength = 34; // point format 3

class LasRecordSourceTest : public testing::Test {
protected:
  void
  SetUp () override
  {
    path_ = dir_ + "/two_points.laz";
    const std::vector<std::uint8_t> bytes = lazBytes (table_offset);
    std::ofstream out (path_, std::ios::binary);
    out.write (reinterpret_cast<const char*> (bytes.data()),
               static_cast<std::streamsize> (bytes.size()));
  }

  std::unique_ptr<pcl_ext::io::LasRecordSource>
  source (std::uint64_t count) const
  {
    return pcl_ext::io::makeLazRecordSource (
        path_, point_data_offset, 3, kRecordLength, count, vlr (2, 50000, 3));
  }

  std::string dir_ = freshFolder ("las_record_source");
  std::string path_;
};

TEST_F (LasRecordSourceTest, RecordsInOrderForAnyBlockSize)
{
  std::vector<std::uint8_t> expected = firstRecord();
  const std::vector<std::uint8_t> second = secondRecord();
  expected.insert (expected.end(), second.begin(), second.end());
  for (const std::size_t block : {1u, 2u, 3u, 100u}) {
    SCOPED_TRACE (block);
    const auto records = source (2);
    std::vector<std::uint8_t> buffer (block * kRecordLength);
    std::vector<std::uint8_t> all;
    std::vector<std::size_t> counts;
    while (const std::size_t n = records->readRecords (block, buffer.data())) {
      counts.push_back (n);
      all.insert (all.end(), buffer.begin(), buffer.begin() + n * kRecordLength);
    }
    EXPECT_EQ (all, expected);
    // Fewer than asked only in the last call.
    for (std::size_t i = 0; i + 1 < counts.size(); ++i)
      EXPECT_EQ (counts[i], block);
  }
}

TEST_F (LasRecordSourceTest, NothingAfterTheEnd)
{
  const auto records = source (1);
  std::vector<std::uint8_t> buffer (4 * kRecordLength);
  EXPECT_EQ (records->readRecords (4, buffer.data()), 1u);
  EXPECT_EQ (std::vector<std::uint8_t> (buffer.begin(), buffer.begin() + kRecordLength),
             firstRecord());
  EXPECT_EQ (records->readRecords (4, buffer.data()), 0u);
  EXPECT_EQ (records->readRecords (1, buffer.data()), 0u);
  EXPECT_EQ (source (0)->readRecords (4, buffer.data()), 0u);
}
} // namespace
