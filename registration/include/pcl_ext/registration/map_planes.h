/*
 * pcl_ext: wall and floor planes inferred from building footprints (Khoshelham & Gorte
 * 2009, section 3.1).
 */
#pragma once

#include <pcl_ext/io/footprints.h>
#include <pcl_ext/registration/planes.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace pcl_ext {
/** \brief How map planes are built from footprints. */
struct MapPlaneParameters {
  /** \brief Local origin subtracted from the map coordinates before anything else, so
   * that georeferenced coordinates (x ~ 10^5 m in RD New, 10^6 m in UTM) keep their
   * digits in the float clouds PCL registers. The registration result maps the scan
   * into map - origin. */
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double floor_height = 0.0; ///< floor plane z = floor_height (map frame); paper: z = 0
  double wall_height =
      10.0; ///< height of the walls' extent boxes (m), > 0; the map has none
  double min_edge_length = 0.5; ///< edges shorter than this (m) give no wall, >= 0
  bool add_floor = true;        ///< add the horizontal floor plane (paper: yes)
};

/** \brief The footprints near a scan: those whose bounding box, in plan, comes
 * within \a margin of \a scan_box (the scan's points in map coordinates, e.g. moved by
 * a guess; x and y are used). A city's footprint file holds hundreds of walls; with
 * all of them as map planes, the initial combinations of Khoshelham & Gorte's search
 * (section 3.3) are swamped by walls the scan cannot have seen. When none is near (a
 * scan that is not in map coordinates), all are kept: the global search needs no
 * overlap.
 * \param[in] footprints polygons in map coordinates
 * \param[in] scan_box the scan's bounding box in map coordinates
 * \param[in] margin slack around the box (m), >= 0
 * \param[out] near the footprints kept, in file order
 * \return whether some footprint was near (false: \a near holds all) */
bool
selectFootprintsNearScan (const std::vector<io::Footprint>& footprints,
                          const Eigen::AlignedBox3d& scan_box,
                          double margin,
                          std::vector<io::Footprint>& near);

/** \brief A local origin for \a footprints: the centre of their bounding box rounded to
 * whole metres, z = 0. Rounding keeps the origin easy to read and to re-apply by hand.
 * \return false when there is no finite vertex */
bool
chooseLocalOrigin (const std::vector<io::Footprint>& footprints,
                   Eigen::Vector3d& origin);

/** \brief Map planes of Khoshelham & Gorte section 3.1: a vertical wall on every
 * polygon edge (outer rings and holes) and a horizontal floor.
 *
 * A wall on the edge p1 -> p2 (in map - origin coordinates) has the normal of eq. 1,
 * n = (y2 - y1, -(x2 - x1), 0) / |l|, and eq. 2's signed offset (x1 y2 - x2 y1) / |l|,
 * which is n . p1; as a pcl_ext::Plane (n . x + d = 0), d = -n . p1. Eq. 2 takes the
 * absolute value of d, which contradicts eq. 1's normal on one side of the origin;
 * pcl_ext keeps the sign. The readers orient outer rings counter-clockwise and holes
 * clockwise, so eq. 1's normal points out of the building, which is the side a
 * terrestrial scanner sees: this is the canonical sign of every wall. The floor has n =
 * (0, 0, 1) and d = origin.z - floor_height.
 *
 * \param[in] footprints polygons in map coordinates (double precision)
 * \param[in] parameters origin, floor, extents
 * \param[out] planes floor first (if added), then the walls in file order
 * \return false with a PCL_ERROR (and no planes) for no polygon, a non-finite vertex, a
 * ring with fewer than 3 vertices, a self-intersecting ring or invalid parameters
 */
bool
computeMapPlanes (const std::vector<io::Footprint>& footprints,
                  const MapPlaneParameters& parameters,
                  std::vector<MapPlane>& planes);

/** \brief Same for one outer ring (either orientation; reversed to counter-clockwise
 * first), e.g. a simulated footprint. Edge indices refer to the counter-clockwise
 * order. */
bool
computeMapPlanes (const io::Ring2d& ring,
                  const MapPlaneParameters& parameters,
                  std::vector<MapPlane>& planes);

/** \brief Whether two edges of \a ring cross or touch other than at their shared
 * vertex. */
bool
isSelfIntersecting (const io::Ring2d& ring);
} // namespace pcl_ext
