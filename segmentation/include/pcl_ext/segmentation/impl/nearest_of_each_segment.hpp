/*
 * pcl_ext: NearestOfEachSegment implementation.
 */
#pragma once

#include <pcl_ext/segmentation/nearest_of_each_segment.h>

#include <pcl/console/print.h>

#include <Eigen/Core>

#include <algorithm>

template <typename PointT>
void
pcl_ext::NearestOfEachSegment<PointT>::setInput (
    const typename Cloud::ConstPtr& cloud,
    const typename LabelCloud::ConstPtr& segments,
    const pcl::IndicesConstPtr& candidates)
{
  clear();
  if (!cloud || !segments || segments->size() != cloud->size()) {
    PCL_ERROR ("[pcl_ext::NearestOfEachSegment::setInput] %zu segment labels for %zu "
               "points; give one per point. No partners will be found.\n",
               segments ? segments->size() : std::size_t (0),
               cloud ? cloud->size() : std::size_t (0));
    return;
  }
  cloud_ = cloud;
  segments_ = segments;
  // Unsorted radius searches: only each segment's nearest is wanted. Candidates out of
  // range or not finite are left out of the tree.
  tree_.reset (new search::NanoflannKdTree<PointT> (false));
  if (candidates && !candidates->empty())
    tree_->setInputCloud (cloud_, candidates);
}

template <typename PointT>
void
pcl_ext::NearestOfEachSegment<PointT>::clear()
{
  tree_.reset();
  cloud_.reset();
  segments_.reset();
}

template <typename PointT>
void
pcl_ext::NearestOfEachSegment<PointT>::find (const pcl::Indices& queries,
                                             const std::vector<double>& reaches,
                                             Scratch& buffers,
                                             std::vector<std::size_t>& offsets,
                                             std::vector<pcl::index_t>& nearest) const
{
  const std::size_t m = queries.size();
  offsets.assign (m + 1, 0);
  nearest.clear();
  buffers.start.assign (m, 0);
  buffers.length.assign (m, 0);
  buffers.found.clear();
  if (reaches.size() != m) {
    PCL_ERROR ("[pcl_ext::NearestOfEachSegment::find] %zu reaches for %zu queries; "
               "give one per query.\n",
               reaches.size(),
               m);
    return;
  }
  if (!tree_ || !tree_->getInputCloud())
    return;
  for (const auto i : queries)
    if (i < 0 || static_cast<std::size_t> (i) >= cloud_->size()) {
      PCL_ERROR ("[pcl_ext::NearestOfEachSegment::find] Query index %d is not a point "
                 "of the cloud (%zu points).\n",
                 static_cast<int> (i),
                 cloud_->size());
      return;
    }
  const auto pointOf = [this] (pcl::index_t i) {
    const PointT& p = (*cloud_)[i];
    return Eigen::Vector3d (p.x, p.y, p.z);
  };
  buffers.grouped.assign (m, 0);
  for (std::size_t q = 0; q < m; ++q)
    buffers.grouped[q] = !(reaches[q] > 0.0); // no reach: an empty row
  constexpr std::size_t kGroupWindow = 64;
  // Float rounding of the squared distances stays far inside this relative margin.
  constexpr double margin = 1.0 + 1e-4;
  for (std::size_t first = 0; first < m; ++first) {
    if (buffers.grouped[first])
      continue;
    const Eigen::Vector3d anchor = pointOf (queries[first]);
    double gather = reaches[first];
    buffers.group.assign (1, first);
    // Among the next few queries only (neighbours in the cloud's order are mostly
    // neighbours in space), so that sparse queries cost linear time.
    for (std::size_t q = first + 1; q < std::min (m, first + 1 + kGroupWindow); ++q) {
      if (buffers.grouped[q])
        continue;
      const double offset = (pointOf (queries[q]) - anchor).norm();
      if (offset <= 0.5 * reaches[first]) {
        buffers.group.push_back (q);
        buffers.grouped[q] = 1;
        gather = std::max (gather, reaches[q] + offset);
      }
    }
    // Unsorted results: the minimum per segment is taken below.
    tree_->radiusSearch ((*cloud_)[queries[first]],
                         gather * margin,
                         buffers.indices,
                         buffers.sqr_distances);
    const std::size_t found = buffers.indices.size();
    buffers.x.resize (found);
    buffers.y.resize (found);
    buffers.z.resize (found);
    buffers.segment.resize (found);
    buffers.sqr_distances.resize (found);
    buffers.kept.resize (found);
    for (std::size_t c = 0; c < found; ++c) {
      const PointT& p = (*cloud_)[buffers.indices[c]];
      buffers.x[c] = p.x;
      buffers.y[c] = p.y;
      buffers.z[c] = p.z;
      buffers.segment[c] = (*segments_)[buffers.indices[c]].label;
    }
    for (const std::size_t q : buffers.group) {
      const pcl::index_t i = queries[q];
      const PointT& pq = (*cloud_)[i];
      const std::uint32_t own = (*segments_)[i].label;
      // As the tree's radius search compares: float squared distances, strictly below
      // the squared reach.
      const float limit = static_cast<float> (reaches[q] * reaches[q]);
      // The squared distances first, in a loop the compiler vectorises.
      float* d = buffers.sqr_distances.data();
      for (std::size_t c = 0; c < found; ++c) {
        const float dx = pq.x - buffers.x[c], dy = pq.y - buffers.y[c],
                    dz = pq.z - buffers.z[c];
        d[c] = dx * dx + dy * dy + dz * dz;
      }
      // Those within the reach and of another segment (so never the query itself),
      // compacted without a branch: most of the found points are of the query's own
      // segment.
      std::uint32_t* keep = buffers.kept.data();
      std::size_t kept = 0;
      for (std::size_t c = 0; c < found; ++c) {
        keep[kept] = static_cast<std::uint32_t> (c);
        kept += (d[c] < limit) & (buffers.segment[c] != own);
      }
      auto& best = buffers.nearest;
      auto& best_segment = buffers.nearest_segment;
      best.clear();
      best_segment.clear();
      for (std::size_t k = 0; k < kept; ++k) {
        const std::size_t c = keep[k];
        const std::uint32_t s = buffers.segment[c];
        const std::pair<float, pcl::index_t> candidate (d[c], buffers.indices[c]);
        const std::size_t at = static_cast<std::size_t> (
            std::find (best_segment.begin(), best_segment.end(), s) -
            best_segment.begin());
        if (at == best.size()) {
          best.push_back (candidate);
          best_segment.push_back (s);
        }
        else if (candidate < best[at])
          best[at] = candidate;
      }
      std::sort (best.begin(), best.end());
      buffers.start[q] = buffers.found.size();
      buffers.length[q] = best.size();
      for (const auto& b : best)
        buffers.found.push_back (b.second);
    }
  }
  // The rows in query order.
  nearest.reserve (buffers.found.size());
  for (std::size_t q = 0; q < m; ++q) {
    nearest.insert (nearest.end(),
                    buffers.found.begin() + buffers.start[q],
                    buffers.found.begin() + buffers.start[q] + buffers.length[q]);
    offsets[q + 1] = nearest.size();
  }
}

#define PCL_EXT_INSTANTIATE_NearestOfEachSegment(T)                                    \
  template class pcl_ext::NearestOfEachSegment<T>;
