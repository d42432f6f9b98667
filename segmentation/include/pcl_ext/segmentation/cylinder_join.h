/*
 * pcl_ext: joining the segments of one cylinder, on plain coordinates.
 */
#pragma once

#include <pcl_ext/segmentation/cylinders.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl_ext {
namespace cylinder_join {
/** \brief Everything the join needs; see CylinderSegmentJoin for the meaning and
 * defaults. */
struct JoinParameters {
  cylinders::DetectionParameters detection;
  double max_gap = 2.0; ///< longest gap bridged along an axis or to an elbow
  double max_axis_angle = M_PI / 36.0; ///< radians (5 degrees): one straight run
  double min_elbow_angle = M_PI / 6.0; ///< radians (30 degrees): two legs of an elbow
  double max_radius_difference = 0.3;  ///< share of the larger radius
  double max_axis_offset = 0.3;        ///< in radii, plus the distance tolerance
  double whole_segment_fraction = 0.5;
  double absorb_fraction =
      0.5; ///< 0: off; else the share of a pieceless segment on a group
  unsigned int threads = 1;
};

constexpr std::uint32_t kNoSegment = std::numeric_limits<std::uint32_t>::max();

/** \brief A cylinder found in an input segment. */
struct Piece {
  std::uint32_t segment = 0; ///< the input segment it was found in
  std::uint32_t joined =
      kNoSegment; ///< output segment of its group; kNoSegment if alone
  /** \brief Inliers as positions in the coordinates; a piece of a straight run of
   * joined pieces has the run's axis, radius and taper (fitted to all the run's
   * inliers), its point and half-length being its own extent along that axis. */
  cylinders::Cylinder cylinder;
};

/** \brief The joined segmentation. */
struct JoinResult {
  std::vector<Piece> pieces; ///< in segment order, then the order found
  std::vector<std::uint32_t>
      labels; ///< output segment of each point; kNoSegment if none
  std::size_t num_segments = 0;
};

/** \brief The points of the segments to join, one segment at a time: held in memory,
 * or read from disk by a caller that cannot hold the cloud (pcl_ext_tiles). */
class SegmentSource {
public:
  virtual ~SegmentSource() = default;

  /** \brief The number of segments. */
  virtual std::size_t
  size () const = 0;

  /** \brief The number of points of segment \a s. */
  virtual std::size_t
  pointCount (std::size_t s) const = 0;

  /** \brief The coordinates of segment \a s's points, in their order, best centred near
   * the origin; called from several threads at once. \return false on a failure (which
   * the source reports) */
  virtual bool
  load (std::size_t s, std::vector<Eigen::Vector3d>& points) const = 0;
};

/** \brief The join over a SegmentSource, per segment rather than per point. */
struct SegmentJoin {
  /** \brief In segment order, then the order found; a piece's inliers are indices into
   * its segment's points, and \a joined the label of its group (numbered from the
   * number of segments on) or kNoSegment. */
  std::vector<Piece> pieces;
  /** \brief Per segment, the label all its points take (its pieces' group, or the
   * group it lies on); kNoSegment where it keeps its own label (its index) but for the
   * inliers of its pieces in a group, which take the group's label. */
  std::vector<std::uint32_t> whole;
  std::uint32_t labels = 0; ///< segments plus groups: every label is below
};

/** \brief Check \a p; false when a value is out of range. */
bool
validParameters (const JoinParameters& p);

/** \brief Whether two cylinders continue one another: one straight run (axes parallel,
 * each end's axis through the other's facing end, a gap no longer than the maximum) or
 * the two legs of an elbow (axes meeting near both ends); radii agreeing in both cases.
 */
bool
continues (const cylinders::Cylinder& a,
           const cylinders::Cylinder& b,
           const JoinParameters& p);

/** \brief Find the cylinders of every segment (in parallel; the result does not depend
 * on the thread count), join those that continue one another, refit each straight run
 * of joined pieces as one cylinder (or cone) over all their inliers (the pieces then
 * carry the run's axis, radius and taper over their own extent; a short strip seen from
 * one side fixes its radius poorly), and relabel: a segment
 * whose pieces all joined one group, and cover at least the whole-segment fraction of
 * it, moves to that group whole; otherwise only its pieces' points move. \param[in] xyz
 * finite coordinates, best centred near the origin \param[in] segments positions in \a
 * xyz; a position in no segment, or in an earlier one, keeps the label it has
 * (kNoSegment or the earlier segment's) \return false when a parameter is invalid or a
 * position is out of range */
/** \brief What joinCylinderSegments does, over segments that a source loads one at a
 * time (at most one per thread), so that the cloud need not be held: the segments'
 * cylinders, the groups and straight runs, and the labels per segment (see
 * SegmentJoin). Positions in the order of joinCylinderSegments are the segments' points
 * one segment after the other, and the result is the same. \return false when a
 * parameter is invalid or the source fails */
bool
joinSegments (const SegmentSource& source,
              const JoinParameters& p,
              SegmentJoin& result);

bool
joinCylinderSegments (const std::vector<Eigen::Vector3d>& xyz,
                      const std::vector<std::vector<std::uint32_t>>& segments,
                      const JoinParameters& p,
                      JoinResult& result);
} // namespace cylinder_join
} // namespace pcl_ext
