/*
 * pcl_ext: headless rendering of coloured clouds to PNG.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/framing.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief One coloured cloud drawn in a view; later layers are drawn over earlier ones.
 */
struct Layer {
  pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr cloud;
  /** In pixels; 0 (the default): from the cloud's point spacing (estimateSpacing) and
   * the picture's scale, so that neighbouring points just touch (2 to 8 pixels). */
  double point_size = 0.0;
};

/** \brief A colour bar: which values a scalar colour map's colours stand for. No bar is
 * drawn while \a name is empty. */
struct ColourBar {
  std::string name;
  float min = 0.0f;
  float max = 1.0f;
  ColourMap map = ColourMap::Viridis;
};

/** \brief One panel of the image: a title, its layers, and a legend and a colour bar at
 * its right (each when not empty). */
struct View {
  /** Written at the panel's top left, one line per '\n', in a font small enough for the
   * longest line to fit the panel's width. */
  std::string title;
  std::vector<Layer> layers;
  std::vector<LegendEntry> legend;
  ColourBar colour_bar = {}; ///< none when its name is empty
};

/** \brief Image and camera settings. All panels share one camera so results compare.
 *
 * The camera is orthographic and framed on robust bounds (frameRobustly) of the points
 * drawn, in the part of the panel the title, legend and colour bar leave free. */
struct RenderOptions {
  int width = 1280; ///< whole image, pixels
  int height = 720; ///< whole image, pixels
  int columns = 0;  ///< panels per row; 0: as square a grid as fits
  /** Where the camera looks from. Auto: from the sensor when it is known and outside
   * the points' horizontal bounds (a camera looking at a scene), otherwise Oblique. */
  ViewKind view = ViewKind::Auto;
  /** The scene's up direction (z for most scans; setSceneFrame reads it from a cloud).
   */
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  /** The scanner's position; NaN (the default) when unknown. */
  Eigen::Vector3d sensor =
      Eigen::Vector3d::Constant (std::numeric_limits<double>::quiet_NaN());
  /** Points higher than this along \a up are left out (e.g. a ceiling hiding the
   * rooms). NaN (the default): just below a ceiling when the data have one
   * (estimateCeilingHeight), otherwise no clip; +infinity: no clip. */
  double max_height = std::numeric_limits<double>::quiet_NaN();
  /** Explicit direction the camera looks along; zero (the default): from \a view. */
  Eigen::Vector3d view_direction = Eigen::Vector3d::Zero();
  /** Free space kept on each side of the subject, as a fraction of the frame. */
  double margin = 0.05;
  std::uint8_t background[3] = {255, 255, 255};
};

/** \brief Sets \a options' up direction and sensor from \a cloud's frame: an organised
 * cloud is a depth camera's image, in the camera's frame (x right, y down, z forward)
 * turned by its sensor_orientation_, with the camera at sensor_origin_; any other cloud
 * has z up, and its sensor at sensor_origin_ when that is not the origin. */
template <typename PointT>
void
setSceneFrame (const pcl::PointCloud<PointT>& cloud, RenderOptions& options)
{
  const Eigen::Vector3d origin =
      cloud.sensor_origin_.template head<3>().template cast<double>();
  if (cloud.isOrganized() && cloud.height > 1) {
    options.up =
        (cloud.sensor_orientation_.template cast<double>() * -Eigen::Vector3d::UnitY());
    options.sensor = origin;
    return;
  }
  options.up = Eigen::Vector3d::UnitZ();
  if (origin.norm() > 0.0)
    options.sensor = origin;
}

/** \brief Render views side by side into a PNG file, offscreen.
 *
 * Uses PCL's visualizer without an interactor and VTK's offscreen rendering. VTK on
 * Debian is built for X only, so an X display is needed (on a headless machine run
 * under Xvfb, e.g. `xvfb-run -a`); without DISPLAY the function reports an error
 * instead of letting VTK abort. The file is written atomically (a temporary file
 * renamed into place). Points outside the frame (far outliers) are not seen.
 * \return false with a message on stderr when there is nothing to
 * draw, no display, bad options or the file cannot be written
 */
bool
renderToPng (const std::vector<View>& views,
             const std::string& path,
             const RenderOptions& options = RenderOptions());

/** \brief Whether an X display is available for rendering: DISPLAY is set and the
 * display opens (tried a few times over about a second). The connection is kept open
 * until the process ends, so that the server does not reset (and refuse VTK's
 * connection) between this check and the rendering. */
bool
displayAvailable ();
} // namespace visualization
} // namespace pcl_ext
