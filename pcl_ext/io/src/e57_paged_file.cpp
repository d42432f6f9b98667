/*
 * pcl_ext: the physical layer of an E57 file: checksummed pages and the file header.
 */
#include "e57_paged_file.h"

#include <sys/stat.h>

#include <cstring>

namespace pcl_ext {
namespace io {
namespace detail {
namespace {
std::string
hex (std::uint32_t v)
{
  char text[11];
  std::snprintf (text, sizeof (text), "0x%08X", v);
  return text;
}
} // namespace

E57PagedFile::E57PagedFile (const std::string& path)
: path_ (path), file_ (nullptr, std::fclose)
{
  struct stat st;
  if (::stat (path.c_str(), &st) != 0)
    throw ReadError (path, 0, "no such file");
  if (S_ISDIR (st.st_mode))
    throw ReadError (path, 0, "is a folder, not a file");
  file_.reset (std::fopen (path.c_str(), "rb"));
  if (!file_)
    throw ReadError (path, 0, "cannot be opened for reading");
  if (::fseeko (file_.get(), 0, SEEK_END) != 0)
    fail ("cannot be read (no size)");
  const off_t size = ::ftello (file_.get());
  if (size < 0)
    fail ("cannot be read (no size)");
  const std::uint64_t physical = static_cast<std::uint64_t> (size);

  std::uint8_t head[48] = {};
  if (physical < sizeof (head) || ::fseeko (file_.get(), 0, SEEK_SET) != 0 ||
      std::fread (head, 1, sizeof (head), file_.get()) != sizeof (head))
    fail ("too short for an E57 header (48 bytes)");
  if (std::memcmp (head, "ASTM-E57", 8) != 0)
    fail ("not an E57 file (the signature is not ASTM-E57)");
  if (physical < kE57PageSize || physical % kE57PageSize != 0)
    fail ("its size (" + std::to_string (physical) +
          " bytes) is not a whole number of 1024-byte pages (truncated?)");
  logical_size_ = physical / kE57PageSize * kE57PagePayload;
  loadPage (0); // checks the header page's CRC
  header_.major_version = static_cast<std::uint32_t> (readLE (head + 8, 4));
  header_.minor_version = static_cast<std::uint32_t> (readLE (head + 12, 4));
  header_.physical_length = readLE (head + 16, 8);
  header_.xml_physical_offset = readLE (head + 24, 8);
  header_.xml_logical_length = readLE (head + 32, 8);
  header_.page_size = readLE (head + 40, 8);
  if (header_.major_version != 1)
    fail ("E57 version " + std::to_string (header_.major_version) + "." +
          std::to_string (header_.minor_version) + " is not supported (only 1.x)");
  if (header_.page_size != kE57PageSize)
    fail ("page size " + std::to_string (header_.page_size) + " instead of 1024");
  if (header_.physical_length != physical)
    fail ("the header declares " + std::to_string (header_.physical_length) +
          " bytes, the file has " + std::to_string (physical) + " (truncated?)");
  const std::uint64_t xml = header_.xml_physical_offset;
  if (xml >= physical || xml % kE57PageSize >= kE57PagePayload ||
      header_.xml_logical_length == 0 ||
      header_.xml_logical_length > logical_size_ - e57LogicalOffset (xml))
    fail ("the XML section (offset " + std::to_string (xml) + ", length " +
          std::to_string (header_.xml_logical_length) + ") is not inside the file");
}

void
E57PagedFile::fail (const std::string& message) const
{
  throw ReadError (path_, 0, message);
}

void
E57PagedFile::loadPage (std::uint64_t page)
{
  if (page == cached_page_)
    return;
  cached_page_ = UINT64_MAX;
  if (::fseeko (file_.get(), static_cast<off_t> (page * kE57PageSize), SEEK_SET) != 0 ||
      std::fread (page_, 1, kE57PageSize, file_.get()) != kE57PageSize)
    fail ("page " + std::to_string (page) + " cannot be read");
  const std::uint32_t stored = static_cast<std::uint32_t> (
      (std::uint32_t{page_[1020]} << 24) | (std::uint32_t{page_[1021]} << 16) |
      (std::uint32_t{page_[1022]} << 8) | page_[1023]);
  const std::uint32_t computed = crc32c (page_, kE57PagePayload);
  if (stored != computed)
    fail ("bad checksum on page " + std::to_string (page) + " (physical offset " +
          std::to_string (page * kE57PageSize) + "): stored " + hex (stored) +
          ", computed " + hex (computed));
  cached_page_ = page;
}

void
E57PagedFile::read (std::uint64_t offset, std::uint8_t* out, std::size_t size)
{
  if (offset > logical_size_ || size > logical_size_ - offset)
    fail ("a read of " + std::to_string (size) + " bytes at logical offset " +
          std::to_string (offset) + " goes past the end of the file");
  while (size > 0) {
    const std::uint64_t page = offset / kE57PagePayload;
    const std::size_t in_page = static_cast<std::size_t> (offset % kE57PagePayload);
    const std::size_t n = std::min<std::size_t> (
        size, static_cast<std::size_t> (kE57PagePayload) - in_page);
    loadPage (page);
    std::memcpy (out, page_ + in_page, n);
    out += n;
    offset += n;
    size -= n;
  }
}

std::string
E57PagedFile::readXml()
{
  std::string xml (static_cast<std::size_t> (header_.xml_logical_length), '\0');
  read (e57LogicalOffset (header_.xml_physical_offset),
        reinterpret_cast<std::uint8_t*> (&xml[0]),
        xml.size());
  return xml;
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
