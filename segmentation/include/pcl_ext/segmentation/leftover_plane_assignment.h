/*
 * pcl_ext: the points a segmentation left out put into the neighbouring segment whose
 * local plane they lie on.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_options.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace pcl_ext {
/** \brief Each point still without a segment joins the neighbouring segment whose local
 * plane it lies on.
 *
 * Beyond D. Belton and D. D. Lichti, "Classification and segmentation of terrestrial
 * laser scanner point clouds using local variance information" (ISPRS Commission V
 * Symposium 2006): section 4 re-integrates the edge and boundary points that fit the
 * local plane of a segment within the circles of the local intersections (eq. 9-17);
 * the points it leaves, a patch's rim on a sparse surface, the ends of scan lines, are
 * then in no segment although they lie on one. Here, for every point without a segment
 * (label 0), each segment with a point among its getCandidateK() nearest neighbours is
 * a candidate; the candidate's points among the point's whole neighbourhood row give a
 * local plane (at least 5 points, not a line: middle eigenvalue at least 5 % of the
 * largest), and the point joins the candidate whose plane it lies closest to in units
 * of that plane's RMS residual, when within getDistanceFactor() of them (default 3).
 * Each point is decided from the input labels alone (no chain of assignments), so the
 * result does not depend on the order or the thread count.
 *
 * Inputs: the segment label of every point (0: none) and neighbourhoods, searched or
 * shared (rows closest first, of the points without a segment). Output: the labels,
 * with the points assigned. Bad input (no cloud, an empty one, labels of the wrong
 * size, indices out of range, parameters out of range): PCL_ERROR and empty output.
 *
 * \code
 * pcl_ext::LeftoverPlaneAssignment<pcl::PointXYZ> assignment;
 * assignment.setInputCloud (cloud);
 * assignment.setNeighbourhoods (nb);     // the segmentation's own, or none: searched
 * assignment.setSegmentLabels (labels);  // e.g. CoplanarSegmentMerging's output
 * pcl::PointCloud<pcl::Label> assigned;
 * assignment.compute (assigned);
 * \endcode
 */
template <typename PointT>
class LeftoverPlaneAssignment : public pcl::PCLBase<PointT>,
                                public NeighbourhoodOptions<PointT> {
public:
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;

  /** \brief The fewest points of a segment in a neighbourhood to fit its local plane.
   */
  static constexpr std::size_t kMinPlanePoints = 5;

  /** \brief What compute() did. */
  struct Report {
    std::size_t examined = 0; ///< finite points without a segment
    std::size_t assigned = 0; ///< of them, put into a segment
  };

  /** \brief The segment of every point of the input cloud (0: none). Required. */
  void
  setSegmentLabels (const LabelCloudConstPtr& labels)
  {
    segments_ = labels;
  }

  LabelCloudConstPtr
  getSegmentLabels () const
  {
    return segments_;
  }

  /** \brief The nearest neighbours (the point excluded) whose segments are the
   * candidates (default 12, fewer where a row is shorter). */
  void
  setCandidateK (int k)
  {
    candidate_k_ = k;
  }

  int
  getCandidateK () const
  {
    return candidate_k_;
  }

  /** \brief The largest distance from a candidate's local plane, in units of the
   * plane's RMS residual (default 3). */
  void
  setDistanceFactor (double factor)
  {
    distance_factor_ = factor;
  }

  double
  getDistanceFactor () const
  {
    return distance_factor_;
  }

  /** \brief Assign. \a output gets one label per input point: the input's, or the
   * segment a point without one joins. On bad input: PCL_ERROR, empty output, false. */
  bool
  compute (LabelCloud& output);

  const Report&
  getReport () const
  {
    return report_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  bool
  checkInputs (const char* name) const;

  LabelCloudConstPtr segments_;
  int candidate_k_ = 12;
  double distance_factor_ = 3.0;
  Report report_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/leftover_plane_assignment.hpp>
#endif
