/*
 * pcl_ext: the connected visible pieces of each surface in a simulated scan (internal).
 */
#pragma once

#include "scan_grid.h"

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace simulation {
namespace detail {
/** Give every connected visible piece of a surface its own segment id (see
 * TlsScanSimulation::setConnectedSegments). Two returns of one surface are linked when
 * - they come from adjacent rays of one scanner (one step in azimuth or elevation) and
 * are continuous (within 4 spacings, the test of the coverage boundaries), or
 * - they come from different scanners and lie within the spacing of both (where two
 * scans overlap, every return of one lies inside a grid cell of the other, so within
 * about 0.7 spacing of one of its returns; two pieces that only face each other across
 * a gap wider than the local spacing, e.g. the two sides of a wall cutting a ceiling,
 * are not). The pieces are the connected components of the links. The largest piece of
 * a surface keeps its id; the others get new ids, above every surface id of the scan,
 * in the order of (surface id, first point), except pieces of fewer than 10 returns (a
 * few rays through a gap, a face seen edge-on), which keep the surface's id. Porous
 * surfaces (vegetation) are scattered returns, not a continuous surface, and are not
 * split. Points are numbered in output order, so the result does not depend on the
 * thread count. \param[in] index the returns numbered (see buildReturnIndex) before any
 * segment id changes \param[in,out] points the returns' points, whose segment ids
 * become piece ids \param[out] surface_of_segment the surface id of every segment id
 * (left as it is when the scan has no return) */
void
splitSegmentsIntoPieces (const ScanGrid& grid,
                         const ReturnIndex& index,
                         unsigned int threads,
                         std::vector<ColumnPoints>& points,
                         std::vector<std::uint32_t>& surface_of_segment);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
