/*
 * pcl_ext: a LAS file opened for reading at given offsets, and the record source that
 * reads uncompressed point data from it in blocks.
 */
#pragma once

#include <pcl_ext/io/las_record_source.h>
#include <pcl_ext/io/read_error.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace pcl_ext {
namespace io {
namespace las {
/** A file read at offsets (pread); closed when destroyed. */
class File {
public:
  /** \throw ReadError when \a path cannot be opened or is not a regular file */
  explicit File (const std::string& path);
  ~File();
  File (const File&) = delete;
  File&
  operator= (const File&) = delete;

  std::uint64_t
  size () const
  {
    return size_;
  }

  const std::string&
  path () const
  {
    return path_;
  }

  /** Reads \a n bytes at \a offset into \a out. \throw ReadError naming \a what when
   * the file ends before */
  void
  readAt (std::uint64_t offset, std::size_t n, void* out, const char* what) const;

private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

/** The point records of an uncompressed file, read in blocks straight from it. */
class FileRecordSource : public LasRecordSource {
public:
  FileRecordSource (std::shared_ptr<const File> file,
                    std::uint64_t offset,
                    std::size_t record_length,
                    std::uint64_t count)
  : file_ (std::move (file))
  , offset_ (offset)
  , record_length_ (record_length)
  , remaining_ (count)
  {}

  std::size_t
  readRecords (std::size_t n, std::uint8_t* out) override
  {
    const std::size_t k = static_cast<std::size_t> (
        std::min<std::uint64_t> (static_cast<std::uint64_t> (n), remaining_));
    file_->readAt (offset_, k * record_length_, out, "point data");
    offset_ += static_cast<std::uint64_t> (k) * record_length_;
    remaining_ -= k;
    return k;
  }

private:
  std::shared_ptr<const File> file_;
  std::uint64_t offset_;
  std::size_t record_length_;
  std::uint64_t remaining_;
};
} // namespace las
} // namespace io
} // namespace pcl_ext
