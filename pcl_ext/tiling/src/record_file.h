/*
 * pcl_ext: reading a work file of fixed-size binary records (inside pcl_ext::tiling
 * only).
 */
#pragma once

#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace pcl_ext {
namespace tiling {
namespace detail {
/** What readRecordFile found. */
enum class RecordFileRead { Done, CannotOpen, NotWholeRecords, CannotRead };

/** The bytes of the file at \a path, which must hold a whole number of records of
 * \a record_bytes bytes each; \a data is left empty unless Done. */
inline RecordFileRead
readRecordFile (const std::string& path,
                std::size_t record_bytes,
                std::vector<char>& data)
{
  data.clear();
  std::ifstream in (path, std::ios::binary | std::ios::ate);
  if (!in)
    return RecordFileRead::CannotOpen;
  const std::streamoff bytes = in.tellg();
  if (bytes < 0 || bytes % static_cast<std::streamoff> (record_bytes) != 0)
    return RecordFileRead::NotWholeRecords;
  in.seekg (0);
  data.resize (static_cast<std::size_t> (bytes));
  in.read (data.data(), bytes);
  if (!in) {
    data.clear();
    return RecordFileRead::CannotRead;
  }
  return RecordFileRead::Done;
}
} // namespace detail
} // namespace tiling
} // namespace pcl_ext
