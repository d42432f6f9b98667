/*
 * pcl_ext: segments that are one plane's interleaved pieces merged.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/segmentation/segment_contacts.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace pcl_ext {
/** \brief Merges the segments that are pieces of one plane lying among each other.
 *
 * Beyond D. Belton and D. D. Lichti, "Classification and segmentation of terrestrial
 * laser scanner point clouds using local variance information" (ISPRS Commission V
 * Symposium 2006), in the spirit of its section 3 ("a surface may be fitted to groups"
 * of points): on a sparse plane scanned from several stations or at
 * a grazing angle, the points are far from a uniform sampling (dense scan lines far
 * apart, two scans' grids mixed), so that eq. 6 calls many of its points boundary
 * points; the growth of section 3 stops at them, and the plane comes out as several
 * segments whose points are interleaved (a scan line's or a station's points a
 * segment); section 4's re-integration and the new segments among the points left out
 * (pcl_ext::LeftoverRegionGrowing) keep them apart. Two segments are merged when
 * (pcl_ext::CoplanarMergeCriteria) a quarter or more of the smaller one's points have a
 * point of the other among their nearest neighbours (interleaved, not two surfaces
 * meeting along a border, where only the border's points do), the smaller one's points
 * lie on the larger one's plane within twice their residuals, and, where the smaller
 * one is a plane rather than a line, the normals agree within 10 degrees; merged groups
 * are tested again as wholes (pcl_ext::mergeInterleavedCoplanarSegments).
 *
 * Inputs: the segment label of every point (0: none) and neighbourhoods, searched or
 * shared (rows closest first; the first getContactK() of a row are read, the point
 * itself skipped). Output: the labels with each group of merged segments under its
 * smallest label, then renumbered 1, 2, ... in their order. The same result in every
 * run and for any thread count. accumulate() gives the sums of a part of the cloud (a
 * tile's own points), whose total over the parts decides the same merges.
 *
 * Bad input (no cloud, an empty one, labels of the wrong size, indices out of range,
 * parameters out of range) gives a PCL_ERROR and an empty output.
 *
 * \code
 * pcl_ext::CoplanarSegmentMerging<pcl::PointXYZ> merging;
 * merging.setInputCloud (cloud);
 * merging.setNeighbourhoods (nb);      // the segmentation's own, or none: searched
 * merging.setSegmentLabels (labels);   // e.g. LeftoverRegionGrowing's output
 * pcl::PointCloud<pcl::Label> merged;
 * merging.compute (merged);
 * \endcode
 */
template <typename PointT>
class CoplanarSegmentMerging : public pcl::PCLBase<PointT>,
                               public NeighbourhoodOptions<PointT> {
public:
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;

  /** \brief What compute() did. */
  struct Report {
    std::size_t segments = 0; ///< segments in the input
    std::size_t merges = 0;   ///< pairs that met the criteria
    std::size_t result = 0;   ///< segments in the output
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

  /** \brief The nearest neighbours of a point (itself excluded) among which the other
   * segments' points are looked for (default 20, fewer where a row is shorter). */
  void
  setContactK (int k)
  {
    contact_k_ = k;
  }

  int
  getContactK () const
  {
    return contact_k_;
  }

  /** \brief When two segments are merged (pcl_ext::CoplanarMergeCriteria's defaults).
   */
  void
  setCriteria (const CoplanarMergeCriteria& criteria)
  {
    criteria_ = criteria;
  }

  const CoplanarMergeCriteria&
  getCriteria () const
  {
    return criteria_;
  }

  /** \brief Add the plane sums and contacts of the points \a linking (null: every
   * indexed point) to \a contacts: what compute() merges by, for one part of a cloud.
   * On bad input: PCL_ERROR, false. */
  bool
  accumulate (SegmentContacts& contacts, const pcl::IndicesConstPtr& linking = nullptr);

  /** \brief Merge. \a output gets one label per input point. On bad input:
   * PCL_ERROR, empty output, false. */
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
  checkInputs (const char* name, const pcl::Indices* linking) const;

  LabelCloudConstPtr segments_;
  int contact_k_ = 20;
  CoplanarMergeCriteria criteria_;
  Report report_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/coplanar_segment_merging.hpp>
#endif
