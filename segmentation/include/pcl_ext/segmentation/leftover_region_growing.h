/*
 * pcl_ext: segments grown among the points a segmentation left out.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/segmentation/cluster_size_limits.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstddef>

namespace pcl_ext {
/** \brief New segments among the points a segmentation left without one: the pieces
 * that have no surface point to grow from.
 *
 * Belton & Lichti (2006) grow segments from surface points only (section 3) and
 * re-integrate edge and boundary points into the segments that exist (section 4, eq.
 * 9-17); the paper notes (section 3) that doorways and recesses drop out, too few of
 * their points being surface. Pipes of a few neighbourhood radii, door jambs, narrow
 * faces and sparse planes seen at a grazing angle are all edge or boundary points
 * under eq. 5 and 6 and stay unsegmented. This step goes beyond the paper: among the
 * points still without a segment (label 0), each is linked to those of its nearest
 * neighbours, also without one, whose normals differ from its own by less than the
 * angle threshold, and each connected group of at least the minimum size becomes a new
 * segment. The normals are fitted to the nearest few neighbours only (setNormalK), so
 * that they turn at a crease within a spacing or two rather than over a whole k = 50
 * neighbourhood, while on a smooth curved surface neighbouring normals differ by the
 * spacing over the radius of curvature. Points whose patch is not flat enough
 * (setMaxCurvature: on a crease) link nothing themselves, so that no chain of slowly
 * turning normals crosses a crease; each joins the group of its flat neighbour of the
 * closest normal within the angle.
 *
 * Inputs: the segment label of every point of the cloud (any segmentation; 0: none).
 * Neighbourhoods are searched once for the whole cloud or shared through
 * setNeighbourhoods (rows closest first; shared rows of only the points without a
 * segment will do, the only rows read); the first getNormalK() of each row give the
 * normal and the links. Output: the input labels, with the new segments numbered after
 * the largest input label by decreasing size (ties: the smallest point index first).
 * Deterministic: the groups are the connected components of a symmetric link test.
 */
template <typename PointT>
class LeftoverRegionGrowing : public pcl::PCLBase<PointT>,
                              public NeighbourhoodOptions<PointT>,
                              public ClusterSizeLimits {
public:
  using Ptr = pcl::shared_ptr<LeftoverRegionGrowing<PointT>>;
  using ConstPtr = pcl::shared_ptr<const LeftoverRegionGrowing<PointT>>;
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;

  /** \brief What compute() did. */
  struct Report {
    std::size_t examined = 0;  ///< finite points without a segment
    std::size_t segments = 0;  ///< new segments
    std::size_t segmented = 0; ///< points put into them
  };

  /** \brief Groups of fewer than 50 points are left out by default (setMinClusterSize):
   * below that a group of points without a segment is mostly a crease band's piece. */
  LeftoverRegionGrowing() { min_size_ = 50; }

  /** \brief The segment of every point of the input cloud (0: none). */
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

  /** \brief Largest angle between the normals of two linked points, in radians
   * (default 25 degrees, CGAL's default for its region growing). */
  void
  setAngleThreshold (double radians)
  {
    angle_ = radians;
  }

  double
  getAngleThreshold () const
  {
    return angle_;
  }

  /** \brief Largest surface variance (eq. 4, l0 / (l0 + l1 + l2)) of a point's normal
   * patch for it to link to others (default 0.05): a patch across a crease has a
   * larger one, a patch on a plane or a pipe a few spacings in radius a smaller one. */
  void
  setMaxCurvature (double max_curvature)
  {
    max_curvature_ = max_curvature;
  }

  double
  getMaxCurvature () const
  {
    return max_curvature_;
  }

  /** \brief Neighbours (the point included) a normal is fitted to and links are looked
   * for among (default 12, fewer where a row is shorter; at least 3). */
  void
  setNormalK (int k)
  {
    normal_k_ = k;
  }

  int
  getNormalK () const
  {
    return normal_k_;
  }

  /** \brief Only the points \a indices make links of their own (default, null: every
   * point that takes part). The others take part as partners and groups: linked to
   * when a linking point finds them among its nearest neighbours, never linking
   * themselves. A tile of a larger cloud links from its own points only, the links of
   * its halo being made by the tiles that own them, so that every link of the whole
   * cloud is made exactly once, from its own point's whole neighbourhood. */
  void
  setLinkingIndices (const pcl::IndicesConstPtr& indices)
  {
    linking_ = indices;
  }

  pcl::IndicesConstPtr
  getLinkingIndices () const
  {
    return linking_;
  }

  /** \brief Grow the new segments. \a output gets one label per input point: the
   * input's, or a new segment's. On bad input: PCL_ERROR, empty output, false. */
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
  pcl::IndicesConstPtr linking_;
  double angle_ = 25.0 * M_PI / 180.0;
  double max_curvature_ = 0.05;
  int normal_k_ = 12;
  Report report_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/leftover_region_growing.hpp>
#endif
