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
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief How a method searches neighbourhoods: k nearest (capped at max_radius when >
 * 0) or all within radius (when > 0), and how many neighbourhood steps a point's
 * result reaches through (1: its own neighbourhood; 2: also its neighbours' own, as eq.
 * 5 of Belton & Lichti does). */
struct NeighbourhoodReach {
  int k = 50;
  double radius = 0.0;
  double max_radius = 0.0;
  int hops = 1;
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
};

/** \brief Load tile \a tile of \a plan from \a folder with neighbourhoods as \a reach
 * says, and check that every core point's result can be that of the whole cloud: each
 * neighbourhood it reaches through (\a reach.hops steps) lies within the points loaded
 * (its radius at most the distance to the edge of the loaded data). When one does not,
 * the margin around the core is widened by what it lacked (the points read from the
 * tiles around) and the search runs again, until all do (at worst the whole cloud).
 * \return false (message printed) when a file cannot be read or the search fails */
bool
loadTileCloud (const tiling::TilePlan& plan,
               const std::string& folder,
               std::size_t tile,
               const NeighbourhoodReach& reach,
               unsigned int threads,
               TileCloud& result);
} // namespace apps
} // namespace pcl_ext
