/*
 * pcl_ext: the picture options every tool that writes a PNG offers (-view, -png_max_z).
 */
#pragma once

#include <pcl_ext/apps/command_line.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

namespace pcl_ext {
namespace apps {
/** \brief -view and -png_max_z: where the pictures are seen from and a height clip. */
struct PictureOptions {
  std::string view = "auto";
  /** "auto": below a ceiling found in the data, none otherwise; "none": no clip; or a
   * height. */
  std::string max_z = "auto";

  void
  addTo (CommandLine& cl)
  {
    cl.addOption ("view",
                  view,
                  "PNG: seen from auto|top|side|oblique|sensor (auto: from the sensor "
                  "when it looks at the scene from outside, otherwise oblique)");
    cl.addOption ("png_max_z",
                  max_z,
                  "PNG: leave out points higher than this (along the up direction: z, "
                  "or -y in a depth camera's frame); auto: below a ceiling found in "
                  "the data; none: no clip");
  }

  /** \brief Whether the options are valid; reports the first error on stderr. */
  bool
  valid () const
  {
    double height = 0.0;
    if (!maxHeight (height)) {
      std::cerr << "Error: -png_max_z must be auto, none or a number, not '" << max_z
                << "'.\n";
      return false;
    }
    for (const char* name : {"auto", "top", "side", "oblique", "sensor"})
      if (view == name)
        return true;
    std::cerr << "Error: -view must be auto, top, side, oblique or sensor, not '"
              << view << "'.\n";
    return false;
  }

  /** \brief -png_max_z as RenderOptions::max_height takes it (NaN: auto, +infinity:
   * none); false when it is none of auto, none or a finite number. */
  bool
  maxHeight (double& height) const
  {
    if (max_z == "auto") {
      height = std::numeric_limits<double>::quiet_NaN();
      return true;
    }
    if (max_z == "none") {
      height = std::numeric_limits<double>::infinity();
      return true;
    }
    char* end = nullptr;
    height = std::strtod (max_z.c_str(), &end);
    return !max_z.empty() && *end == '\0' && std::isfinite (height);
  }

#ifdef PCL_EXT_HAVE_VISUALIZATION
  /** \brief Render options of the picture of \a cloud (its frame: setSceneFrame). */
  template <typename PointT>
  visualization::RenderOptions
  renderOptions (const pcl::PointCloud<PointT>& cloud) const
  {
    visualization::RenderOptions options;
    visualization::setSceneFrame (cloud, options);
    visualization::parseViewKind (view, options.view);
    maxHeight (options.max_height);
    return options;
  }
#endif
};
} // namespace apps
} // namespace pcl_ext
