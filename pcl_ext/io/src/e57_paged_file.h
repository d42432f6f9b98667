/*
 * pcl_ext: the physical layer of an E57 file (private header): checksummed pages, the
 * logical byte stream they carry and the file header.
 */
#pragma once

#include <pcl_ext/io/e57_format.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace pcl_ext {
namespace io {
namespace detail {
/** The file header (ASTM E2807 section 9.4), the first 48 bytes of the file. */
struct E57Header {
  std::uint32_t major_version = 0;
  std::uint32_t minor_version = 0;
  std::uint64_t physical_length = 0;
  std::uint64_t xml_physical_offset = 0;
  std::uint64_t xml_logical_length = 0;
  std::uint64_t page_size = 0;
};

/** Reads the logical bytes of an E57 file page by page, checking the CRC-32C of every
 * page it loads (one page is cached). All offsets given to it are logical. */
class E57PagedFile {
public:
  /** Opens \a path and reads and checks its header: signature "ASTM-E57", major
   * version 1, page size 1024, a physical length equal to the file's size (a multiple
   * of the page size) and an XML section inside the file. Throws ReadError. */
  explicit E57PagedFile (const std::string& path);

  const E57Header&
  header () const
  {
    return header_;
  }

  /** Logical bytes in the file. */
  std::uint64_t
  logicalSize () const
  {
    return logical_size_;
  }

  /** Copies \a size logical bytes from logical offset \a offset; throws ReadError when
   * they are not all inside the file or a page's checksum is wrong. */
  void
  read (std::uint64_t offset, std::uint8_t* out, std::size_t size);

  /** The XML section's text. */
  std::string
  readXml ();

  [[noreturn]] void
  fail (const std::string& message) const;

  const std::string&
  path () const
  {
    return path_;
  }

private:
  void
  loadPage (std::uint64_t page);

  std::string path_;
  std::unique_ptr<std::FILE, int (*) (std::FILE*)> file_;
  E57Header header_;
  std::uint64_t logical_size_ = 0;
  std::uint64_t cached_page_ = UINT64_MAX;
  std::uint8_t page_[kE57PageSize] = {};
};

/** Little-endian integers of the E57 binary structures. */
inline std::uint64_t
readLE (const std::uint8_t* p, int bytes)
{
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i)
    v = (v << 8) | p[i];
  return v;
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
