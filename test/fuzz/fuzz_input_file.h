/*
 * pcl_ext fuzzing: the readers take a path, so each input is handed to them as a file.
 */
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace pcl_ext_fuzz {
/** One anonymous in-memory file (memfd), rewritten for every input and read back
 * through /proc/self/fd/N: no disk traffic, nothing left behind. */
class InputFile {
public:
  InputFile()
  {
    fd_ = ::memfd_create ("pcl_ext_fuzz_input", 0);
    if (fd_ < 0) {
      std::perror ("memfd_create");
      std::abort();
    }
    path_ = "/proc/self/fd/" + std::to_string (fd_);
  }

  /** Replaces the file's content by \a size bytes at \a data; returns its path. */
  const std::string&
  write (const std::uint8_t* data, std::size_t size)
  {
    if (::ftruncate (fd_, 0) != 0)
      std::abort();
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n =
          ::pwrite (fd_, data + done, size - done, static_cast<off_t> (done));
      if (n <= 0)
        std::abort();
      done += static_cast<std::size_t> (n);
    }
    return path_;
  }

private:
  int fd_ = -1;
  std::string path_;
};

/** Stops the fuzzer with a message when a documented guarantee of a reader does not
 * hold. */
inline void
check (bool condition, const char* what)
{
  if (!condition) {
    std::fprintf (stderr, "pcl_ext fuzz: guarantee violated: %s\n", what);
    std::abort();
  }
}
} // namespace pcl_ext_fuzz
