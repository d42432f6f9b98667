/*
 * pcl_ext: a picture in which a scan's fit to a 2D footprint can be judged.
 */
#pragma once

#include <pcl_ext/visualization/offscreen_renderer.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief A footprint's walls as 2D segments (map frame). */
using FootprintSegments = std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>;

/** \brief A top view of a registered scan's wall points over its footprint (Khoshelham
 * & Gorte 2009, figures 3 and 5, made judgeable): each wall point (map frame) is drawn
 * at its (x, y), coloured by its residual, the 2D distance to the nearest footprint
 * segment, on a colour bar from 0 to \a max_residual (0: the residuals' 95th
 * percentile); the footprint is drawn over it in black, one pixel wide. Render it with
 * RenderOptions::view = ViewKind::Top. Points that are not finite are left out; no
 * segment gives a view of the points in grey. */
View
makeFootprintView (const std::string& title,
                   const std::vector<Eigen::Vector3d>& wall_points,
                   const FootprintSegments& footprint,
                   double max_residual = 0.0);
} // namespace visualization
} // namespace pcl_ext
