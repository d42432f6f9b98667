/*
 * pcl_ext_tiles: the points of one tile with neighbourhoods that are those of the whole
 * cloud.
 */
#include "tile_cloud.h"

#include <pcl_ext/tiling/tile_points.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace pcl_ext {
namespace apps {
namespace {
/** The points of the tiles \a tiles, each once, in global order, with their \a count
 * attributes each (\a attributes, point after point). */
bool
readTiles (const std::string& folder,
           const std::vector<std::size_t>& tiles,
           std::size_t count,
           std::vector<tiling::TilePoint>& points,
           std::vector<float>& attributes)
{
  std::vector<tiling::TilePoint> all, one;
  std::vector<float> all_attributes, one_attributes;
  for (const std::size_t t : tiles) {
    if (!tiling::readTilePoints (folder, t, one) ||
        !tiling::readTileAttributes (folder, t, count, one_attributes))
      return false;
    if (one_attributes.size() != one.size() * count) {
      std::cerr << "Error: the attributes of tile " << t << " in " << folder
                << " do not match its points.\n";
      return false;
    }
    all.insert (all.end(), one.begin(), one.end());
    all_attributes.insert (
        all_attributes.end(), one_attributes.begin(), one_attributes.end());
  }
  std::vector<std::size_t> order (all.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort (order.begin(), order.end(), [&all] (std::size_t a, std::size_t b) {
    return all[a].index < all[b].index;
  });
  points.clear();
  attributes.clear();
  for (const std::size_t i : order) {
    if (!points.empty() && points.back().index == all[i].index)
      continue; // a halo point read from two tiles
    points.push_back (all[i]);
    attributes.insert (attributes.end(),
                       all_attributes.begin() + static_cast<std::ptrdiff_t> (i * count),
                       all_attributes.begin() +
                           static_cast<std::ptrdiff_t> ((i + 1) * count));
  }
  return true;
}

/** Whether each point's own neighbourhood lies within the loaded data; \a short_by: the
 * most any falls short by. */
std::vector<char>
ownNeighbourhoodsWithin (const tiling::TilePlan& plan,
                         const tiling::TileGrid& grid,
                         const TileCloud& t,
                         const NeighbourhoodReach& reach,
                         const std::vector<char>& query,
                         double& short_by)
{
  const auto& nb = *t.neighbourhoods;
  short_by = 0.0;
  std::vector<char> within (t.cloud->size(), 0);
  for (std::size_t i = 0; i < t.cloud->size(); ++i) {
    if (!query.empty() && !query[i]) {
      within[i] = 1; // no row is read: nothing to check
      continue;
    }
    const auto& p = (*t.cloud)[i];
    const double space =
        grid.getReach (t.tile, plan.origin.x() + p.x, plan.origin.y() + p.y, t.margin);
    if (std::isinf (space)) {
      within[i] = 1;
      continue;
    }
    const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
    double needed = std::numeric_limits<double>::infinity();
    if (reach.radius > 0.0)
      needed = reach.radius;
    else if (row >= 0) {
      const auto r = nb[static_cast<std::size_t> (row)];
      if (r.size() == static_cast<std::size_t> (reach.k) && r.size() > 0)
        needed = std::sqrt (static_cast<double> (
            nb.getSquaredDistance (static_cast<std::size_t> (row), r.size() - 1)));
      else if (reach.max_radius > 0.0)
        needed = reach.max_radius;
    }
    within[i] = needed <= space;
    if (!within[i])
      short_by = std::max (short_by, needed - space);
  }
  return within;
}
} // namespace

bool
loadTileCloud (const tiling::TilePlan& plan,
               const std::string& folder,
               std::size_t tile,
               const NeighbourhoodReach& reach,
               unsigned int threads,
               TileCloud& result,
               double min_margin,
               const PointSelection& select)
{
  const tiling::TileGrid grid = plan.getGrid();
  result = TileCloud();
  result.tile = tile;
  std::vector<std::size_t> tiles;
  std::vector<tiling::TilePoint> points;
  std::vector<float> attributes;
  const auto found = plan.settings.find ("attributes");
  const std::size_t count =
      found == plan.settings.end() ? 0 : std::stoul (found->second);
  double margin = std::max (plan.halo, min_margin);
  for (;;) {
    // The tiles whose cores reach into the margin, then their points within it.
    const auto rings = static_cast<std::size_t> (
        std::ceil (std::max (0.0, margin - plan.halo) / plan.tile_size));
    grid.getTilesAround (tile, rings, tiles);
    if (!readTiles (folder, tiles, count, points, attributes))
      return false;
    const std::size_t read = points.size();
    if (rings > 0) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (grid.isWithin (tile,
                           plan.origin.x() + points[i].x,
                           plan.origin.y() + points[i].y,
                           margin)) {
          points[kept] = points[i];
          std::copy_n (attributes.begin() + static_cast<std::ptrdiff_t> (i * count),
                       count,
                       attributes.begin() + static_cast<std::ptrdiff_t> (kept * count));
          ++kept;
        }
      points.resize (kept);
      attributes.resize (kept * count);
    }
    result.attribute_count = count;
    result.attributes = attributes;
    result.margin = margin;
    result.grid = grid;
    result.origin = plan.origin;
    result.whole = tiles.size() == grid.size() && points.size() == read;
    result.cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    result.cloud->resize (points.size());
    result.indices.resize (points.size());
    result.owners.resize (points.size());
    result.core.assign (points.size(), false);
    result.core_points = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      (*result.cloud)[i] = pcl::PointXYZ (points[i].x, points[i].y, points[i].z);
      result.indices[i] = points[i].index;
      result.owners[i] = points[i].owner;
      result.core[i] = points[i].owner == tile;
      result.core_points += result.core[i];
    }
    if (result.core_points == 0)
      return true; // an empty tile: nothing to compute
    if (!reach.search) {
      // A method that searches by itself needs more than k points (isolated points
      // whose neighbours lie beyond the halo).
      if (result.cloud->size() > static_cast<std::size_t> (reach.k) || result.whole)
        return true;
      margin += std::max (reach.radius, 0.05 * plan.tile_size);
      continue;
    }
    result.neighbourhoods = pcl::make_shared<pcl_ext::Neighbourhoods<pcl::PointXYZ>>();
    auto& nb = *result.neighbourhoods;
    nb.setInputCloud (result.cloud);
    nb.setStoreSquaredDistances (false);
    if (reach.radius > 0.0)
      nb.setRadiusSearch (reach.radius);
    else {
      nb.setKSearch (reach.k);
      nb.setMaxRadius (reach.max_radius);
    }
    nb.setNumberOfThreads (threads);
    std::vector<char> query;
    if (select) {
      if (!select (result, query) || query.size() != result.cloud->size())
        return false;
      auto chosen = pcl::make_shared<pcl::Indices>();
      for (std::size_t i = 0; i < query.size(); ++i)
        if (query[i])
          chosen->push_back (static_cast<pcl::index_t> (i));
      if (chosen->empty())
        return true; // nothing to search: no point of the tile needs a row
      nb.setIndices (chosen);
    }
    if (result.cloud->size() <= static_cast<std::size_t> (reach.k) &&
        reach.radius <= 0.0 && tiles.size() == grid.size())
      return true; // fewer points than k in the whole cloud: the method says so
    if (result.cloud->size() > static_cast<std::size_t> (reach.k) ||
        reach.radius > 0.0) {
      if (!nb.compute()) {
        std::cerr << "Error: the neighbourhood search of tile " << tile << " failed.\n";
        return false;
      }
    }
    // Within after h steps: its own neighbourhood and those of its neighbours within
    // after h - 1 steps.
    double short_by = 0.0;
    std::vector<char> within;
    if (nb.empty())
      short_by = plan.tile_size; // too few points to search: widen
    else {
      within = ownNeighbourhoodsWithin (plan, grid, result, reach, query, short_by);
      for (int h = 1; h < reach.hops; ++h) {
        std::vector<char> next = within;
        for (std::size_t i = 0; i < within.size(); ++i) {
          if (!within[i])
            continue;
          const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
          if (row < 0)
            continue;
          const auto r = nb[static_cast<std::size_t> (row)];
          for (std::size_t j = 0; j < r.size() && next[i]; ++j)
            next[i] = within[static_cast<std::size_t> (r.indices[j])];
        }
        within.swap (next);
      }
    }
    bool all = !nb.empty();
    for (std::size_t i = 0; i < within.size() && all; ++i)
      all = !result.core[i] || within[i];
    if (all || tiles.size() == grid.size())
      return true;
    // Widen by what the farthest neighbourhood lacked, and a little more.
    margin += std::max (1.25 * short_by, 0.05 * plan.tile_size);
  }
}
} // namespace apps
} // namespace pcl_ext
