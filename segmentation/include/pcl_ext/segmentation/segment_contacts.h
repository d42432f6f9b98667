/*
 * pcl_ext: the planes of segments and how closely they interleave, summed point by
 * point, and the merges they call for.
 */
#pragma once

#include <pcl_ext/common/covariance.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief Per segment, the sums of its points' coordinates (a plane fit without a
 * second pass); per ordered pair of segments (a, b), how many points of a have a point
 * of b among their nearest neighbours. Summed over any partition of the points (the
 * tiles of a cloud, the threads of a pass) and added together, they are those of the
 * whole cloud. Label 0 (no segment) is never recorded. */
class SegmentContacts {
public:
  /** \brief The plane sums of one segment: its points' running sums around a
   * reference point (pcl_ext::CovarianceSums), so that a segment far from the frame's
   * origin keeps its residuals in double precision. */
  using PlaneSums = CovarianceSums;

  /** \brief Add the sums of points of segment \a segment (> 0). */
  void
  addPoints (std::uint32_t segment, const PlaneSums& sums);

  /** \brief \a count points of \a from have a point of \a to among their nearest
   * neighbours. */
  void
  addContacts (std::uint32_t from, std::uint32_t to, std::size_t count);

  /** \brief Add the sums of another part of the cloud. */
  void
  add (const SegmentContacts& other);

  const std::map<std::uint32_t, PlaneSums>&
  planes () const
  {
    return planes_;
  }

  const std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t>&
  contacts () const
  {
    return contacts_;
  }

private:
  std::map<std::uint32_t, PlaneSums> planes_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> contacts_;
};

/** \brief When two segments are interleaved pieces of one plane
 * (pcl_ext::mergeInterleavedCoplanarSegments). */
struct CoplanarMergeCriteria {
  /** The smallest share of the smaller segment's points that have a point of the other
   * among their nearest neighbours (default 0.25): pieces whose points lie among each
   * other's, not two surfaces meeting along a border, where only a border's points do.
   */
  double min_contact_fraction = 0.25;
  /** The largest angle between the two planes' normals, in radians (default 10
   * degrees), where the smaller segment is a plane (not a line: its middle eigenvalue
   * at least 5 % of its largest). */
  double max_angle = 10.0 * 3.14159265358979323846 / 180.0;
  /** The largest RMS distance of the smaller segment's points from the larger one's
   * plane, as a multiple of the larger of their RMS residuals (default 2). */
  double distance_factor = 2.0;
};

/** \brief Which segments to merge, and under which labels.
 *
 * Agglomerative: the pair of (groups of) segments with the largest share of contacts
 * that meets \a criteria is merged first, and the groups' sums and contacts are then
 * those of their segments together, so a small piece lying between two surfaces joins
 * the one it is most a part of and does not chain them together. Ties go to the
 * smaller labels: the result is the same in every run and for any order in which the
 * sums were added.
 * \return (label, new label) for every segment of \a contacts, in label order: each
 * group of merged segments takes the smallest of their labels, and the labels left are
 * renumbered 1, 2, ... in their order (any labels, however large: only those in use
 * are stored)
 * \param[out] merges when not null, the number of merges */
std::vector<std::pair<std::uint32_t, std::uint32_t>>
mergeInterleavedCoplanarSegments (const SegmentContacts& contacts,
                                  const CoplanarMergeCriteria& criteria,
                                  std::size_t* merges = nullptr);
} // namespace pcl_ext
