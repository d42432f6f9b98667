/*
 * pcl_ext: the creases of a simulated scan that it saw from one side only (internal).
 */
#pragma once

#include "scan_grid.h"

#include <pcl_ext/simulation/scene_geometry.h>

#include <vector>

namespace pcl_ext {
namespace simulation {
namespace detail {
/** Edge points of a crease whose other surface no scanner saw near them become
 * Boundary. A crease is the line where two surfaces meet; where the scan holds points
 * of one of them alone (the other face turned away from every station, hidden, or
 * outside the field of view), its points end there as they end at the edge of a shadow,
 * and the cloud holds nothing that tells the two apart: the scanned part of the surface
 * has a border there (see markCoverageBoundaries). A point stays an edge when a return
 * of the other surface of any crease within its band lies within 4 of its spacings: the
 * reach within which the open borders are judged (the returns of a point's surface
 * there must leave more than a right angle free around it), about the radius of 50
 * points of the point's own scan. A face seen at grazing incidence from far away, its
 * returns many of the point's spacings apart, is not seen at the point's scale. Not on
 * porous surfaces. \a index must hold the tree. */
void
markOneSidedCreases (const ScanGrid& grid,
                     const ReturnIndex& index,
                     const SceneGeometry& geometry,
                     unsigned int threads,
                     std::vector<ColumnPoints>& points);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
