/*
 * pcl_ext: registration accuracy against a known transform (Khoshelham & Gorte 2009,
 * section 4). The distances between the matched planes of Tables 1-2 need no truth: the
 * registration measures them itself (pcl_ext/registration/plane_distances.h).
 */
#pragma once

#include <Eigen/Core>

namespace pcl_ext {
/** \brief Difference between an estimated and a true rigid (or similarity) transform.
 */
struct TransformationError {
  double rotation_deg =
      0.0;                  ///< angle of the relative rotation, in degrees, in [0, 180]
  double translation = 0.0; ///< distance between the two images of the reference point
  double scale_ratio = 1.0; ///< estimated scale / true scale (1 for rigid transforms)
};

/** \brief Angle of a rotation matrix in degrees, in [0, 180].
 *
 * Computed as atan2(|vee(R - R^T)| / 2, (trace R - 1) / 2), which stays accurate for
 * angles near 0 and 180 degrees where acos((trace R - 1) / 2) loses digits. \a rotation
 * is made orthonormal first (nearest rotation, by SVD), so a scaled rotation is
 * accepted.
 */
double
rotationAngleDegrees (const Eigen::Matrix3d& rotation);

/** \brief Rotation and translation error of \a estimated against \a truth.
 *
 * - rotation: the angle of R_est R_true^T (rotationAngleDegrees), where R is the
 * nearest rotation to the 3x3 block (polar decomposition by SVD), so a similarity's
 * scale does not leak into it;
 * - translation: |T_est c - T_true c| for the reference point c. With c = 0 (default)
 * this is |t_est - t_true|. Since a rotation error moves points in proportion to their
 * distance from the origin, pass the scan's centroid to measure the error where the
 * data is;
 * - scale ratio: ratio of the mean singular values of the two 3x3 blocks.
 * \param[in] estimated the estimated source-to-target transform (bottom row 0 0 0 1)
 * \param[in] truth the true source-to-target transform
 * \param[in] reference the point c, in source coordinates; default the origin
 */
TransformationError
computeTransformationError (const Eigen::Matrix4d& estimated,
                            const Eigen::Matrix4d& truth,
                            const Eigen::Vector3d& reference = Eigen::Vector3d::Zero());
} // namespace pcl_ext
