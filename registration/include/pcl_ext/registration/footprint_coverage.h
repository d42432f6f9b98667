/*
 * pcl_ext: how much of an airborne scan's roof a pose puts over the footprints, the
 * check of plane matching's candidate poses against the whole map.
 */
#pragma once

#include <pcl_ext/io/footprints.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief The footprints as areas in plan: which points a pose puts inside a building.
 *
 * Khoshelham & Gorte (2009, section 3.3) rank match sets by their number of pairs.
 * Beyond the paper: a map of many buildings (a block's footprints, a city's cadastre)
 * has parallel, repeated walls, and with an airborne scan's walls (roof outlines, a
 * few degrees off, section 3.1 with airborne data) a half or quarter turn of the whole
 * scan, or a shift by one house along a row, pairs as many walls as the true pose. The
 * roof points must lie over a footprint (less the eaves and the buildings the map does
 * not hold): the share that a pose puts inside tells those poses apart (see
 * PlaneMatchingParameters::coverage_margin).
 */
class FootprintCoverage {
public:
  /** \brief The footprints' outer rings and holes, moved by -\a origin (the map's local
   * frame). */
  FootprintCoverage (const std::vector<io::Footprint>& footprints,
                     const Eigen::Vector3d& origin);

  /** \brief Whether the map has any area. */
  bool
  empty () const
  {
    return polygons_.empty();
  }

  /** \brief Whether the point (x, y) of the local frame is inside a footprint (even-odd
   * rule over each polygon's rings, so holes are outside). */
  bool
  inside (const Eigen::Vector2d& q) const;

  /** \brief The share of \a points (local scan frame) that \a pose (scan to local map
   * frame) puts inside a footprint; 0 for no points. */
  double
  share (const std::vector<Eigen::Vector3d>& points, const Eigen::Matrix4d& pose) const;

private:
  struct Area {
    Eigen::AlignedBox2d box;
    std::vector<io::Ring2d> rings;
  };
  void
  indexAreas ();
  std::pair<int, int>
  cellOf (const Eigen::Vector2d& q) const;

  std::vector<Area> polygons_;
  Eigen::AlignedBox2d grid_box_; // the areas' boxes
  double cell_ = 1.0;
  int columns_ = 0, rows_ = 0;
  std::vector<std::vector<std::size_t>> cells_; // areas overlapping each cell
};
} // namespace pcl_ext
