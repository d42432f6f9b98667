/*
 * pcl_ext_tiles: the points of one tile with neighbourhoods that are those of the whole
 * cloud.
 */
#pragma once

#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/tiling/tile_plan.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief How a method searches neighbourhoods: k nearest (capped at max_radius when >
 * 0) or all within radius (when > 0), and how many neighbourhood steps a point's
 * result reaches through (1: its own neighbourhood; 2: also its neighbours' own, as eq.
 * 5 of Belton & Lichti does). With search false the method searches by itself: the
 * tile is its core and a margin of \a radius around it (the halo), no neighbourhoods
 * are searched or checked, and the result near the tile's edge may differ from the
 * whole cloud's (a method whose reach cannot be bounded, e.g. through belief
 * propagation); the margin is then widened only where it holds k points or fewer, and
 * the halo is radius plus hops k-neighbourhoods (see getNeededMargin for the check). */
struct NeighbourhoodReach {
  int k = 50;
  double radius = 0.0;
  double max_radius = 0.0;
  int hops = 1;
  bool search = true;
};

/** \brief A tile's points (its core, its halo and, when the halo was too small, a wider
 * margin read from the tiles around it) with their neighbourhoods. */
struct TileCloud {
  std::size_t tile = 0;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint64_t> indices; ///< global index of each point
  std::vector<bool> core;             ///< whether the tile owns the point
  std::vector<std::uint32_t> owners;  ///< the tile that owns each point
  pcl_ext::Neighbourhoods<pcl::PointXYZ>::Ptr neighbourhoods;
  double margin =
      0.0; ///< the core box widened by this holds the points (the halo or more)
  std::size_t core_points = 0;
  bool whole = false;              ///< the points are those of the whole cloud
  std::size_t attribute_count = 0; ///< values per point besides x y z (the method's)
  std::vector<float> attributes;   ///< those values, point after point
  tiling::TileGrid grid;           ///< the plan's tiles
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< the plan's origin

  /** \brief How far the point at local (x, y) is from the edge of the data loaded
   * (tiling::TileGrid::getReach with this margin; infinity where no data lies
   * beyond). */
  double
  getReach (float x, float y) const
  {
    return grid.getReach (tile, origin.x() + x, origin.y() + y, margin);
  }
};

/** \brief Which of a tile's loaded points need neighbourhoods: \a query gets one flag
 * per point of \a cloud (neighbourhoods not searched yet). \return false (message
 * printed) on error */
using PointSelection =
    std::function<bool (const TileCloud& cloud, std::vector<char>& query)>;

/** \brief Load tile \a tile of \a plan from \a folder with neighbourhoods as \a reach
 * says, and check that every core point's result can be that of the whole cloud: each
 * neighbourhood it reaches through (\a reach.hops steps) lies within the points loaded
 * (its radius at most the distance to the edge of the loaded data). When one does not,
 * the margin around the core is widened by what it lacked (the points read from the
 * tiles around) and the search runs again, until all do (at worst the whole cloud).
 * The margin is at least \a min_margin (and the plan's halo). With \a reach.search
 * false, the core and the halo without neighbourhoods, the margin widened only while it
 * holds at most \a reach.k points. With \a select, only the points it marks (given the
 * points loaded, one flag per point) get neighbourhoods and are checked, through the
 * rows of the marked points alone: for a method that reads no other rows.
 * \return false (message printed) when a file cannot be read, the search or \a select
 * fails */
bool
loadTileCloud (const tiling::TilePlan& plan,
               const std::string& folder,
               std::size_t tile,
               const NeighbourhoodReach& reach,
               unsigned int threads,
               TileCloud& result,
               double min_margin = 0.0,
               const PointSelection& select = {});
} // namespace apps
} // namespace pcl_ext
