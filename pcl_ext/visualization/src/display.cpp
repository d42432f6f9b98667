/*
 * pcl_ext: whether an X display can be opened for rendering. Apart from the renderer:
 * Xlib's macros (None, Status, Bool) clash with other headers.
 */
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <chrono>
#include <cstdlib>
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
  // VTK aborts the process when it cannot open the display: open it here first, so
  // that a display that cannot be reached (a stale DISPLAY, a server that has gone)
  // gives an error instead. A busy server may refuse a connection for a moment: a few
  // attempts.
  for (int attempt = 0; attempt < 5; ++attempt) {
    if (Display* display = XOpenDisplay (name)) {
      XCloseDisplay (display);
      return true;
    }
    std::this_thread::sleep_for (std::chrono::milliseconds (200));
  }
  return false;
}
} // namespace visualization
} // namespace pcl_ext
