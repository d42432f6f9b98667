/*
 * pcl_ext: the share of points a pose puts inside the footprints.
 */
#include <pcl_ext/registration/footprint_coverage.h>

#include <algorithm>

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
  indexAreas();
}

void
FootprintCoverage::indexAreas()
{
  // A uniform grid over the areas' boxes, cells about a footprint across (at most
  // kMaxCellsAcross along a side): a point is tested against the areas of its cell
  // only, so a city's cadastre costs what a block does.
  constexpr int kMaxCellsAcross = 512;
  grid_box_.setEmpty();
  cells_.clear();
  if (polygons_.empty())
    return;
  std::vector<double> sizes;
  for (const auto& area : polygons_) {
    grid_box_.extend (area.box);
    sizes.push_back (area.box.sizes().maxCoeff());
  }
  std::nth_element (sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  const double extent = grid_box_.sizes().maxCoeff();
  cell_ = std::max ({sizes[sizes.size() / 2], extent / kMaxCellsAcross, 1e-9});
  columns_ =
      std::min (kMaxCellsAcross, static_cast<int> (grid_box_.sizes().x() / cell_) + 1);
  rows_ =
      std::min (kMaxCellsAcross, static_cast<int> (grid_box_.sizes().y() / cell_) + 1);
  cells_.assign (static_cast<std::size_t> (columns_) * rows_, {});
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    const auto lo = cellOf (polygons_[i].box.min()),
               hi = cellOf (polygons_[i].box.max());
    for (int y = lo.second; y <= hi.second; ++y)
      for (int x = lo.first; x <= hi.first; ++x)
        cells_[static_cast<std::size_t> (y) * columns_ + x].push_back (i);
  }
}

std::pair<int, int>
FootprintCoverage::cellOf (const Eigen::Vector2d& q) const
{
  const Eigen::Vector2d c = (q - grid_box_.min()) / cell_;
  return {std::max (0, std::min (columns_ - 1, static_cast<int> (c.x()))),
          std::max (0, std::min (rows_ - 1, static_cast<int> (c.y())))};
}

bool
FootprintCoverage::inside (const Eigen::Vector2d& q) const
{
  if (polygons_.empty() || !grid_box_.contains (q))
    return false;
  const auto cell = cellOf (q);
  for (const std::size_t i :
       cells_[static_cast<std::size_t> (cell.second) * columns_ + cell.first]) {
    const Area& area = polygons_[i];
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
