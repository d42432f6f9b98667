/*
 * pcl_ext: cylinders found in a set of points without normals (shared by the
 * segmenters).
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace cylinders {
/** \brief A cylinder and the points on its surface. */
struct Cylinder {
  Eigen::Vector3d point =
      Eigen::Vector3d::Zero(); ///< on the axis, mid-way along the inliers
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< unit direction
  double radius = 0.0;                             ///< at \a point
  double taper = 0.0; ///< change of the radius per unit length along \a axis (a cone)
  double half_length = 0.0; ///< the inliers span point +- half_length * axis
  double arc = 0.0;         ///< the angle (radians) the inliers span around the axis
  /** \brief Of the points within three tolerances of the surface or inside it (along
   * the inliers' extent), the share within one tolerance: close to 1 for a solid
   * cylinder seen from outside, lower for a surface a cylinder only cuts or touches (a
   * plane, the faces of a box). A pipe with another inside it (coaxial) fails. */
  double surface_fraction = 0.0;
  std::vector<std::uint32_t> inliers; ///< positions in the input points, ascending
};

/** \brief Settings of detectCylinders; lengths in the units of the points. */
struct DetectionParameters {
  double distance_tolerance = 0.015;    ///< inlier band around the surface (> 0)
  double min_radius = 0.02;             ///< (> 0)
  double max_radius = 0.6;              ///< (>= min_radius)
  double neighbourhood_radius = 0.6;    ///< the patch a hypothesis is drawn from (> 0)
  unsigned int hypotheses = 300;        ///< hypotheses drawn per cylinder (>= 1)
  unsigned int refined_hypotheses = 20; ///< the best ones grown and refined (>= 1)
  std::size_t min_points = 40;          ///< fewest inliers of a cylinder (>= 3)
  /** \brief Largest taper (radius change per unit length) fitted, in [0, 1): 0 fits
   * cylinders only; above, also cones (a tree trunk narrows upwards). Default 0.1. */
  double max_taper = 0.1;
  double min_surface_fraction = 0.9; ///< see Cylinder::surface_fraction, in [0, 1]
  unsigned int max_cylinders = 8;    ///< per call
  unsigned int max_failures = 2;     ///< searches without a cylinder before giving up
  std::uint64_t seed = 1; ///< the random draws (pcl_ext::RandomStream: same seed, same
                          ///< result with every standard library)
};

/** \brief Check \a p; false when a value is out of range. */
bool
validParameters (const DetectionParameters& p);

/** \brief Refine a cylinder to \a subset of \a points by Gauss-Newton on the geometric
 * distance |distance to axis - radius| (axis direction, axis position and radius; with
 * \a taper also the change of the radius along the axis, a cone).
 * \return false when the fit degenerates or \a subset has fewer than 6 points (the
 * inputs are then left as they were) */
bool
refineCylinder (const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& subset,
                Eigen::Vector3d& point,
                Eigen::Vector3d& axis,
                double& radius,
                double* taper = nullptr);

/** \brief Find cylinders one after another, each from the points the earlier ones left.
 *
 * No normals are needed. A hypothesis is drawn from the patch within the neighbourhood
 * radius of a random point: the patch's principal direction is the axis (a strip of a
 * cylinder is longest along it) and a circle through three of its points, across that
 * axis, gives centre and radius. Hypotheses are ranked by their patch (a point within
 * the tolerance counts 1, one within three tolerances -2, so planes, which such a
 * circle only touches, rank low); the best are grown along the axis (window doubled
 * each step, refined in 3D each time) over all points left, and the one the points fit
 * best (a truncated quadratic loss, MSAC, with half the tolerance as its band: of a
 * circle through the undersides of two pipes side by side and either pipe's own, the
 * points lie tighter on the latter) is kept if its inliers are at least as long as its
 * diameter, it passes the surface test (Cylinder::surface_fraction; points taken by an
 * earlier candidate that failed it still count) and its arc bows out of its chord by at
 * least the tolerance (else a plane explains the points as well: two scan rows of a
 * sparse plane fit a cylinder). \param[in] points coordinates, best centred near the
 * origin \param[out] cylinders in the order found; empty when none or the parameters
 * are invalid */
void
detectCylinders (const std::vector<Eigen::Vector3d>& points,
                 const DetectionParameters& p,
                 std::vector<Cylinder>& cylinders);
} // namespace cylinders
} // namespace pcl_ext
