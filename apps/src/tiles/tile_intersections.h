/*
 * pcl_ext_tiles segment_variance -intersections: the local intersection points of
 * section 4 that each tile's own points found, saved per tile and merged in the whole
 * cloud's order.
 */
#pragma once

#include <pcl_ext/segmentation/surface_intersection_point.h>

#include <pcl/point_cloud.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief An intersection point found in a tile, with the whole cloud's indices of
 * its two surface points (the point's own index fields are the tile's). */
struct TileIntersection {
  SurfaceIntersectionPoint point;
  std::uint64_t index_a = 0; ///< the point that found it
  std::uint64_t index_b = 0;
};

/** \brief Save \a intersections, found by tile \a tile's own points in the whole
 * cloud's order, in \a workdir. \return false (message printed) when it cannot */
bool
saveTileIntersections (const std::string& workdir,
                       std::size_t tile,
                       const std::vector<TileIntersection>& intersections);

/** \brief The intersection points saved by the \a tiles tiles of \a workdir in the
 * order the untiled tool gives them: by the index of the point that found them (each
 * point belongs to one tile, which saved its points in their order), with the whole
 * cloud's indices. \return false (message printed) when a tile's file is missing or
 * broken, or an index does not fit the points' 32-bit index fields */
bool
mergeTileIntersections (const std::string& workdir,
                        std::size_t tiles,
                        pcl::PointCloud<SurfaceIntersectionPoint>& intersections);
} // namespace apps
} // namespace pcl_ext
