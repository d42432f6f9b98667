/*
 * pcl_ext: whole reads and writes at an offset of an open file.
 */
#include <pcl_ext/tiling/positioned_io.h>

#include <cerrno>
#include <sys/types.h>
#include <unistd.h>

namespace pcl_ext {
namespace tiling {
bool
writeAllAt (int fd, const void* bytes, std::size_t size, std::uint64_t offset)
{
  const auto* p = static_cast<const char*> (bytes);
  while (size > 0) {
    const ssize_t w = ::pwrite (fd, p, size, static_cast<off_t> (offset));
    if (w <= 0) {
      if (w < 0 && errno == EINTR)
        continue;
      return false;
    }
    p += w;
    size -= static_cast<std::size_t> (w);
    offset += static_cast<std::uint64_t> (w);
  }
  return true;
}

bool
readAllAt (int fd, void* bytes, std::size_t size, std::uint64_t offset)
{
  auto* p = static_cast<char*> (bytes);
  while (size > 0) {
    const ssize_t r = ::pread (fd, p, size, static_cast<off_t> (offset));
    if (r <= 0) {
      if (r < 0 && errno == EINTR)
        continue;
      return false;
    }
    p += r;
    size -= static_cast<std::size_t> (r);
    offset += static_cast<std::uint64_t> (r);
  }
  return true;
}
} // namespace tiling
} // namespace pcl_ext
