/*
 * pcl_ext: the range noise and the point spacing of a cloud, estimated from the
 * eigenvalues of its neighbourhoods.
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pcl_ext {
/** \brief The eigenvalues of one neighbourhood's covariance (divided by n), ascending,
 * and the number of points in it. */
struct NeighbourhoodSpread {
  Eigen::Vector3d values = Eigen::Vector3d::Zero(); ///< l0 <= l1 <= l2
  std::size_t size = 0;                             ///< points in the neighbourhood
};

/** \brief What estimateNoiseAndSpacing found. */
struct NoiseEstimate {
  /** \brief False when the cloud does not let the noise be estimated (\a reason says
   * why); sigma and spacing are then NaN. */
  bool valid = false;
  /** \brief Standard deviation of the points about their surface, along its normal
   * (for a scanner: the range noise projected on the normal), in the cloud's units. */
  double sigma = std::numeric_limits<double>::quiet_NaN();
  /** \brief Typical distance between neighbouring points on a surface. */
  double spacing = std::numeric_limits<double>::quiet_NaN();
  /** \brief Median curvature l0 / (l0 + l1 + l2) of the neighbourhoods used. */
  double flat_curvature = std::numeric_limits<double>::quiet_NaN();
  /** \brief Neighbourhoods the estimate comes from (the flattest share). */
  std::size_t used = 0;
  /** \brief Why the estimate is not valid; empty when it is. */
  std::string reason;
};

/** \brief Fewest usable neighbourhoods estimateNoiseAndSpacing needs. */
constexpr std::size_t kMinNoiseNeighbourhoods = 100;

/** \brief Largest median curvature of the flattest neighbourhoods for which the noise
 * is estimated: above it (the noise reaches about a quarter of the neighbourhood's
 * radius) the flattest neighbourhoods show no surface to measure the noise about. */
constexpr double kMaxFlatCurvature = 1.0 / 30.0;

/** \brief Estimates the noise about the surfaces and the point spacing of a cloud from
 * the eigenvalues of its neighbourhoods (any sample of them).
 *
 * On a smooth surface sampled with spacing s and noise sigma along the normal, the
 * smallest eigenvalue l0 of a neighbourhood of n points is about sigma^2 (n - 3) / n
 * (the plane fitted through the points takes 3 degrees of freedom), and its two
 * others describe a disc of radius r, l1 + l2 = r^2 / 2, with pi r^2 = n s^2. Most
 * neighbourhoods of a scan lie on surfaces; those across a crease, a border or a
 * curved surface have a larger curvature l0 / (l0 + l1 + l2). So the estimate uses the
 * flattest share of the neighbourhoods (by curvature, \a flat_share of them) and takes
 * - sigma^2 = the median of l0 n / (n - 3) over them,
 * - s = the median of sqrt(2 pi (l1 + l2) / n) over them.
 * Choosing by curvature prefers the neighbourhoods whose l0 happens to be low, so sigma
 * comes out a few per cent low on a plane (about 7 % at n = 50, flat_share 0.5).
 *
 * Not valid (reason given) with fewer than kMinNoiseNeighbourhoods usable
 * neighbourhoods (finite, at least 4 points, l1 + l2 > 0) or when the median curvature
 * of the flattest share exceeds kMaxFlatCurvature.
 *
 * \param[in] spreads the eigenvalues and sizes of the neighbourhoods
 * \param[in] flat_share the share of the usable neighbourhoods, flattest first, that
 * the estimate uses; in (0, 1]
 */
NoiseEstimate
estimateNoiseAndSpacing (const std::vector<NeighbourhoodSpread>& spreads,
                         double flat_share = 0.5);
} // namespace pcl_ext
