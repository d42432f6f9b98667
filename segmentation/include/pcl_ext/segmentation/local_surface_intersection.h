/*
 * pcl_ext: local intersection of segmented surfaces and re-integration of edge points
 * (Belton & Lichti 2006, section 4).
 */
#pragma once

#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/segmentation/local_planes.h>
#include <pcl_ext/segmentation/nearest_of_each_segment.h>
#include <pcl_ext/segmentation/surface_intersection_point.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief Local intersection points between segmented surfaces, and re-integration of
 * edge and boundary points into the surfaces they fit (Belton & Lichti 2006, section 4,
 * eq. 9-17).
 *
 * Inputs, one entry per point of the cloud: segment labels (0 = no segment; any
 * segmenter, or ground truth) and point classes (pcl_ext::PointClass, e.g. from
 * pcl_ext::LocalVarianceClassification); optionally normals. Neighbourhoods are
 * searched once (k nearest, or shared through setNeighbourhoods, computed for the whole
 * cloud).
 *
 * Intersections: every surface point p1 with a segment is checked against the nearest
 * point p2 of each other segment within the reach (the paper checks "each surface point
 * to see if another point belonging to a different surface can be reached"). The reach
 * defaults to a few neighbourhood radii, because a classifier leaves a band of edge
 * points about a neighbourhood wide on each side of a crease, and the surface points of
 * two segments are only that close. Each of the two points gets a local plane through
 * the centroid of its neighbours of its own segment (the paper's improvement over a
 * plane through the point itself; keeping the fit to the point's own segment keeps the
 * other surface out of it near the crease). Then:
 * - eq. 9: when the normals differ by less than the parallel-angle threshold the
 * surfaces are taken as parallel, a jump discontinuity with no intersection near the
 * points;
 * - eq. 10-15: the line of intersection of the two planes;
 * - eq. 17: its point closest to both, in closed form the projection of the midpoint of
 * p1 and p2 onto the line (see pcl_ext::intersectLocalPlanes; the angle cost of eq. 16
 * has no simple minimiser, as the paper says);
 * - the point is rejected when it lies farther than the distance tolerance from both p1
 * and p2 ("care must be taken in case the point that is returned is not close to the
 * surface points"). A pair found from both of its points is reported once. Surface
 * points whose whole neighbourhood is surface of their own segment lie inside it and
 * are not examined, and partners are taken among the segments' border points (surface
 * points with a neighbour outside their segment): a segment's nearest point to anything
 * outside it is on its border, and this keeps the search to the border zones.
 *
 * Re-integration (the paper's last step): each edge or boundary point without a segment
 * is compared with the local plane of the nearest border point of each segment within
 * its reach. It fits a segment when its distance to that plane is within the fit
 * tolerance (by default 3 standard deviations of the distance expected there) and it
 * lies "within the circles" of that segment's local intersections: the paper grows a
 * circle along each plane from p1 and p2 until they meet on the intersection line, so a
 * point belongs to a surface only on that surface's side of the line; pcl_ext tests the
 * side of the line (within the fit tolerance) rather than the circle's radius, which
 * depends on how far p1 happens to be from the crease. A point that fits one segment is
 * re-integrated; one that fits several is ambiguous ("no guarantee ... that they will
 * not be deemed to belong to more than one surface") and goes to the closest plane
 * unless setAssignAmbiguous(false); one that fits none is left without a segment.
 * getReport() counts each outcome. The input labels decide everything (re-integrated
 * points are not used to re-integrate others), so the result does not depend on the
 * order of the points.
 *
 * Positions are handled in double precision around local centres, so georeferenced
 * coordinates lose nothing beyond the float storage of the cloud. The loops are
 * OpenMP-parallel (setNumberOfThreads) and the output does not depend on the thread
 * count.
 *
 * \code
 * pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ> lsi;
 * lsi.setInputCloud (cloud);
 * lsi.setSegmentLabels (segments);   // pcl::PointCloud<pcl::Label>, one per point
 * lsi.setPointClasses (classes);     // from LocalVarianceClassification::classify
 * pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
 * pcl::PointCloud<pcl::Label> labels;
 * lsi.compute (intersections, labels);
 * \endcode
 */
template <typename PointT>
class LocalSurfaceIntersection : public pcl::PCLBase<PointT>,
                                 public NeighbourhoodOptions<PointT> {
public:
  using Ptr = pcl::shared_ptr<LocalSurfaceIntersection<PointT>>;
  using ConstPtr = pcl::shared_ptr<const LocalSurfaceIntersection<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;
  using NormalCloudConstPtr = pcl::PointCloud<pcl::Normal>::ConstPtr;
  using IntersectionCloud = pcl::PointCloud<SurfaceIntersectionPoint>;
  using NeighbourhoodsConstPtr = typename Neighbourhoods<PointT>::ConstPtr;
  using SearchPtr = typename Neighbourhoods<PointT>::SearchPtr;

  /** \brief What the last compute() did. */
  struct Report {
    std::size_t pairs = 0; ///< pairs (p1, nearest p2 of another segment), each once
    std::size_t intersections = 0; ///< pairs that gave an intersection point
    std::size_t parallel = 0;      ///< pairs rejected by eq. 9 (jump discontinuities)
    std::size_t beyond_tolerance =
        0;                        ///< pairs whose point was too far from both points
    std::size_t no_plane = 0;     ///< pairs where a local plane could not be fitted
    std::size_t examined = 0;     ///< edge and boundary points without a segment
    std::size_t reintegrated = 0; ///< fitted exactly one segment
    std::size_t ambiguous = 0;    ///< fitted several
    std::size_t left = 0;         ///< fitted none
  };

  LocalSurfaceIntersection() = default;

  /** \brief Segment of every point of the input cloud (not only of the indices); 0 =
   * none. */
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

  /** \brief pcl_ext::PointClass of every point of the input cloud. Surface points are
   * intersected; edge and boundary points without a segment are re-integrated. */
  void
  setPointClasses (const LabelCloudConstPtr& classes)
  {
    classes_ = classes;
  }

  LabelCloudConstPtr
  getPointClasses () const
  {
    return classes_;
  }

  /** \brief Normals of every point of the input cloud (optional; the paper's
   * "approximate normal direction for each point"). Default none: each local plane
   * takes the normal of its own fit. */
  void
  setInputNormals (const NormalCloudConstPtr& normals)
  {
    normals_ = normals;
  }

  NormalCloudConstPtr
  getInputNormals () const
  {
    return normals_;
  }

  /** \brief Threshold on the angle theta between the two normals (eq. 9), in radians:
   * below it the surfaces are parallel and not intersected. Default 10 degrees
   * (0.1745); valid: 0 .. pi/2. The error of the intersection grows as 1 / sin(theta),
   * so small thresholds let noise through. */
  void
  setParallelAngleThreshold (double radians)
  {
    parallel_angle_ = radians;
  }

  double
  getParallelAngleThreshold () const
  {
    return parallel_angle_;
  }

  /** \brief An intersection point farther than this from both p1 and p2 is rejected, in
   * the cloud's units. Default 0: each point's own neighbourhood radius (distance to
   * its k-th neighbour), so the point must lie within the reach of the data one of the
   * two planes was fitted to. Valid: >= 0. */
  void
  setDistanceTolerance (double tolerance)
  {
    distance_tolerance_ = tolerance;
  }

  double
  getDistanceTolerance () const
  {
    return distance_tolerance_;
  }

  /** \brief How far a point of another segment (for intersections) or of a segment (for
   * re-integration) may be, in the cloud's units. Default 0: the reach factor times the
   * point's neighbourhood radius (distance to its k-th neighbour). Valid: >= 0. */
  void
  setReach (double reach)
  {
    reach_ = reach;
  }

  double
  getReach () const
  {
    return reach_;
  }

  /** \brief The reach in neighbourhood radii when no reach is set. Default 3: a
   * classifier's edge band is about one neighbourhood radius wide on each side of a
   * crease (a point is an edge when its neighbourhood reaches across, Belton & Lichti
   * section 2.2), so the nearest surface points of two segments meeting at a right
   * angle are about 2 sqrt(2) radii apart. Valid: > 0. */
  void
  setReachFactor (double factor)
  {
    reach_factor_ = factor;
  }

  double
  getReachFactor () const
  {
    return reach_factor_;
  }

  /** \brief Largest distance from a point to a local plane for it to fit that plane, in
   * the cloud's units. Default 0: 3 standard deviations of the distance expected for a
   * point of that surface there (the plane's residual noise plus its uncertainty away
   * from its centroid, see pcl_ext::LocalPlane::residualSigma). Valid: >= 0. */
  void
  setFitTolerance (double tolerance)
  {
    fit_tolerance_ = tolerance;
  }

  double
  getFitTolerance () const
  {
    return fit_tolerance_;
  }

  /** \brief Give a point that fits several segments to the one whose plane is closest.
   * Default true; false leaves it without a segment. Either way it counts as ambiguous.
   */
  void
  setAssignAmbiguous (bool assign)
  {
    assign_ambiguous_ = assign;
  }

  bool
  getAssignAmbiguous () const
  {
    return assign_ambiguous_;
  }

  /** \brief Intersect the segments and re-integrate edge and boundary points.
   *
   * Only the points named by setIndices are examined (all by default); their neighbours
   * may be any point of the cloud. \param[out] intersections one point per accepted
   * pair, in the order of p1 in the indices \param[out] labels the segment labels, with
   * the re-integrated points' segments set (one per point of the cloud, laid out as the
   * input labels) \return false (PCL_ERROR, both outputs empty) on bad input or
   * parameters: no or empty cloud, labels or classes missing or not one per point,
   * normals not one per point, no point that is both surface and segmented, parameters
   * out of range */
  bool
  compute (IntersectionCloud& intersections, LabelCloud& labels);

  /** \brief Counts of the last compute(). */
  const Report&
  getReport () const
  {
    return report_;
  }

protected:
  using NeighbourhoodOptions<PointT>::threads_;
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief What became of a pair. */
  enum class Outcome : std::uint8_t { Accepted, Parallel, BeyondTolerance, NoPlane };

  /** \brief A pair and its intersection, in double precision (the side test of
   * re-integration uses the line). */
  struct Record {
    Eigen::Vector3d point;
    Eigen::Vector3d direction;
    pcl::index_t a;
    pcl::index_t b;
    Outcome outcome;
  };

  /** \brief Scratch space of nearestOfEachSegment, one per thread. */
  struct SearchBuffers {
    typename NearestOfEachSegment<PointT>::Scratch scratch;
    std::vector<double> reaches;
  };

  bool
  checkInput () const;

  /** \brief Plane of point \a i through its neighbours of its own segment (the one
   * fitted beforehand for a border point). */
  bool
  planeOf (pcl::index_t i, pcl::Indices& buffer, LocalPlane& plane) const;

  /** \brief Fit the plane of every border point once, in parallel: the searches of both
   * steps pair points only with border points, each many times. */
  void
  fitBorderPlanes (const pcl::Indices& border);

  /** \brief Fit the plane of point \a i through its neighbours of its own segment. */
  bool
  fitPlaneOf (pcl::index_t i, pcl::Indices& buffer, LocalPlane& plane) const;

  /** \brief The reach of point \a i. */
  double
  reachOf (pcl::index_t i) const;

  /** \brief For each point of \a queries, the nearest border point of each segment
   * other than its own within its reach (reachOf), closest first, as row q of \a
   * nearest: nearest[offsets[q] .. offsets[q + 1]) (see NearestOfEachSegment). */
  void
  nearestOfEachSegment (const pcl::Indices& queries,
                        SearchBuffers& buffers,
                        std::vector<std::size_t>& offsets,
                        std::vector<pcl::index_t>& nearest) const;

  /** \brief Whether every neighbour of surface point \a i is in its segment (then it is
   * inside the segment and not examined). */
  bool
  isInterior (pcl::index_t i) const;

  /** \brief Intersections of every examined surface point (\a on_border: 1 for a
   * segmented surface point with a neighbour outside its segment), in index order. */
  void
  intersect (const std::vector<std::uint8_t>& on_border, std::vector<Record>& records);

  /** \brief Re-integration of edge and boundary points, given the accepted pairs. */
  void
  reintegrate (const std::vector<Record>& records, LabelCloud& labels);

  std::uint32_t
  segmentOf (pcl::index_t i) const
  {
    return (*segments_)[i].label;
  }

  std::uint32_t
  classOf (pcl::index_t i) const
  {
    return (*classes_)[i].label;
  }

  LabelCloudConstPtr segments_;
  LabelCloudConstPtr classes_;
  NormalCloudConstPtr normals_;
  double parallel_angle_ = 0.17453292519943295;
  double distance_tolerance_ = 0.0;
  double reach_ = 0.0;
  double reach_factor_ = 3.0;
  double fit_tolerance_ = 0.0;
  bool assign_ambiguous_ = true;

  const Neighbourhoods<PointT>* nb_ = nullptr; ///< during compute()
  /** \brief The segments' border points, searched within the reach, during compute().
   */
  NearestOfEachSegment<PointT> partners_;
  /** \brief During compute(): per point, its slot in border_planes_ (-1: none); per
   * border point, its plane and whether the fit succeeded. */
  std::vector<std::int32_t> border_slot_;
  std::vector<LocalPlane> border_planes_;
  std::vector<char> border_fitted_;
  Report report_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/local_surface_intersection.hpp>
#endif
