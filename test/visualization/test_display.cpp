/*
 * Test of the display check against an X server that resets when its last client
 * leaves (Xvfb's default): renders one after another must all succeed. Starts an Xvfb
 * of its own; skipped where Xvfb is not installed.
 */
#include "render_test_helpers.h"

#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {
/** An Xvfb server on a free display (it picks the number, -displayfd), stopped at the
 * end of the scope. Without -noreset: it resets whenever its last client disconnects
 * and refuses connections while it does. */
class ResettingServer {
public:
  ResettingServer()
  {
    int fds[2];
    if (::pipe (fds) != 0)
      return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close (fds[0]);
      const std::string fd = std::to_string (fds[1]);
      // Its output is not the test's, and it must not hold the test's output open
      // (ctest waits for it) nor outlive the test should the test abort.
      const int null = ::open ("/dev/null", O_WRONLY);
      ::dup2 (null, STDOUT_FILENO);
      ::dup2 (null, STDERR_FILENO);
      ::prctl (PR_SET_PDEATHSIG, SIGTERM);
      ::execlp ("Xvfb",
                "Xvfb",
                "-displayfd",
                fd.c_str(),
                "-screen",
                "0",
                "1600x1200x24",
                "-nolisten",
                "tcp",
                static_cast<char*> (nullptr));
      ::_exit (127);
    }
    ::close (fds[1]);
    if (pid_ < 0) {
      ::close (fds[0]);
      return;
    }
    // Xvfb writes the display's number once it accepts connections.
    char buffer[16] = {};
    std::size_t used = 0;
    ssize_t got;
    while (used + 1 < sizeof (buffer) &&
           (got = ::read (fds[0], buffer + used, sizeof (buffer) - 1 - used)) > 0)
      used += static_cast<std::size_t> (got);
    ::close (fds[0]);
    const int number = std::atoi (buffer);
    if (used > 0 && buffer[0] >= '0' && buffer[0] <= '9')
      display_ = ":" + std::to_string (number);
  }
  ~ResettingServer()
  {
    if (pid_ > 0) {
      ::kill (pid_, SIGTERM);
      ::waitpid (pid_, nullptr, 0);
    }
  }
  const std::string&
  display () const
  {
    return display_;
  }

private:
  pid_t pid_ = -1;
  std::string display_;
};

bool
xvfbInstalled ()
{
  const char* path = std::getenv ("PATH");
  std::string paths = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= paths.size()) {
    const std::size_t end = std::min (paths.find (':', start), paths.size());
    if (::access ((paths.substr (start, end - start) + "/Xvfb").c_str(), X_OK) == 0)
      return true;
    start = end + 1;
  }
  return false;
}
} // namespace

// Each render used to open the display, close it and let VTK open its own: the server,
// left without clients, reset between the two and VTK aborted the process. The reset
// takes well under a millisecond on an idle machine and longer on a busy one (as under
// ctest -j): the renders run here beside busy threads, which made every run of this
// test abort before the check's connection stayed open.
TEST (DisplayCheck, RendersOneAfterAnotherOnAServerThatResetsWhenIdle)
{
  if (!xvfbInstalled())
    GTEST_SKIP() << "Xvfb is not installed";
  using namespace pcl_ext::visualization;
  ResettingServer server;
  ASSERT_FALSE (server.display().empty()) << "Xvfb did not start";
  const char* before = std::getenv ("DISPLAY");
  const std::string saved = before ? before : "";
  setenv ("DISPLAY", server.display().c_str(), 1);

  const auto cloud = sphereCloud (500);
  const View view{"sphere",
                  {{makeColouredCloud (
                        cloud, std::vector<Colour> (cloud.size(), Colour{200, 40, 40})),
                    2.0}}};
  RenderOptions options;
  options.width = 64;
  options.height = 64;
  const std::string path = temporaryPng ("resetting_server");
  std::atomic<bool> busy{true};
  std::vector<std::thread> load;
  for (unsigned t = 0; t < 2 * std::max (1u, std::thread::hardware_concurrency()); ++t)
    load.emplace_back ([&busy] {
      volatile unsigned long spin = 0;
      while (busy.load (std::memory_order_relaxed))
        ++spin;
    });
  int written = 0;
  for (int i = 0; i < 30; ++i) {
    std::remove (path.c_str());
    if (renderToPng ({view}, path, options) && std::ifstream (path).good())
      ++written;
  }
  busy = false;
  for (auto& thread : load)
    thread.join();
  std::remove (path.c_str());
  if (before)
    setenv ("DISPLAY", saved.c_str(), 1);
  else
    unsetenv ("DISPLAY");
  EXPECT_EQ (written, 30);
}
