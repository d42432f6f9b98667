/*
 * pcl_ext: a picture in which a scan's fit to a 2D footprint can be judged.
 */
#include <pcl_ext/visualization/footprint_view.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace visualization {
namespace {
double
segmentDistance (const Eigen::Vector2d& p,
                 const Eigen::Vector2d& a,
                 const Eigen::Vector2d& b)
{
  const Eigen::Vector2d ab = b - a;
  const double length = ab.squaredNorm();
  const double t =
      length > 0.0 ? std::clamp ((p - a).dot (ab) / length, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}
} // namespace

View
makeFootprintView (const std::string& title,
                   const std::vector<Eigen::Vector3d>& wall_points,
                   const FootprintSegments& footprint,
                   double max_residual)
{
  View view;
  view.title = title;
  pcl::PointCloud<pcl::PointXYZ> walls;
  std::vector<float> residual;
  for (const auto& p : wall_points) {
    if (!p.allFinite())
      continue;
    double nearest = std::numeric_limits<double>::quiet_NaN();
    for (const auto& [a, b] : footprint) {
      const double d = segmentDistance (p.head<2>(), a, b);
      if (!(d >= nearest))
        nearest = d;
    }
    walls.push_back (pcl::PointXYZ (float (p.x()), float (p.y()), 0.0f));
    residual.push_back (float (nearest));
  }
  if (!(max_residual > 0.0)) {
    std::vector<float> finite;
    for (const float r : residual)
      if (std::isfinite (r))
        finite.push_back (r);
    max_residual = 1.0;
    if (!finite.empty()) {
      const std::size_t k = finite.size() * 95 / 100;
      std::nth_element (finite.begin(), finite.begin() + k, finite.end());
      max_residual = std::max (double (finite[k]), 1e-3);
    }
  }
  std::vector<Colour> colours =
      colourByScalar (residual, ColourMap::Jet, 0.0f, float (max_residual));
  for (std::size_t i = 0; i < residual.size(); ++i)
    if (!std::isfinite (residual[i]))
      colours[i] = {150, 150, 150};
  view.layers.push_back ({makeColouredCloud (walls, colours)});
  if (!footprint.empty()) {
    // The outline a little above the points, drawn over them in the top view, one pixel
    // wide so that the colours of the points on it show on both sides.
    pcl::PointCloud<pcl::PointXYZ> outline;
    double length = 0.0;
    for (const auto& [a, b] : footprint)
      length += (b - a).norm();
    const double step = std::max (length / 4000.0, 1e-6);
    for (const auto& [a, b] : footprint) {
      const int steps = std::max (2, static_cast<int> ((b - a).norm() / step));
      for (int s = 0; s <= steps; ++s) {
        const Eigen::Vector2d q = a + (b - a) * (double (s) / steps);
        outline.push_back (pcl::PointXYZ (float (q.x()), float (q.y()), 0.01f));
      }
    }
    view.layers.push_back (
        {makeColouredCloud (outline,
                            std::vector<Colour> (outline.size(), Colour{0, 0, 0})),
         1.0});
    view.legend.push_back ({"footprint", {0, 0, 0}});
    view.colour_bar = {
        "distance to footprint", 0.0f, float (max_residual), ColourMap::Jet};
  }
  return view;
}
} // namespace visualization
} // namespace pcl_ext
