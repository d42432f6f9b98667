/*
 * pcl_ext: a terrestrial laser scanner simulator.
 */
#pragma once

#include <pcl_ext/simulation/scene_geometry.h>
#include <pcl_ext/simulation/simulated_point.h>

#include <pcl/point_cloud.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace simulation {
/** \brief Simulates terrestrial laser scans of a SceneGeometry from one or more
 * positions.
 *
 * Scanner model (the one of a panoramic phase/time-of-flight TLS with a level head):
 * - Rays form an equal-angle grid: azimuth i * step for i = 0 .. floor(360 / step) - 1
 * and elevation j * step for every integer j with the elevation in [min, max] (default
 * -60 deg to +90 deg, the blind cone below the tripod is not scanned). Point spacing
 * therefore grows linearly with range and with 1 / cos(incidence) on inclined surfaces.
 * - Each ray returns the nearest surface (occlusion) within the maximum range; returns
 * whose incidence angle exceeds the maximum incidence angle (default 88 deg) are
 * dropped, as real scanners lose them. Porous primitives (vegetation) let a ray through
 * with their porosity.
 * - Range noise is Gaussian along the ray with standard deviation
 *   sigma(r) = noise_sigma + noise_per_metre * r (defaults 5 mm and 0), plus the
 * primitive's roughness; there is no angular noise. Ground truth (class) uses the
 * noise-free hit.
 * - Class ground truth: a point is Edge (Boundary) when its true position lies within
 * the edge distance of a crease (border) curve of its own segment, see
 * SceneGeometry::classify. The edge distance is the local scan spacing range * step (in
 * radians) unless set explicitly. A Surface point is also Boundary where the scanned
 * part of its surface ends although the surface goes on (setCoverageBoundaries, default
 * on): a neighbouring ray of the grid (one step in azimuth or elevation, i.e. one local
 * spacing away) returned a point much farther from it than the spacing, nearer to the
 * scanner or farther (the edge of a shadow, or the silhouette of a smooth surface
 * turning away from the scanner), or points into the blind cone, or returned nothing
 * (past a silhouette beyond the maximum incidence, the sky, the maximum range, the edge
 * of the field of view; not on porous surfaces, whose gaps let rays through). A point
 * stays marked only where the returns of all scanners leave the gap open: those of its
 * surface among its 64 nearest returns, within 4 of its spacings, leave more than a
 * right angle free around it (another scanner seeing into a shadow closes it). An Edge
 * point becomes Boundary too where no scanner saw the crease's other face near it (the
 * back of a box, a roof above a wall seen from the street): no return of that face lies
 * within 4 of its spacings, as for the open borders. Those are the borders
 * of the sampled surface that a point cloud method sees.
 * - Segment ground truth: by default (setConnectedSegments) a segment id names one
 * connected visible piece of a surface, not the whole surface: a ceiling cut in two by
 * a wall, or a floor split by an object's shadow that no scan position sees into, gives
 * two segments. Returns of one surface are connected when they come from adjacent rays
 * of one scanner and lie within 4 spacings of each other (the continuity test of the
 * coverage boundaries), or from different scanners and lie within the local spacing of
 * both (where scans overlap). The largest piece keeps the surface's id, the others get
 * new ids above every surface id of the scan; scan() can report the surface of every
 * segment id. Pieces of fewer than 10 returns (a few rays through a gap, a face seen
 * edge-on) and porous surfaces (vegetation: scattered returns, not a continuous
 * surface) keep the surface's id.
 * - Colour and intensity follow the surface Material (see primitives.h).
 *
 * Determinism: every ray draws its random numbers from a stream seeded by a hash of
 * (seed, scanner index, azimuth index, elevation index), and the output is ordered by
 * scanner, azimuth column and elevation row, so results are bit-identical for any
 * thread count.
 */
class TlsScanSimulation {
public:
  /** \brief Scanner positions (the optical centre); the head is level (z up). */
  void
  setScanPositions (const std::vector<Vec3>& positions)
  {
    positions_ = positions;
  }
  const std::vector<Vec3>&
  getScanPositions () const
  {
    return positions_;
  }

  /** \brief Angular step between adjacent rays in degrees, both in azimuth and
   * elevation (default 0.1, range [0.001, 10]). */
  void
  setAngularStep (double degrees)
  {
    step_deg_ = degrees;
  }
  double
  getAngularStep () const
  {
    return step_deg_;
  }

  /** \brief Vertical field of view in degrees (default -60 to 90). */
  void
  setElevationRange (double min_deg, double max_deg)
  {
    min_elevation_deg_ = min_deg;
    max_elevation_deg_ = max_deg;
  }

  /** \brief Maximum range in metres (default 150). */
  void
  setMaximumRange (double range)
  {
    max_range_ = range;
  }
  double
  getMaximumRange () const
  {
    return max_range_;
  }

  /** \brief Range noise sigma(r) = sigma + per_metre * r, metres (defaults 0.005 and
   * 0). */
  void
  setRangeNoise (double sigma, double per_metre = 0.0)
  {
    noise_sigma_ = sigma;
    noise_per_metre_ = per_metre;
  }
  double
  getRangeNoise () const
  {
    return noise_sigma_;
  }

  /** \brief Largest incidence angle (degrees from the normal) that still returns
   * (default 88). */
  void
  setMaximumIncidence (double degrees)
  {
    max_incidence_deg_ = degrees;
  }

  /** \brief Distance (m) to a crease or border under which a point is Edge or Boundary;
   * 0 (default) uses the local scan spacing range * step. */
  void
  setEdgeDistance (double distance)
  {
    edge_distance_ = distance;
  }
  double
  getEdgeDistance () const
  {
    return edge_distance_;
  }

  /** \brief Mark the borders of the scanned part of each surface (shadows, silhouettes,
   * field of view, range, creases whose other face was not seen) as Boundary, besides
   * the borders of the surfaces themselves (default true). */
  void
  setCoverageBoundaries (bool enable)
  {
    coverage_boundaries_ = enable;
  }
  bool
  getCoverageBoundaries () const
  {
    return coverage_boundaries_;
  }

  /** \brief One segment id per connected visible piece of a surface (default true), or
   * one per surface (false: the ids of the scene's surfaces, as built). A region-based
   * segmentation can only find connected pieces, so they are what its ground truth
   * should hold; the object id is never split. See the class description for the
   * connection test. */
  void
  setConnectedSegments (bool enable)
  {
    connected_segments_ = enable;
  }
  bool
  getConnectedSegments () const
  {
    return connected_segments_;
  }

  /** \brief Seed of the random numbers (default 1). */
  void
  setSeed (std::uint64_t seed)
  {
    seed_ = seed;
  }

  /** \brief Rigid transform applied to the measured points before they are stored as
   * floats (a pose, or a large offset to mimic georeferenced coordinates); identity by
   * default. */
  void
  setOutputTransform (const Eigen::Isometry3d& transform)
  {
    output_transform_ = transform;
  }

  /** \brief Threads (0 = all cores, the default). */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }

  /** \brief Scan \a geometry (built) from every position.
   * \param[out] cloud the returns, ordered by scanner, azimuth and elevation
   * \param[out] scanner_of_point when not null, the index of the position of each point
   * \param[out] surface_of_segment when not null, indexed by segment id: the id of the
   *             scene surface the segment is a piece of (the identity without connected
   *             segments); index 0 is unused
   * \return false (with an error) on invalid parameters; \a cloud is then empty */
  bool
  scan (const SceneGeometry& geometry,
        pcl::PointCloud<SimulatedPoint>& cloud,
        std::vector<std::uint16_t>* scanner_of_point = nullptr,
        std::vector<std::uint32_t>* surface_of_segment = nullptr) const;

  /** \brief Number of returns a scan at \a step_deg would produce (no attributes
   * computed). */
  std::size_t
  countReturns (const SceneGeometry& geometry, double step_deg) const;

  /** \brief Angular step (degrees) whose scan produces about \a points returns, found
   * by counting coarser scans and scaling by sqrt(count / points) (returns grow as 1 /
   * step^2); typically within 2 % of the target. 0 when the scene returns nothing. */
  double
  stepForPointCount (const SceneGeometry& geometry, std::size_t points) const;

  /** \brief Whether the parameters are valid; prints a PCL_ERROR naming the bad one. */
  bool
  checkParameters () const;

private:
  struct ColumnRange {
    long first = 0; ///< first azimuth index (may exceed the column count: wrap around)
    long count = 0; ///< number of columns
  };
  ColumnRange
  columnRange (const Vec3& origin,
               const Aabb& box,
               double step_rad,
               long num_columns) const;
  void
  elevationRange (const Vec3& origin,
                  const Aabb& box,
                  double step_rad,
                  long& j_min,
                  long& j_max) const;
  template <typename Visitor>
  void
  traceColumns (const SceneGeometry& geometry, double step_deg, Visitor&& visit) const;

  std::vector<Vec3> positions_;
  double step_deg_ = 0.1;
  double min_elevation_deg_ = -60.0;
  double max_elevation_deg_ = 90.0;
  double max_range_ = 150.0;
  double noise_sigma_ = 0.005;
  double noise_per_metre_ = 0.0;
  double max_incidence_deg_ = 88.0;
  double edge_distance_ = 0.0;
  bool coverage_boundaries_ = true;
  bool connected_segments_ = true;
  std::uint64_t seed_ = 1;
  Eigen::Isometry3d output_transform_ = Eigen::Isometry3d::Identity();
  unsigned int threads_ = 0;
};
} // namespace simulation
} // namespace pcl_ext
