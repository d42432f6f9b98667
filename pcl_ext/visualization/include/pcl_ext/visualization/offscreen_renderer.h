/*
 * pcl_ext: headless rendering of coloured clouds to PNG.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstdint>

#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief One coloured cloud drawn in a view; later layers are drawn over earlier ones.
 */
struct Layer {
  pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr cloud;
  double point_size = 2.0; ///< in pixels
};

/** \brief One panel of the image: a title and its layers. */
struct View {
  /** Written at the panel's top left, one line per '\n', in a font small enough for the
   * longest line to fit the panel's width. */
  std::string title;
  std::vector<Layer> layers;
};

/** \brief Image and camera settings. All panels share one camera so results compare. */
struct RenderOptions {
  int width = 1280; ///< whole image, pixels
  int height = 720; ///< whole image, pixels
  int columns = 0;  ///< panels per row; 0: as square a grid as fits
  /** Direction the camera looks along (towards the scene), default from above and the
   * side. */
  Eigen::Vector3d view_direction = Eigen::Vector3d (-1.0, -1.4, -1.1);
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  /** Distance as a multiple of the scene's bounding-sphere radius. */
  double zoom_out = 2.3;
  std::uint8_t background[3] = {255, 255, 255};
};

/** \brief Render views side by side into a PNG file, offscreen.
 *
 * Uses PCL's visualizer without an interactor and VTK's offscreen rendering. VTK on
 * Debian is built for X only, so an X display is needed (on a headless machine run
 * under Xvfb, e.g. `xvfb-run -a`); without DISPLAY the function reports an error
 * instead of letting VTK abort. The file is written atomically (a temporary file
 * renamed into place). \return false with a message on stderr when there is nothing to
 * draw, no display, bad options or the file cannot be written
 */
bool
renderToPng (const std::vector<View>& views,
             const std::string& path,
             const RenderOptions& options = RenderOptions());

/** \brief Whether an X display is available for rendering. */
bool
displayAvailable ();
} // namespace visualization
} // namespace pcl_ext
