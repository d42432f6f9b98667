/*
 * pcl_ext: the borders of the scanned part of each surface in a simulated scan
 * (internal).
 */
#pragma once

#include "scan_grid.h"

#include <vector>

namespace pcl_ext {
namespace simulation {
namespace detail {
/** Surface points where the scanned part of their surface ends become Boundary: a
 * neighbouring ray of the grid returned a point of a discontinuity, or points into the
 * blind cone. A neighbour on the same continuous surface lies about one spacing away
 * (range * step / cos incidence); a jump of more than 4 spacings is a discontinuity.
 * Both sides of a jump are marked: the far side is the edge of a shadow, the near side
 * the occluding contour, where a smooth surface turns away from the scanner (a pipe's
 * or a column's silhouette) and its data end as they do at a shadow. Where the near
 * side ends at a curve of the scene (a box's crease), the scene's own curves have
 * already labelled it. A neighbouring ray that returned nothing marks a border too:
 * past a silhouette the rays meet the surface beyond the maximum incidence angle, or
 * miss it into the sky or beyond the maximum range; so does the edge of the field of
 * view. Not on porous surfaces (vegetation), whose gaps let rays through. A border of
 * one scan is a border of the scanned part only where the returns of all scanners leave
 * the gap open: a point stays marked when the returns of its surface among its 64
 * nearest, within 4 of its spacings (the continuity distance), leave an angle wider
 * than a right angle free around it in its tangent plane (pcl::BoundaryEstimation's
 * criterion). Another scanner that sees into the shadow, or past the silhouette, fills
 * the gap; so does the far side of a shadow narrower than the continuity distance. \a
 * index must hold the tree. */
void
markCoverageBoundaries (const ScanGrid& grid,
                        const ReturnIndex& index,
                        unsigned int threads,
                        std::vector<ColumnPoints>& points);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
