/*
 * pcl_ext: LeftoverPlaneAssignment implementation.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>
#include <pcl_ext/segmentation/local_planes.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

template <typename PointT>
bool
pcl_ext::LeftoverPlaneAssignment<PointT>::checkInputs (const char* name) const
{
  const std::size_t n = input_->size();
  if (n == 0) {
    PCL_ERROR ("%s The input cloud is empty.\n", name);
    return false;
  }
  if (!onePerPoint (segments_.get(), n, name, "segment label", "setSegmentLabels") ||
      !indicesInRange (*indices_, n, name))
    return false;
  if (!this->checkNeighbourhoodOptions (name, 2))
    return false;
  if (candidate_k_ < 1) {
    PCL_ERROR ("%s candidate k = %d; it must be at least 1.\n", name, candidate_k_);
    return false;
  }
  if (!(distance_factor_ > 0.0) || !std::isfinite (distance_factor_)) {
    PCL_ERROR ("%s distance factor = %g; it must be finite and > 0.\n",
               name,
               distance_factor_);
    return false;
  }
  return true;
}

template <typename PointT>
bool
pcl_ext::LeftoverPlaneAssignment<PointT>::compute (LabelCloud& output)
{
  const char* const name = "[pcl_ext::LeftoverPlaneAssignment::compute]";
  output.clear();
  output.width = output.height = 0;
  report_ = Report();
  if (!initCompute()) {
    PCL_ERROR ("%s No input cloud.\n", name);
    return false;
  }
  if (!checkInputs (name)) {
    deinitCompute();
    return false;
  }
  // The finite points without a segment, in index order.
  std::vector<pcl::index_t> points;
  for (const auto i : *indices_)
    if ((*segments_)[i].label == 0 && pcl::isFinite ((*input_)[i]))
      points.push_back (i);
  std::sort (points.begin(), points.end());
  points.erase (std::unique (points.begin(), points.end()), points.end());
  const Neighbourhoods<PointT>* const nb = this->prepareNeighbourhoodsCovering (
      "LeftoverPlaneAssignment::compute", input_, points);
  if (!nb) {
    deinitCompute();
    return false;
  }
  report_.examined = points.size();

  const std::size_t k = static_cast<std::size_t> (candidate_k_);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (points.size());
  std::vector<std::uint32_t> joins (points.size(), 0);
#pragma omp parallel num_threads(resolveThreadCount(this->threads_))
  {
    std::vector<std::uint32_t> candidates;
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t s = 0; s < count; ++s) {
      const pcl::index_t i = points[static_cast<std::size_t> (s)];
      const std::ptrdiff_t r = nb->getRowOfPoint (i);
      if (r < 0)
        continue;
      const auto row = (*nb)[static_cast<std::size_t> (r)];
      candidates.clear();
      std::size_t taken = 0;
      for (auto it = row.begin(); it != row.end() && taken < k; ++it) {
        if (*it == i || *it < 0)
          continue;
        ++taken;
        const std::uint32_t b = (*segments_)[*it].label;
        if (b != 0 &&
            std::find (candidates.begin(), candidates.end(), b) == candidates.end())
          candidates.push_back (b);
      }
      std::sort (candidates.begin(), candidates.end());
      const auto& p = (*input_)[i];
      const Eigen::Vector3d point (p.x, p.y, p.z);
      double best = std::numeric_limits<double>::infinity();
      for (const auto b : candidates) {
        CovarianceSums sums;
        for (const auto j : row)
          if (j >= 0 && j != i && (*segments_)[j].label == b) {
            const auto& q = (*input_)[j];
            sums.add (Eigen::Vector3d (q.x, q.y, q.z));
          }
        // The candidate's local plane, as section 4 fits one (a line has none here).
        LocalPlane plane;
        if (sums.size() < kMinPlanePoints || !fitLocalPlane (sums, nullptr, plane) ||
            plane.variance1 < 0.05 * plane.variance2)
          continue;
        // A floor under the residual: an exact plane has none.
        const double residual =
            std::max (plane.rms, 1e-6 * std::sqrt (plane.variance2));
        const double ratio =
            std::abs (plane.normal.dot (point - plane.centroid)) / residual;
        if (ratio <= distance_factor_ && ratio < best) {
          best = ratio;
          joins[static_cast<std::size_t> (s)] = b;
        }
      }
    }
  }
  output = *segments_;
  for (std::size_t s = 0; s < points.size(); ++s)
    if (joins[s] != 0) {
      output[static_cast<std::size_t> (points[s])].label = joins[s];
      ++report_.assigned;
    }
  this->releaseNeighbourhoods();
  deinitCompute();
  return true;
}

#define PCL_EXT_INSTANTIATE_LeftoverPlaneAssignment(T)                                 \
  template class pcl_ext::LeftoverPlaneAssignment<T>;
