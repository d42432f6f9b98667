/*
 * pcl_ext: region growing over the surface / edge / boundary classification (Belton &
 * Lichti 2006, section 3).
 */
#pragma once

#include <pcl_ext/point_types.h>
#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/segmentation/cluster_size_limits.h>
#include <pcl_ext/segmentation/local_planes.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <vector>

namespace pcl_ext {
/** \brief The walks and merges of Belton & Lichti's region growing (section 3) over
 * stored neighbourhoods (pcl_ext::Neighbourhoods::getRows).
 *
 * For every row whose point is a surface point, its neighbours are visited closest
 * first: the point itself and points of class -1 are skipped, a surface point is linked
 * to the seed, and anything else, or the end of the row's reach, ends the walk. The
 * result is the connected components of the links.
 * \param[in] rows the neighbours of each row, closest first
 * \param[in] row_points the point of each row
 * \param[in] class_of_point per point of the cloud: a PointClass value, or -1 for
 * points that are not segmented (skipped in the walks) \param[in] row_reach per row,
 * how many of its first neighbours lie within the seed's distance limit (the walk stops
 * there); empty: no limit \param[in] threads OpenMP threads for the walks (0: all
 * cores) \param[out] root per point of the cloud: the smallest point index of its
 * segment for surface points of the rows, -1 for every other point; empty when \a
 * row_reach is neither empty nor one per row
 */
void
growSurfaceSegments (const NeighbourRowsView& rows,
                     const pcl::Indices& row_points,
                     const std::vector<std::int8_t>& class_of_point,
                     const std::vector<std::uint32_t>& row_reach,
                     unsigned int threads,
                     std::vector<std::int32_t>& root);

/** \brief Segmentation by region growing over classified points: D. Belton and D. D.
 * Lichti, "Classification and segmentation of terrestrial laser scanner point clouds
 * using local variance information", ISPRS Commission V Symposium 2006, section 3 and
 * figure 4.
 *
 * The points come labelled surface, edge or boundary (section 2: the output of
 * pcl_ext::LocalVarianceClassification::classify, given with setInputClasses, as
 * pcl::RegionGrowing takes its normals). Then every surface point in turn is a seed:
 * its neighbours are visited nearest first and
 * - an unlabelled surface neighbour joins the seed's segment;
 * - a surface neighbour already in another segment merges the two segments;
 * - a non-surface neighbour (edge, boundary or unknown) stops the walk through the
 * list, as does a neighbour farther from the seed than the maximum distance
 * (setMaxDistance, setMaxDistanceFactor). Edge and boundary points so act as cut lines
 * between surfaces, and are left unsegmented (they are for the local surface
 * intersection of section 4 to re-integrate). Segments smaller than the minimum size
 * (or larger than the maximum) are dropped.
 *
 * Where pcl_ext departs from or makes the text precise:
 * - Figure 4's pseudo-code has its branches out of order (its "else if" can never run);
 * this class implements the order of the text of section 3, as settled in the notes on
 * the paper: join, merge (with a union-find), stop.
 * - Because a join and a merge both put the seed and its neighbour in one segment, the
 *   segments are the connected components of the links "seed - neighbour before the
 * first stop". They do not depend on the seed order, so the result is the same in every
 * run and for any thread count. The walks are made in parallel; the links are united
 *   sequentially, in point order, into a union-find whose root is the smallest point
 * index.
 * - The neighbours are the k nearest (50 by default, the paper's k) or those of shared
 *   pcl_ext::Neighbourhoods (best the classifier's own), the seed excluded. Neighbours
 * that are not among the indices (setIndices) are skipped: they are not segmented and
 * were not classified.
 * - The paper's limit on the distance from the seed is, by default, 3 times the seed's
 * local point spacing (setMaxDistanceFactor) rather than one distance for the whole
 * cloud: the spacing of a TLS scan grows with range, and without a limit a sparse
 * seed's neighbourhood links the two faces of a thin wall.
 * - Points with non-finite coordinates are unknown, never segmented and nobody's
 * neighbour.
 * - Segments are returned largest first (ties: smallest point index first), each with
 * its indices in increasing order. Optionally (setFitPlanes) each segment gets a
 * least-squares plane with its residuals (section 3: "a surface may be fitted to
 * groups").
 *
 * Bad input (no cloud, an empty cloud or empty indices, no classes or classes of the
 * wrong size, no surface point, parameters out of range) gives a PCL_ERROR and no
 * segment.
 *
 * \code
 * auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<pcl::PointXYZ>> ();
 * nb->setInputCloud (cloud);
 * nb->setKSearch (50);
 * nb->compute ();
 * pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
 * classifier.setInputCloud (cloud);
 * classifier.setNeighbourhoods (nb);
 * auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>> ();
 * classifier.classify (*classes);
 * pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> rg;
 * rg.setInputCloud (cloud);
 * rg.setNeighbourhoods (nb);
 * rg.setInputClasses (classes);
 * rg.setMinClusterSize (50);
 * std::vector<pcl::PointIndices> segments;
 * rg.extract (segments);
 * \endcode
 * pcl_ext::segmentByLocalVariance (classification module) does the same in one call.
 */
template <typename PointT>
class VarianceRegionGrowing : public pcl::PCLBase<PointT>,
                              public NeighbourhoodOptions<PointT>,
                              public ClusterSizeLimits {
public:
  /** \brief The smallest m of the local spacing of setMaxDistanceFactor. */
  static constexpr std::size_t kMinSpacingNeighbour = 3;

  using Ptr = pcl::shared_ptr<VarianceRegionGrowing<PointT>>;
  using ConstPtr = pcl::shared_ptr<const VarianceRegionGrowing<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using NeighbourhoodsConstPtr = typename Neighbourhoods<PointT>::ConstPtr;
  using SearchPtr = typename Neighbourhoods<PointT>::SearchPtr;
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = typename LabelCloud::ConstPtr;

  VarianceRegionGrowing() = default;

  /** \brief Point classes to grow on, one pcl::Label per index with a
   * pcl_ext::PointClass value: the output of
   * pcl_ext::LocalVarianceClassification::classify for the same cloud and indices.
   * Required. */
  void
  setInputClasses (const LabelCloudConstPtr& classes)
  {
    classes_ = classes;
  }

  LabelCloudConstPtr
  getInputClasses () const
  {
    return classes_;
  }

  /** \brief Longest distance from a seed to a neighbour it may link to (the paper's
   * "limit" on the distance from the seed point). Default 0: no limit beyond the
   * neighbourhood; valid: >= 0 and finite. */
  void
  setMaxDistance (double distance)
  {
    max_distance_ = distance;
  }

  double
  getMaxDistance () const
  {
    return max_distance_;
  }

  /** \brief The distance limit from the seed as a multiple of the seed's local point
   * spacing s = r_m sqrt(pi / m), r_m the distance to its m-th nearest neighbour, m
   * half its neighbours (the spacing of a uniform sampling with m points within r_m;
   * half the neighbourhood, so that the rows of a surface seen at a grazing angle, far
   * apart across and dense along the scan line, still count as one sampling). Default 3
   * (the paper gives no value); 0: no such limit; valid: >= 0 and finite. With both
   * limits set, the smaller applies. A TLS cloud's spacing varies with range and
   * incidence, so one fixed distance cannot suit near and far surfaces; a multiple of
   * the local spacing stops the walks from linking two parallel surfaces (the two faces
   * of a thin wall) that a sparse seed's neighbourhood reaches across. Rows of fewer
   * than 7 neighbours have no such limit. */
  void
  setMaxDistanceFactor (double factor)
  {
    max_distance_factor_ = factor;
  }

  double
  getMaxDistanceFactor () const
  {
    return max_distance_factor_;
  }

  /** \brief Fit a least-squares plane to every segment kept (getSegmentPlanes). Default
   * false. */
  void
  setFitPlanes (bool fit)
  {
    fit_planes_ = fit;
  }

  bool
  getFitPlanes () const
  {
    return fit_planes_;
  }

  /** \brief Only these points (indices into the input cloud) start walks; every point
   * is still classified, linked to by the seeds and labelled. Default null: every
   * point is a seed. For a tile of a larger cloud: its own points seed, the points of
   * its halo around it are linked to, so that no walk starts where the tile's
   * neighbourhoods are not the whole cloud's; the segments of the tiles are then joined
   * through the points they share. */
  void
  setSeedIndices (const pcl::IndicesConstPtr& seeds)
  {
    seeds_ = seeds;
  }

  pcl::IndicesConstPtr
  getSeedIndices () const
  {
    return seeds_;
  }

  /** \brief Segment the cloud (the indices, if set).
   * \param[out] clusters one PointIndices per segment, largest first; empty after a
   * PCL_ERROR */
  void
  extract (std::vector<pcl::PointIndices>& clusters);

  /** \brief One label per point of the input cloud (its width and height kept): segment
   * i + 1 for the points of clusters[i], 0 for points in no segment. Empty before a
   * successful extract(). */
  void
  getSegmentLabels (LabelCloud& labels) const;

  /** \brief The input cloud coloured by segment (unsegmented points white), as
   * pcl::RegionGrowing::getColoredCloud; empty before a successful extract(). */
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr
  getColoredCloud () const;

  /** \brief The planes of the last extract()'s segments, one per cluster, when
   * setFitPlanes was on; empty otherwise. */
  const std::vector<Plane>&
  getSegmentPlanes () const
  {
    return planes_;
  }

protected:
  using NeighbourhoodOptions<PointT>::threads_;
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Parameter checks; PCL_ERROR and false on the first bad one. */
  bool
  checkParameters () const;

  /** \brief Whether the input classes are one per index; PCL_ERROR when not. */
  bool
  checkClasses () const;

  LabelCloudConstPtr classes_;
  pcl::IndicesConstPtr seeds_;
  double max_distance_ = 0.0;
  double max_distance_factor_ = 3.0;
  bool fit_planes_ = false;

  // Results of the last extract().
  std::vector<pcl::PointIndices> clusters_;
  std::vector<Plane> planes_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/variance_region_growing.hpp>
#endif
