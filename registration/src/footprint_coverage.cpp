/*
 * pcl_ext: the share of points a pose puts inside the footprints.
 */
#include <pcl_ext/registration/footprint_coverage.h>

namespace pcl_ext {
namespace {
// Even-odd crossing test of one ring.
bool
crossesOddly (const io::Ring2d& ring, const Eigen::Vector2d& q)
{
  bool odd = false;
  for (std::size_t a = 0, b = ring.size() - 1; a < ring.size(); b = a++)
    if ((ring[a].y() > q.y()) != (ring[b].y() > q.y()) &&
        q.x() < ring[a].x() + (ring[b].x() - ring[a].x()) * (q.y() - ring[a].y()) /
                                  (ring[b].y() - ring[a].y()))
      odd = !odd;
  return odd;
}
} // namespace

FootprintCoverage::FootprintCoverage (const std::vector<io::Footprint>& footprints,
                                      const Eigen::Vector3d& origin)
{
  const Eigen::Vector2d shift = origin.head<2>();
  for (const auto& footprint : footprints)
    for (const auto& polygon : footprint.polygons) {
      if (polygon.outer.size() < 3)
        continue;
      Area area;
      area.rings.push_back (polygon.outer);
      for (const auto& hole : polygon.holes)
        if (hole.size() >= 3)
          area.rings.push_back (hole);
      for (auto& ring : area.rings)
        for (auto& v : ring) {
          v -= shift;
          area.box.extend (v);
        }
      polygons_.push_back (std::move (area));
    }
}

bool
FootprintCoverage::inside (const Eigen::Vector2d& q) const
{
  for (const auto& area : polygons_) {
    if (!area.box.contains (q))
      continue;
    bool odd = false;
    for (const auto& ring : area.rings)
      odd = odd != crossesOddly (ring, q);
    if (odd)
      return true;
  }
  return false;
}

double
FootprintCoverage::share (const std::vector<Eigen::Vector3d>& points,
                          const Eigen::Matrix4d& pose) const
{
  if (points.empty())
    return 0.0;
  const Eigen::Matrix<double, 2, 3> rotation = pose.topLeftCorner<2, 3>();
  const Eigen::Vector2d translation = pose.topRightCorner<2, 1>();
  std::size_t count = 0;
  for (const auto& p : points)
    count += inside (rotation * p + translation);
  return static_cast<double> (count) / static_cast<double> (points.size());
}
} // namespace pcl_ext
