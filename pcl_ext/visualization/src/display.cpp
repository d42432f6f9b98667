/*
 * pcl_ext: whether an X display can be opened for rendering. Apart from the renderer:
 * Xlib's macros (None, Status, Bool) clash with other headers.
 */
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include <X11/Xlib.h>

namespace pcl_ext {
namespace visualization {
bool
displayAvailable ()
{
  const char* name = std::getenv ("DISPLAY");
  if (!name || !*name)
    return false;
  // An X server resets when its last client leaves (unless started with -noreset, which
  // Xvfb is not by default) and refuses connections while it does. A connection opened
  // here and closed again would leave the server without clients just before VTK opens
  // its own, which then fails, and VTK aborts the process. The connection therefore
  // stays open for the life of the process (one per display name): while it is open the
  // server does not reset under VTK's connection. A server that is resetting because
  // another process has just left it refuses for a moment: a few attempts.
  static std::mutex mutex;
  static std::map<std::string, Display*> connections;
  std::lock_guard<std::mutex> lock (mutex);
  if (connections.count (name))
    return true;
  for (int attempt = 0; attempt < 5; ++attempt) {
    if (Display* display = XOpenDisplay (name)) {
      connections[name] = display;
      return true;
    }
    std::this_thread::sleep_for (std::chrono::milliseconds (200));
  }
  return false;
}
} // namespace visualization
} // namespace pcl_ext
