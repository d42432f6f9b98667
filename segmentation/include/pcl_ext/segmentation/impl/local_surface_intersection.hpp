/*
 * pcl_ext: LocalSurfaceIntersection implementation.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/impl/nearest_of_each_segment.hpp>
#include <pcl_ext/segmentation/local_surface_intersection.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace pcl_ext {
namespace detail {
/** \brief Rows per unit of parallel work; each chunk collects its own results, which
 * are concatenated in chunk order, so the output does not depend on the thread count.
 */
constexpr std::ptrdiff_t kIntersectionChunk = 256;

inline bool
isNonNegativeFinite (double value)
{
  return value >= 0.0 && std::isfinite (value);
}
} // namespace detail
} // namespace pcl_ext

template <typename PointT>
bool
pcl_ext::LocalSurfaceIntersection<PointT>::checkInput() const
{
  const char* const name = "[pcl_ext::LocalSurfaceIntersection::compute]";
  const std::size_t n = input_->size();
  if (n == 0) {
    PCL_ERROR ("%s The input cloud is empty.\n", name);
    return false;
  }
  if (!onePerPoint (segments_.get(), n, name, "segment label", "setSegmentLabels") ||
      !onePerPoint (classes_.get(), n, name, "point class", "setPointClasses"))
    return false;
  if (normals_ && normals_->size() != n) {
    PCL_ERROR ("%s %zu normals for %zu points; give one per point or none.\n",
               name,
               normals_->size(),
               n);
    return false;
  }
  if (!indicesInRange (*indices_, n, name))
    return false;
  if (!this->checkNeighbourhoodOptions (name, 3))
    return false;
  if (!(parallel_angle_ >= 0.0 && parallel_angle_ <= 0.5 * M_PI)) {
    PCL_ERROR ("%s parallel angle threshold = %g rad; valid: 0 .. pi/2.\n",
               name,
               parallel_angle_);
    return false;
  }
  if (!detail::isNonNegativeFinite (distance_tolerance_) ||
      !detail::isNonNegativeFinite (reach_) ||
      !detail::isNonNegativeFinite (fit_tolerance_)) {
    PCL_ERROR (
        "%s distance tolerance = %g, reach = %g, fit tolerance = %g; each must be "
        "finite and >= 0.\n",
        name,
        distance_tolerance_,
        reach_,
        fit_tolerance_);
    return false;
  }
  if (!(reach_factor_ > 0.0) || !std::isfinite (reach_factor_)) {
    PCL_ERROR (
        "%s reach factor = %g; it must be finite and > 0.\n", name, reach_factor_);
    return false;
  }
  return true;
}

template <typename PointT>
double
pcl_ext::LocalSurfaceIntersection<PointT>::reachOf (pcl::index_t i) const
{
  if (reach_ > 0.0)
    return reach_;
  const auto row = (*nb_)[static_cast<std::size_t> (i)];
  return row.empty()
             ? 0.0
             : reach_factor_ * std::sqrt (static_cast<double> (nb_->getSquaredDistance (
                                   static_cast<std::size_t> (i), row.size() - 1)));
}

template <typename PointT>
bool
pcl_ext::LocalSurfaceIntersection<PointT>::planeOf (pcl::index_t i,
                                                    pcl::Indices& buffer,
                                                    LocalPlane& plane) const
{
  const std::int32_t slot =
      border_slot_.empty() ? -1 : border_slot_[static_cast<std::size_t> (i)];
  if (slot < 0)
    return fitPlaneOf (i, buffer, plane);
  if (!border_fitted_[static_cast<std::size_t> (slot)])
    return false;
  plane = border_planes_[static_cast<std::size_t> (slot)];
  return true;
}

template <typename PointT>
void
pcl_ext::LocalSurfaceIntersection<PointT>::fitBorderPlanes (const pcl::Indices& border)
{
  border_slot_.assign (input_->size(), -1);
  border_planes_.assign (border.size(), LocalPlane());
  border_fitted_.assign (border.size(), 0);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (border.size());
#pragma omp parallel num_threads(resolveThreadCount(threads_))
  {
    pcl::Indices buffer;
#pragma omp for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const auto i = static_cast<std::size_t> (border[static_cast<std::size_t> (k)]);
      border_slot_[i] = static_cast<std::int32_t> (k);
      border_fitted_[static_cast<std::size_t> (k)] =
          fitPlaneOf (border[static_cast<std::size_t> (k)],
                      buffer,
                      border_planes_[static_cast<std::size_t> (k)]);
    }
  }
}

template <typename PointT>
bool
pcl_ext::LocalSurfaceIntersection<PointT>::fitPlaneOf (pcl::index_t i,
                                                       pcl::Indices& buffer,
                                                       LocalPlane& plane) const
{
  const std::uint32_t s = segmentOf (i);
  buffer.clear();
  for (const pcl::index_t j : (*nb_)[static_cast<std::size_t> (i)])
    if (segmentOf (j) == s)
      buffer.push_back (j);
  if (!normals_)
    return fitLocalPlane (*input_, buffer.begin(), buffer.end(), nullptr, plane);
  const pcl::Normal& n = (*normals_)[i];
  const Eigen::Vector3d normal (n.normal_x, n.normal_y, n.normal_z);
  return normal.allFinite() &&
         fitLocalPlane (*input_, buffer.begin(), buffer.end(), &normal, plane);
}

template <typename PointT>
bool
pcl_ext::LocalSurfaceIntersection<PointT>::isInterior (pcl::index_t i) const
{
  const std::uint32_t s = segmentOf (i);
  const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
  for (const pcl::index_t j : (*nb_)[static_cast<std::size_t> (i)])
    if (segmentOf (j) != s || classOf (j) != surface)
      return false;
  return true;
}

template <typename PointT>
void
pcl_ext::LocalSurfaceIntersection<PointT>::nearestOfEachSegment (
    const pcl::Indices& queries,
    SearchBuffers& buffers,
    std::vector<std::size_t>& offsets,
    std::vector<pcl::index_t>& nearest) const
{
  buffers.reaches.resize (queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q)
    buffers.reaches[q] = reachOf (queries[q]);
  partners_.find (queries, buffers.reaches, buffers.scratch, offsets, nearest);
}

template <typename PointT>
void
pcl_ext::LocalSurfaceIntersection<PointT>::intersect (
    const std::vector<std::uint8_t>& on_border, std::vector<Record>& records)
{
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
  const std::ptrdiff_t chunks =
      (rows + detail::kIntersectionChunk - 1) / detail::kIntersectionChunk;
  std::vector<std::vector<Record>> chunk_records (static_cast<std::size_t> (chunks));
  const auto radius = [this] (pcl::index_t i) {
    const auto row = (*nb_)[static_cast<std::size_t> (i)];
    return row.empty() ? 0.0
                       : std::sqrt (static_cast<double> (nb_->getSquaredDistance (
                             static_cast<std::size_t> (i), row.size() - 1)));
  };

#pragma omp parallel num_threads(resolveThreadCount(threads_))
  {
    pcl::Indices buffer, queries;
    SearchBuffers search;
    std::vector<std::size_t> offsets;
    std::vector<pcl::index_t> nearest;
    LocalPlane plane1, plane2;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t c = 0; c < chunks; ++c) {
      auto& out = chunk_records[static_cast<std::size_t> (c)];
      const std::ptrdiff_t end = std::min (rows, (c + 1) * detail::kIntersectionChunk);
      queries.clear();
      for (std::ptrdiff_t r = c * detail::kIntersectionChunk; r < end; ++r) {
        const pcl::index_t i = (*indices_)[r];
        if (on_border[static_cast<std::size_t> (i)])
          queries.push_back (i);
      }
      nearestOfEachSegment (queries, search, offsets, nearest);
      for (std::size_t q = 0; q < queries.size(); ++q) {
        const pcl::index_t i = queries[q];
        const PointT& pi = (*input_)[i];
        if (offsets[q] == offsets[q + 1])
          continue;
        const bool have_plane1 = planeOf (i, buffer, plane1);
        for (std::size_t o = offsets[q]; o < offsets[q + 1]; ++o) {
          const pcl::index_t j = nearest[o];
          Record record;
          record.a = i;
          record.b = j;
          if (!have_plane1 || !planeOf (j, buffer, plane2))
            record.outcome = Outcome::NoPlane;
          // Eq. 9: nearly parallel normals mean a jump discontinuity, not a crease.
          else if (normalAngle (plane1.normal, plane2.normal) < parallel_angle_)
            record.outcome = Outcome::Parallel;
          else {
            const PointT& pj = (*input_)[j];
            const Eigen::Vector3d p1 (pi.x, pi.y, pi.z), p2 (pj.x, pj.y, pj.z);
            if (!intersectLocalPlanes (
                    plane1, plane2, p1, p2, record.point, record.direction))
              record.outcome = Outcome::Parallel;
            else {
              // Default: a plane is trusted as far as the points it was fitted to, the
              // radius of its point's neighbourhood.
              const bool fixed = distance_tolerance_ > 0.0;
              const double tolerance1 = fixed ? distance_tolerance_ : radius (i);
              const double tolerance2 = fixed ? distance_tolerance_ : radius (j);
              const bool far = (record.point - p1).norm() > tolerance1 &&
                               (record.point - p2).norm() > tolerance2;
              record.outcome = far ? Outcome::BeyondTolerance : Outcome::Accepted;
            }
          }
          out.push_back (record);
        }
      }
    }
  }

  // A pair found from both of its points gives the same result twice (the computation
  // is symmetric): keep its first occurrence.
  std::vector<std::tuple<pcl::index_t, pcl::index_t, std::size_t>> keys;
  std::size_t total = 0;
  for (const auto& chunk : chunk_records)
    total += chunk.size();
  keys.reserve (total);
  std::vector<Record> all;
  all.reserve (total);
  for (auto& chunk : chunk_records) {
    for (const auto& rec : chunk) {
      keys.emplace_back (std::min (rec.a, rec.b), std::max (rec.a, rec.b), all.size());
      all.push_back (rec);
    }
    std::vector<Record>().swap (chunk);
  }
  std::sort (keys.begin(), keys.end());
  std::vector<char> duplicate (all.size(), 0);
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (std::get<0> (keys[k]) == std::get<0> (keys[k - 1]) &&
        std::get<1> (keys[k]) == std::get<1> (keys[k - 1]))
      duplicate[std::get<2> (keys[k])] = 1;

  records.clear();
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (duplicate[k])
      continue;
    ++report_.pairs;
    switch (all[k].outcome) {
    case Outcome::Accepted:
      records.push_back (all[k]);
      break;
    case Outcome::Parallel:
      ++report_.parallel;
      break;
    case Outcome::BeyondTolerance:
      ++report_.beyond_tolerance;
      break;
    case Outcome::NoPlane:
      ++report_.no_plane;
      break;
    }
  }
  report_.intersections = records.size();
}

template <typename PointT>
void
pcl_ext::LocalSurfaceIntersection<PointT>::reintegrate (
    const std::vector<Record>& records, LabelCloud& labels)
{
  // The records touching each point, as compressed rows (built serially:
  // deterministic).
  const std::size_t n = input_->size();
  std::vector<std::size_t> offsets (n + 1, 0);
  for (const auto& rec : records) {
    ++offsets[static_cast<std::size_t> (rec.a) + 1];
    ++offsets[static_cast<std::size_t> (rec.b) + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
    offsets[i + 1] += offsets[i];
  std::vector<std::size_t> of_point (offsets.back());
  {
    std::vector<std::size_t> fill (offsets.begin(), offsets.end() - 1);
    for (std::size_t k = 0; k < records.size(); ++k) {
      of_point[fill[static_cast<std::size_t> (records[k].a)]++] = k;
      of_point[fill[static_cast<std::size_t> (records[k].b)]++] = k;
    }
  }

  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
  const std::ptrdiff_t chunks =
      (rows + detail::kIntersectionChunk - 1) / detail::kIntersectionChunk;
  const auto edge = static_cast<std::uint32_t> (PointClass::Edge);
  const auto boundary = static_cast<std::uint32_t> (PointClass::Boundary);
  std::size_t examined = 0, reintegrated = 0, ambiguous = 0, left = 0;
#pragma omp parallel num_threads(resolveThreadCount (threads_)) \
    reduction(+ : examined, reintegrated, ambiguous, left)
  {
    pcl::Indices buffer, queries;
    SearchBuffers search;
    std::vector<std::size_t> rows_of_nearest;
    std::vector<pcl::index_t> nearest;
    LocalPlane plane;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t chunk = 0; chunk < chunks; ++chunk) {
      const std::ptrdiff_t end =
          std::min (rows, (chunk + 1) * detail::kIntersectionChunk);
      queries.clear();
      for (std::ptrdiff_t r = chunk * detail::kIntersectionChunk; r < end; ++r) {
        const pcl::index_t q = (*indices_)[r];
        const std::uint32_t c = classOf (q);
        if ((c == edge || c == boundary) && segmentOf (q) == 0 &&
            pcl::isFinite ((*input_)[q]))
          queries.push_back (q);
      }
      examined += queries.size();
      nearestOfEachSegment (queries, search, rows_of_nearest, nearest);
      for (std::size_t row = 0; row < queries.size(); ++row) {
        const pcl::index_t q = queries[row];
        const PointT& pq = (*input_)[q];
        const Eigen::Vector3d x (pq.x, pq.y, pq.z);
        std::size_t fits = 0;
        pcl::index_t best = -1;
        double best_residual = std::numeric_limits<double>::infinity();
        for (std::size_t o = rows_of_nearest[row]; o < rows_of_nearest[row + 1]; ++o) {
          const pcl::index_t j = nearest[o];
          if (!planeOf (j, buffer, plane))
            continue;
          // The floor only matters on noise-free data, where the RMS is round-off.
          const double tolerance =
              fit_tolerance_ > 0.0
                  ? fit_tolerance_
                  : std::max (3.0 * plane.residualSigma (x), 1e-4 * plane.spread());
          const double residual = std::abs (plane.signedDistance (x));
          if (residual > tolerance)
            continue;
          // "Within the circles": not beyond any intersection line of this surface
          // point, on its own plane.
          const PointT& pj = (*input_)[j];
          const Eigen::Vector3d p (pj.x, pj.y, pj.z);
          bool inside = true;
          for (std::size_t o = offsets[static_cast<std::size_t> (j)];
               inside && o < offsets[static_cast<std::size_t> (j) + 1];
               ++o) {
            const Record& rec = records[of_point[o]];
            const Eigen::Vector3d across =
                plane.normal.cross (rec.direction).normalized();
            const double own_side = across.dot (p - rec.point);
            if (std::abs (own_side) <= tolerance)
              continue; // the point lies on the line: no side to keep
            const double side = across.dot (x - rec.point);
            inside = (own_side > 0.0 ? side : -side) >= -tolerance;
          }
          if (!inside)
            continue;
          ++fits;
          if (residual < best_residual) {
            best_residual = residual;
            best = j;
          }
        }
        if (fits == 0)
          ++left;
        else if (fits == 1) {
          ++reintegrated;
          labels[q].label = segmentOf (best);
        }
        else {
          ++ambiguous;
          if (assign_ambiguous_)
            labels[q].label = segmentOf (best);
        }
      }
    }
  }
  report_.examined = examined;
  report_.reintegrated = reintegrated;
  report_.ambiguous = ambiguous;
  report_.left = left;
}

template <typename PointT>
bool
pcl_ext::LocalSurfaceIntersection<PointT>::compute (IntersectionCloud& intersections,
                                                    LabelCloud& labels)
{
  intersections.clear();
  intersections.width = intersections.height = 0;
  labels.clear();
  labels.width = labels.height = 0;
  report_ = Report();
  if (!initCompute()) {
    PCL_ERROR ("[pcl_ext::LocalSurfaceIntersection::compute] No input cloud.\n");
    return false;
  }
  if (!checkInput()) {
    deinitCompute();
    return false;
  }
  // Neighbourhoods of the whole cloud: a point's partner and the points its plane is
  // fitted to need not be among the indices.
  nb_ = this->prepareNeighbourhoods (
      "LocalSurfaceIntersection::compute", input_, pcl::IndicesConstPtr());
  if (!nb_) {
    deinitCompute();
    return false;
  }
  // The border points of the segments (surface points with a neighbour outside their
  // segment) are what is searched within the reach: the nearest point of a segment to a
  // point outside it is on its border, unless the point lies farther from that segment
  // than its neighbourhood radius across a gap in which nothing was classified.
  const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
  // Each point's kind in parallel (0: neither, 1: segmented surface, 2: also on the
  // border), then the border in index order.
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (input_->size());
  std::vector<std::uint8_t> kind (input_->size(), 0);
#pragma omp parallel for num_threads(resolveThreadCount(threads_)) schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto idx = static_cast<pcl::index_t> (i);
    if (classOf (idx) != surface || segmentOf (idx) == 0 ||
        !pcl::isFinite ((*input_)[i]))
      continue;
    kind[i] = isInterior (idx) ? 1 : 2;
  }
  pcl::IndicesPtr border (new pcl::Indices);
  bool any_segmented = false;
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    any_segmented = any_segmented || kind[i] != 0;
    if (kind[i] == 2)
      border->push_back (static_cast<pcl::index_t> (i));
  }
  if (!any_segmented) {
    PCL_ERROR (
        "[pcl_ext::LocalSurfaceIntersection::compute] No finite point is both a "
        "surface point and in a segment: nothing to intersect or to re-integrate "
        "into.\n");
    nb_ = nullptr;
    this->releaseNeighbourhoods();
    deinitCompute();
    return false;
  }
  partners_.setInput (input_, segments_, border);

  fitBorderPlanes (*border);

  for (auto& k : kind)
    k = k == 2;
  std::vector<Record> records;
  intersect (kind, records);
  labels = *segments_;
  reintegrate (records, labels);
  border_slot_ = std::vector<std::int32_t>();
  border_planes_ = std::vector<LocalPlane>();
  border_fitted_ = std::vector<char>();

  intersections.reserve (records.size());
  for (const auto& rec : records) {
    SurfaceIntersectionPoint p;
    p.x = static_cast<float> (rec.point.x());
    p.y = static_cast<float> (rec.point.y());
    p.z = static_cast<float> (rec.point.z());
    p.segment_a = segmentOf (rec.a);
    p.segment_b = segmentOf (rec.b);
    p.index_a = static_cast<std::int32_t> (rec.a);
    p.index_b = static_cast<std::int32_t> (rec.b);
    intersections.push_back (p);
  }
  intersections.header = input_->header;
  intersections.is_dense = true;

  nb_ = nullptr;
  partners_.clear();
  this->releaseNeighbourhoods();
  deinitCompute();
  return true;
}

#define PCL_EXT_INSTANTIATE_LocalSurfaceIntersection(T)                                \
  template class pcl_ext::LocalSurfaceIntersection<T>;
