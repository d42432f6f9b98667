/*
 * pcl_ext_compare_segmenters: running one method in a child process.
 */
#include "isolated_run.h"

#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <malloc.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pcl_ext {
namespace compare {
namespace {
/** The header the child writes before the result bytes. */
struct ChildReport {
  std::uint32_t ok;
  double seconds;
  std::uint64_t peak_bytes;
  std::uint64_t result_size;
};

/** A "Name:   1234 kB" line of /proc/self/status, in bytes; 0 when absent. */
std::size_t
statusBytes (const char* name)
{
  std::ifstream in ("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen (name);
  while (std::getline (in, line))
    if (line.compare (0, length, name) == 0 && line.size() > length &&
        line[length] == ':')
      return static_cast<std::size_t> (
                 std::strtoull (line.c_str() + length + 1, nullptr, 10)) *
             1024;
  return 0;
}

bool
writeAll (int fd, const char* data, std::size_t size)
{
  while (size > 0) {
    const ssize_t n = ::write (fd, data, size);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    data += n;
    size -= static_cast<std::size_t> (n);
  }
  return true;
}

/** The child's side: measure, run, report, and leave without running any destructor. */
[[noreturn]] void
runChild (int fd,
          const std::function<bool()>& work,
          const std::function<std::vector<char>()>& result)
{
  {
    std::ofstream clear ("/proc/self/clear_refs");
    clear << "5"; // reset VmHWM to the current VmRSS (Linux >= 4.0)
  }
  const std::size_t start_rss = statusBytes ("VmRSS");
  const auto t0 = std::chrono::steady_clock::now();
  bool ok = false;
  try {
    ok = work();
  }
  catch (const std::exception& e) {
    std::cerr << "Error: " << e.what() << "\n";
  }
  const auto t1 = std::chrono::steady_clock::now();
  const std::size_t peak = statusBytes ("VmHWM");
  std::vector<char> bytes;
  if (ok)
    bytes = result();
  ChildReport report;
  report.ok = ok ? 1 : 0;
  report.seconds = std::chrono::duration<double> (t1 - t0).count();
  report.peak_bytes = peak > start_rss ? peak - start_rss : 0;
  report.result_size = bytes.size();
  std::fflush (nullptr);
  const bool sent =
      writeAll (fd, reinterpret_cast<const char*> (&report), sizeof (report)) &&
      writeAll (fd, bytes.data(), bytes.size());
  ::close (fd);
  ::_exit (sent ? 0 : 3);
}
} // namespace

IsolatedRun
runIsolated (const std::function<bool()>& work,
             const std::function<std::vector<char>()>& result,
             double timeout_seconds)
{
  IsolatedRun run;
  int fds[2];
  if (::pipe (fds) != 0) {
    run.error = std::string ("cannot create a pipe: ") + std::strerror (errno);
    return run;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush (nullptr);
  ::malloc_trim (0);
  const pid_t pid = ::fork();
  if (pid < 0) {
    run.error = std::string ("cannot fork: ") + std::strerror (errno);
    ::close (fds[0]);
    ::close (fds[1]);
    return run;
  }
  if (pid == 0) {
    ::close (fds[0]);
    runChild (fds[1], work, result);
  }
  ::close (fds[1]);

  // Read everything the child sends until it closes the pipe (or the time is up).
  std::vector<char> bytes;
  char buffer[1 << 16];
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration<double> (timeout_seconds > 0.0 ? timeout_seconds : 0.0);
  bool timed_out = false;
  for (;;) {
    int wait_ms = -1;
    if (timeout_seconds > 0.0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds> (
                            deadline - std::chrono::steady_clock::now())
                            .count();
      if (left <= 0) {
        timed_out = true;
        break;
      }
      wait_ms = static_cast<int> (std::min<long long> (left, 1 << 30));
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll (&p, 1, wait_ms);
    if (ready < 0 && errno == EINTR)
      continue;
    if (ready == 0)
      continue; // the deadline is checked above
    const ssize_t n = ::read (fds[0], buffer, sizeof (buffer));
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      break;
    bytes.insert (bytes.end(), buffer, buffer + n);
  }
  ::close (fds[0]);
  if (timed_out)
    ::kill (pid, SIGKILL);
  int status = 0;
  while (::waitpid (pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    run.error = "timed out after " + std::to_string (timeout_seconds) + " s";
    return run;
  }
  if (WIFSIGNALED (status)) {
    run.error = std::string ("crashed (") + strsignal (WTERMSIG (status)) + ")";
    return run;
  }
  ChildReport report;
  if (bytes.size() < sizeof (report)) {
    run.error = "exited without a result";
    return run;
  }
  std::memcpy (&report, bytes.data(), sizeof (report));
  run.seconds = report.seconds;
  run.peak_bytes = static_cast<std::size_t> (report.peak_bytes);
  if (!report.ok) {
    run.error = "failed (see the messages above)";
    return run;
  }
  if (bytes.size() - sizeof (report) != report.result_size) {
    run.error = "sent an incomplete result";
    return run;
  }
  run.result.assign (bytes.begin() + sizeof (report), bytes.end());
  run.ok = true;
  return run;
}
} // namespace compare
} // namespace pcl_ext
