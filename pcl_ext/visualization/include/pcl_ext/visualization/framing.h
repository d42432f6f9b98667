/*
 * pcl_ext: where the camera of a picture looks from, and what it frames.
 */
#pragma once

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace pcl_ext {
namespace visualization {
/** \brief The direction a picture is seen from. */
enum class ViewKind {
  Auto,    ///< from the data: Sensor when the sensor is known, else Oblique
  Top,     ///< straight down along the up direction
  Side,    ///< horizontally, across the cloud's longer horizontal axis
  Oblique, ///< from above and the side (35 degrees of elevation)
  Sensor   ///< from the scanner's position towards the cloud
};

/** \brief Parses "auto", "top", "side", "oblique" or "sensor"; false for anything else.
 */
bool
parseViewKind (const std::string& text, ViewKind& kind);

/** \brief The name parseViewKind reads. */
std::string
viewKindName (ViewKind kind);

/** \brief An orthographic camera: it looks along \a direction at \a centre with \a up
 * pointing to the top of the picture, and the frame spans \a half_width x \a
 * half_height (world units) about \a centre. */
struct Framing {
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double half_width = 1.0;
  double half_height = 1.0;
};

/** \brief The viewing direction of \a kind for \a points (finite), with \a up the
 * scene's up direction (unit length) and \a sensor the scanner's position (NaN when
 * unknown; Sensor then falls back to Oblique). Side and Oblique look across the longer
 * axis of the points' horizontal spread, so a long building is seen along its length,
 * from the sensor's side when it is known, else from the side where the lowest fifth of
 * the points lies, beyond the highest fifth, by more than a tenth of the extent (the
 * ground a scan saw in front of what stands on it), else from a fixed side. Sensor
 * looks from the sensor at the points' median. */
Eigen::Vector3d
viewDirection (const std::vector<Eigen::Vector3d>& points,
               ViewKind kind,
               const Eigen::Vector3d& up,
               const Eigen::Vector3d& sensor);

/** \brief Frames \a points seen along \a direction (camera up \a up, made orthogonal to
 * it) in a frame of aspect \a aspect (width / height).
 *
 * The frame holds the robust bounds of the points projected on the picture plane: the
 * 1st to 99th percentile per axis of the points of the dense parts, widened to take in
 * every point within half the larger of the two percentile ranges of that box (the
 * subject's own thin or sparse parts: a mast on a plate, the near ground of a scan).
 * The dense parts are the points of the cells of a 48 x 48 grid over the 1st to 99th
 * percentile box of all points that hold at least a tenth of the count of the median
 * point's cell (all points when that would leave out half of them), so that far, sparse
 * parts (the far rings of a scanner's ground, stray returns) do not shrink the subject:
 * they fall outside the frame. A \a margin (a fraction of the frame on each side) keeps
 * the subject off the edges. Empty \a points give the default Framing. */
Framing
frameRobustly (const std::vector<Eigen::Vector3d>& points,
               const Eigen::Vector3d& direction,
               const Eigen::Vector3d& up,
               double aspect,
               double margin = 0.05);

/** \brief The height (along \a up) just below a ceiling, or +infinity when there is
 * none.
 *
 * A ceiling is a thin layer of points at the top of the height range (in its upper
 * fifth) that covers most (at least three fifths) of the cloud's horizontal footprint,
 * so that any view from above would show only it, in a cloud whose height range is at
 * least a twentieth of its horizontal extent. Heights are binned in 64 bins; the
 * layer is the highest bin holding at least four times the median bin's count. */
double
estimateCeilingHeight (const std::vector<Eigen::Vector3d>& points,
                       const Eigen::Vector3d& up);

/** \brief The median distance from a point to its nearest neighbour, from up to 2000
 * points spread over \a points (every point is a candidate neighbour); NaN for fewer
 * than 2 points. */
double
estimateSpacing (const std::vector<Eigen::Vector3d>& points);
} // namespace visualization
} // namespace pcl_ext
