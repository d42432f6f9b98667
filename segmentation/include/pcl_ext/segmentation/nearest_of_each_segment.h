/*
 * pcl_ext: for query points, the nearest point of each other segment within a reach
 * (the partner search of Belton & Lichti 2006, section 4).
 */
#pragma once

#include <pcl_ext/search/nanoflann_kdtree.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_ext {
/** \brief For each query point, the nearest candidate point of each segment other than
 * the query's own within the query's reach: the partners of Belton & Lichti (2006),
 * section 4 ("each surface point [is checked] to see if another point belonging to a
 * different surface can be reached"), for the local intersections (eq. 9-17) and the
 * re-integration of edge points.
 *
 * The candidates (a subset of a cloud, typically the segments' border points) go into
 * one k-d tree. Queries are answered in batches: those within half a reach of one
 * another (among the next few of the batch) share one radius search around the first
 * of them, over the largest of their reaches plus their distance from it, and each
 * keeps what a search of its own would find: float squared distances strictly below its
 * squared reach, as the tree compares them. So each row is the same however the queries
 * are batched and grouped. Of each other segment the nearest candidate is kept (equal
 * distances: the smaller index), closest first.
 *
 * \code
 * pcl_ext::NearestOfEachSegment<pcl::PointXYZ> partners;
 * partners.setInput (cloud, segments, border);   // border: candidate indices
 * pcl_ext::NearestOfEachSegment<pcl::PointXYZ>::Scratch scratch;
 * std::vector<std::size_t> offsets;
 * std::vector<pcl::index_t> nearest;
 * partners.find (queries, reaches, scratch, offsets, nearest);
 * // the partners of queries[q]: nearest[offsets[q] .. offsets[q + 1])
 * \endcode
 */
template <typename PointT>
class NearestOfEachSegment {
public:
  using Cloud = pcl::PointCloud<PointT>;
  using LabelCloud = pcl::PointCloud<pcl::Label>;

  /** \brief Per-thread scratch space of find(), reused from call to call. */
  struct Scratch {
    pcl::Indices indices;
    std::vector<float> sqr_distances;
    /** the found points' coordinates, one array per axis, and their segments */
    std::vector<float> x, y, z;
    std::vector<std::uint32_t> segment;
    /** positions of those a query keeps */
    std::vector<std::uint32_t> kept;
    /** per query: whether a group has taken it */
    std::vector<char> grouped;
    /** the queries (positions) of the current group */
    std::vector<std::size_t> group;
    /** (squared distance, point) and segment of the nearest point of each segment */
    std::vector<std::pair<float, pcl::index_t>> nearest;
    std::vector<std::uint32_t> nearest_segment;
    /** per query: where its row starts in \a found, and its length */
    std::vector<std::size_t> start, length;
    std::vector<pcl::index_t> found;
  };

  /** \brief The cloud, its segment labels (one per point; the candidates' and the
   * queries' segments are read from it) and the candidate points (indices into the
   * cloud; finite points in range only are used). Builds the tree. Labels that are
   * not one per point: PCL_ERROR, and find() gives empty rows. */
  void
  setInput (const typename Cloud::ConstPtr& cloud,
            const typename LabelCloud::ConstPtr& segments,
            const pcl::IndicesConstPtr& candidates);

  /** \brief Release the tree and the inputs. */
  void
  clear ();

  /** \brief For each of \a queries (indices into the cloud) with its reach \a
   * reaches[q] (0 or less: no partners), the nearest candidate of each other segment
   * within the reach, closest first, as row q: nearest[offsets[q] .. offsets[q + 1]).
   * A query's own segment is the label of its point (0: none, so every segment is
   * another); a query that is not finite has none. Not one reach per query, or a query
   * index out of range: PCL_ERROR and empty rows. */
  void
  find (const pcl::Indices& queries,
        const std::vector<double>& reaches,
        Scratch& scratch,
        std::vector<std::size_t>& offsets,
        std::vector<pcl::index_t>& nearest) const;

private:
  typename Cloud::ConstPtr cloud_;
  typename LabelCloud::ConstPtr segments_;
  typename search::NanoflannKdTree<PointT>::Ptr tree_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/nearest_of_each_segment.hpp>
#endif
