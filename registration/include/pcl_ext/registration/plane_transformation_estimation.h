/*
 * pcl_ext: the linear plane-to-plane transformation estimate of Khoshelham & Gorte
 * (2009), section 3.2, eqs. 8-12.
 */
#pragma once

#include <pcl_ext/registration/planes.h>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief Which transform the linear estimate is projected onto. */
enum class PlaneTransformationModel {
  Rigid,      ///< rotation and translation (s = 1): the default
  Similarity, ///< rotation, translation and scale (eq. 5)
};

/** \brief A correspondence: scan plane index, map plane index, and the sign s (+1 or
 * -1) by which the scan plane is multiplied so that the pair agrees ((n, d) and (-n,
 * -d) are the same plane: an extracted plane has no natural sign). */
struct PlanePair {
  int scan = 0;
  int map = 0;
  int sign = 1;
};

/** \brief Result of estimatePlaneTransformation. */
struct PlaneTransformationResult {
  bool valid = false;      ///< false: degenerate (see degenerate) or too few pairs
  bool degenerate = false; ///< the map normals do not span 3D (or scale unobservable)
  Eigen::Matrix<double, 3, 4> affine =
      Eigen::Matrix<double, 3, 4>::Zero(); ///< eq. 12, H rows 1-3
  Eigen::Matrix4d transformation =
      Eigen::Matrix4d::Identity(); ///< projected, scan to map
  double scale = 1.0;              ///< s of eq. 5 (1 for a rigid transform)
  double conditioning =
      0.0; ///< smallest / largest eigenvalue of sum n n^T (map normals), [0, 1]
  std::vector<double>
      angle_residuals; ///< per pair: angle between R n_s and s_i n_m (rad)
  /** \brief Per pair: distance of the transformed scan centroid to the map plane (m).
   * Eq. 10's fourth row measures the offset at the origin instead, where any angle
   * error is multiplied by the distance to the data; this is the figure tolerances are
   * checked against. */
  std::vector<double> distance_residuals;
  /** \brief sqrt(mean (|n_s - R^T n_m|^2 + distance^2)): eq. 8's residual norm for the
   * projected H, its offset part measured at the data (see distance_residuals). */
  double residual_norm = 0.0;
  double max_angle = 0.0;    ///< largest angle residual (rad)
  double max_distance = 0.0; ///< largest distance residual (m)
};

/** \brief Estimate the scan-to-map transform from plane correspondences (Khoshelham &
 * Gorte 2009, section 3.2).
 *
 * Eq. 10 stacks pi_m^T [h1 h2 h3 | 0 0 0 1] = pi_s^T for every pair into A X = B (eq.
 * 11), whose least-squares solution is eq. 12. Because A_i = n_m^T (x) I_4, the normal
 * equations factor: A^T A = (sum n_m n_m^T) (x) I_4, so eq. 12 reduces to [h1 h2 h3] =
 * (sum b_i n_m,i^T) (sum n_m n_m^T)^-1 with b_i the right-hand side of eq. 10: the same
 * numbers without a 12 x 12 solve. This is the general affine block the paper
 * estimates.
 *
 * Departure from the text: the transform sought is a similarity (eq. 5) or a rigid one,
 * which the affine block of eq. 12 is not, so the block is projected onto a rigid or
 * similarity transform before use. The rotation is the nearest rotation to the 3 x 3
 * block (SVD, determinant +1); the translation (and for a similarity the scale) then
 * solve the distance part of eq. 10 by least squares, written at a point c of each scan
 * plane (its centroid projected onto it): n_m . (s R c + t) = d_m. With c = d_s n_s (no
 * centroid known) this is eq. 10's fourth row; at the data, an angle error is not
 * multiplied by the distance from the scan origin to the building (up to 100 m in the
 * tests). Residuals are those of the projected transform, the offset ones measured at
 * the same points.
 *
 * Degenerate configurations are reported, not solved: fewer than 3 pairs (4 for a
 * similarity), map normals that do not span 3D (all walls parallel, or walls without
 * the floor), i.e. conditioning below \a min_conditioning.
 *
 * \param[in] scan scan planes (source)
 * \param[in] map map planes (target)
 * \param[in] pairs the correspondences; sign multiplies the scan plane
 * \param[in] model rigid (default) or similarity
 * \param[out] result the estimate and its residuals
 * \param[in] min_conditioning smallest accepted conditioning, default 1e-3 (a normal
 * set spread within about 2 degrees of a plane is degenerate) \return result.valid
 */
bool
estimatePlaneTransformation (const std::vector<Plane>& scan,
                             const std::vector<Plane>& map,
                             const std::vector<PlanePair>& pairs,
                             PlaneTransformationModel model,
                             PlaneTransformationResult& result,
                             double min_conditioning = 1e-3);

/** \brief The same on arrays of pointers: the matcher's inner loop, which asks for the
 * per-pair residual vectors (\a per_pair) only for the final match set; the maxima and
 * the norm are always computed. */
bool
estimatePlaneTransformation (const Plane* const* scan,
                             const Plane* const* map,
                             const int* signs,
                             int count,
                             PlaneTransformationModel model,
                             PlaneTransformationResult& result,
                             double min_conditioning,
                             bool per_pair = true);
} // namespace pcl_ext
