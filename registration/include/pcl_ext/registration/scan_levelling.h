/*
 * pcl_ext: the vertical direction of a building scan from its planes, for scans that
 * are not levelled (Khoshelham & Gorte 2009 assume a levelled scanner).
 */
#pragma once

#include <pcl_ext/common/plane.h>
#include <pcl_ext/registration/plane_transformation_estimation.h>

#include <Eigen/Core>

#include <vector>

namespace pcl_ext {
/** \brief The largest tilt of a scan's z axis that estimateUpDirection considers by
 * default (degrees). */
constexpr double kMaxLevellingTiltDeg = 20.0;

/** \brief The up direction of a scan from its planes: horizontal planes (ground,
 * floors, roofs, ceilings) have it as normal and walls are perpendicular to it.
 *
 * Khoshelham & Gorte's constraint 1 (section 3.3) rests on a levelled scanner; a scan
 * tilted by a few degrees (an unlevelled tripod, a mobile or hand-held scan) breaks it.
 * Each plane normal within \a max_tilt_deg of the scan's z axis, and the common
 * perpendicular of every two planes 30 degrees or more apart, is a hypothesis; a
 * hypothesis is scored by the supporting points of the planes it makes horizontal or
 * vertical within \a tolerance_deg. The best is refined: the up direction maximises
 * sum_h w (n . u)^2 + sum_v w (1 - (n . u)^2) over its horizontal (h) and vertical (v)
 * planes, w their sizes (the largest eigenvector of sum_h w n n^T + sum_v w (I - n
 * n^T)), twice, re-classifying the planes in between. Without a horizontal plane, the
 * walls' common perpendicular is the same eigenvector.
 * \param[in] planes the scan planes (normals, sizes)
 * \param[out] up unit up direction in the scan frame, z >= 0; (0, 0, 1) when false
 * \param[in] max_tilt_deg largest tilt of the scan's z axis considered, (0, 90)
 * \param[in] tolerance_deg how far from horizontal or vertical a plane may be to
 * count, (0, 45)
 * \return false (no PCL_ERROR: the caller keeps z) when no plane supports a direction
 * or the walls do not span two horizontal directions without a horizontal plane */
bool
estimateUpDirection (const std::vector<Plane>& planes,
                     Eigen::Vector3d& up,
                     double max_tilt_deg = kMaxLevellingTiltDeg,
                     double tolerance_deg = 2.0);

/** \brief The normal of a large, nearly level plane (the ground) as the mean normal of
 * its flat patches, for the levelling.
 *
 * The ground of a town is level pieces (streets, pavements, squares) joined by kerbs,
 * steps and ramps. One plane fitted through all of it leans towards the higher side by
 * what the steps add up to (docs/khoshelham_gorte.md has the figures of the AHN
 * tiles); the pieces themselves are level. The plane's points are
 * binned in cells of its own frame, \a cells_across along the larger side of their
 * extent; each cell of 8 points or more is fitted by least squares (height along \a
 * plane's normal over the plane's axes), the cells whose RMS exceeds 3 times the median
 * cell's (steps, kerbs, clutter) are left out, and the mean of the others' normals,
 * each cell one vote (area, not density, counts), is the result. A plane whose RMS is
 * at most twice the median cell's is even at its own scale (a floor, a paved yard with
 * noise): its fit is the better estimate and is kept; so is the fit of a plane whose
 * patches lean from it by less than 0.1 degrees, the order of the patches' own error
 * (cells of a few points, range noise at grazing angles).
 * \param[in] points the plane's inliers
 * \param[in] plane_normal the fitted plane's unit normal
 * \param[out] normal the mean patch normal, on \a plane_normal's side
 * \param[in] cells_across cells along the larger side, >= 2; default 32
 * \return false (\a normal = \a plane_normal) for an even plane, patches leaning by
 * less than 0.1 degrees, or fewer than 8 flat cells */
bool
estimateFlatPatchNormal (const std::vector<Eigen::Vector3d>& points,
                         const Eigen::Vector3d& plane_normal,
                         Eigen::Vector3d& normal,
                         int cells_across = 32);

/** \brief The smallest rotation taking \a up to (0, 0, 1), as a 4 x 4 transform. */
Eigen::Matrix4d
levellingTransform (const Eigen::Vector3d& up);

/** \brief Keeps the vertical of a levelled scan: the rigid \a estimate of levelled scan
 * planes to map planes (Khoshelham & Gorte 2009, eq. 12, whose map is vertical along z)
 * is replaced by the rotation about z nearest to its rotation, and the translation
 * re-fitted by least squares to the matched pairs at the scan planes' centroids: n_m .
 * (R c_s + t) + d_m = 0 for every pair. The levelling comes from every horizontal and
 * vertical plane of the scan (estimateUpDirection, weighted by size); the estimate's
 * tilt from a handful of matched planes, where walls with a thin band of points (roof
 * outlines of an airborne scan, section 3.1 with airborne data) are tilted by a few
 * degrees. The translation keeps the estimate's value along any direction the matched
 * map normals do not span. Residuals are recomputed.
 * \param[in] scan the levelled scan planes
 * \param[in] map the map planes
 * \param[in] matches the matched pairs
 * \param[in,out] estimate a valid rigid estimate (scale 1); left as it is otherwise
 * \return false when the estimate is left as it is */
bool
refineAboutVertical (const std::vector<Plane>& scan,
                     const std::vector<Plane>& map,
                     const std::vector<PlanePair>& matches,
                     PlaneTransformationResult& estimate);
} // namespace pcl_ext
