/*
 * pcl_ext_tiles: how wide a margin a tile needs for Belton & Lichti's re-integration
 * (section 4) of its core points to be that of the whole cloud.
 */
#pragma once

#include "tile_cloud.h"

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The radius of point \a i's neighbourhood in \a nb (the distance to its
 * farthest neighbour), 0 when it has none. */
double
neighbourhoodRadius (const pcl_ext::Neighbourhoods<pcl::PointXYZ>& nb, std::size_t i);

/** \brief The margin around \a tile's core within which the re-integration of every
 * core point (pcl_ext::LocalSurfaceIntersection with reach factor F = \a reach_factor)
 * reads only data the tile holds (narrower than the present one where that is wider
 * than needed; 0 when no core point is to be re-integrated or none is near an edge of
 * the data).
 *
 * With r(p) the radius of p's neighbourhood, an edge or boundary point q without a
 * segment reads:
 * - the border points of the segments within its reach F r(q), the ball B; which
 * points are border points depends on their neighbourhoods;
 * - for each such point j, the local intersections it takes part in: found by any
 * border point a whose reach F r(a) holds j (j itself among them), each from a's
 * nearest points of the other segments within that reach, each with its
 * neighbourhood.
 * So q reads as far as F r(q) + 2 F r(a) + R(a) for every border point a whose reach
 * meets B, with R(a) the largest radius of a segment's surface point within a's reach.
 * Each such a is rasterised on a grid with that value over its reach; q's margin is
 * F r(q) plus the largest value of the cells over B. The points the tile did not load
 * are bounded by their tile's largest radius (\a tile_radii, from each tile's own run:
 * the largest neighbourhood radius of its surface points); where one of them could
 * reach B, the tile needs a wider margin too. A neighbourhood cut by the edge of the
 * loaded data is wider than the whole cloud's, never narrower, so the bounds hold.
 * \a segments and \a classes hold every point's segment (SegmentMerge::kNoSegment for
 * none) and pcl_ext::PointClass.
 *
 * With \a intersections, the local intersections found by the core's border points
 * must be the whole cloud's too (the intersection points of pcl_ext_segment_variance
 * -intersections): such a point reads its reach, the neighbourhoods of the points
 * there, and, to know whether another point found the same pair first, the
 * intersections of every border point whose reach holds it; the same bound as for q, so
 * the core's border points are counted among the points read for. */
double
neededReintegrationMargin (const TileCloud& tile,
                           const std::vector<std::uint32_t>& segments,
                           const std::vector<std::uint32_t>& classes,
                           const std::vector<float>& tile_radii,
                           double reach_factor,
                           bool intersections = false);
} // namespace apps
} // namespace pcl_ext
