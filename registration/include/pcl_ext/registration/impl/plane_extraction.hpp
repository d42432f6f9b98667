/*
 * pcl_ext: planes of a scan for plane matching.
 */
#pragma once

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/indices.h>
#include <pcl_ext/registration/plane_extraction.h>

#include <pcl/ModelCoefficients.h>
#include <pcl/console/print.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace detail {
/** Inliers of a RANSAC plane farther apart than this along the plane's longer axis
 * belong to different parts: wider than the gaps along one wall (a door, a column of
 * windows, the shadow of a pole), narrower than the distance between the parallel walls
 * of a building. */
constexpr double kPartGap = 2.0;
/** A part whose own plane turns from the RANSAC plane by more than this (degrees) is
 * not on it: the strip of another surface that the infinite plane cuts across. */
constexpr double kPartMaxTurnDeg = 20.0;

/** The inliers \a points of a RANSAC plane without the strips of the surfaces it cuts
 * across: split into parts where consecutive points along the plane's longer axis lie
 * more than kPartGap apart, the parts whose own plane is the plane's (kPartMaxTurnDeg)
 * are kept, sorted. The inliers of an infinite plane are its surface, the surfaces in
 * line with it (the other wing of an H, the next facade of a street) and a strip of
 * every wall it cuts across, as high as the wall and twice the inlier distance wide,
 * which stretched a wall's extent over the whole building. All of \a points when fewer
 * than \a min_points would be left or no plane can be fitted. */
template <typename PointT>
pcl::Indices
withoutCrossingStrips (const pcl::PointCloud<PointT>& cloud,
                       const pcl::Indices& points,
                       std::size_t min_points)
{
  Eigen::Matrix3d covariance;
  Eigen::Vector3d centroid;
  EigenDecomposition eigen;
  if (computeLocalCovariance (cloud, points, covariance, centroid) < 3 ||
      !computeEigenDecomposition (covariance, eigen))
    return points;
  const Eigen::Vector3d axis = eigen.vectors.col (2);
  std::vector<std::pair<double, pcl::index_t>> along;
  along.reserve (points.size());
  for (const auto i : points)
    along.emplace_back (
        axis.dot (cloud[i].getVector3fMap().template cast<double>() - centroid), i);
  std::sort (along.begin(), along.end());
  const double min_cosine = std::cos (kPartMaxTurnDeg * M_PI / 180.0);
  pcl::Indices kept, part;
  for (std::size_t first = 0; first < along.size();) {
    std::size_t last = first + 1;
    while (last < along.size() && along[last].first - along[last - 1].first <= kPartGap)
      ++last;
    part.clear();
    for (std::size_t k = first; k < last; ++k)
      part.push_back (along[k].second);
    first = last;
    Eigen::Vector3d part_centroid;
    EigenDecomposition part_eigen;
    if (part.size() < 3 ||
        computeLocalCovariance (cloud, part, covariance, part_centroid) < 3 ||
        !computeEigenDecomposition (covariance, part_eigen) ||
        std::abs (part_eigen.normal().dot (eigen.normal())) < min_cosine)
      continue;
    kept.insert (kept.end(), part.begin(), part.end());
  }
  if (kept.size() < min_points)
    return points;
  std::sort (kept.begin(), kept.end());
  return kept;
}
} // namespace detail

template <typename PointT>
bool
fitScanPlanes (const pcl::PointCloud<PointT>& cloud,
               const std::vector<pcl::PointIndices>& inliers,
               const ScanViewpoints& viewpoints,
               std::vector<ScanPlane>& planes)
{
  planes.clear();
  const bool per_point = !viewpoints.scanner_of_point.empty();
  if (per_point && viewpoints.scanner_of_point.size() != cloud.size()) {
    PCL_ERROR ("[pcl_ext::fitScanPlanes] %zu scanner indices for %zu points.\n",
               viewpoints.scanner_of_point.size(),
               cloud.size());
    return false;
  }
  const Eigen::Vector3d origin =
      cloud.sensor_origin_.template head<3>().template cast<double>();
  for (const auto& set : inliers) {
    std::vector<int> finite;
    finite.reserve (set.indices.size());
    for (const auto i : set.indices)
      if (i >= 0 && static_cast<std::size_t> (i) < cloud.size() &&
          std::isfinite (cloud[i].x) && std::isfinite (cloud[i].y) &&
          std::isfinite (cloud[i].z))
        finite.push_back (i);
    if (finite.size() < 3)
      continue;
    Eigen::Matrix3d covariance;
    ScanPlane plane;
    if (computeLocalCovariance (cloud, finite, covariance, plane.centroid) < 3)
      continue;
    EigenDecomposition eigen;
    if (!computeEigenDecomposition (covariance, eigen))
      continue;
    plane.normal = eigen.normal();
    plane.rms = std::sqrt (std::max (0.0, eigen.values[0]));

    // Scanner side: the viewpoint most inliers were seen from.
    long votes = 0;
    for (const int i : finite) {
      Eigen::Vector3d view = origin;
      if (per_point) {
        const std::size_t s = viewpoints.scanner_of_point[i];
        if (s >= viewpoints.positions.size()) {
          PCL_ERROR ("[pcl_ext::fitScanPlanes] Point %d names scanner %zu of %zu.\n",
                     i,
                     s,
                     viewpoints.positions.size());
          planes.clear();
          return false;
        }
        view = viewpoints.positions[s];
      }
      else if (!viewpoints.positions.empty())
        view = viewpoints.positions[0];
      const Eigen::Vector3d p (cloud[i].x, cloud[i].y, cloud[i].z);
      votes += plane.normal.dot (view - p) >= 0.0 ? 1 : -1;
    }
    if (votes < 0)
      plane.normal = -plane.normal;
    plane.d = -plane.normal.dot (plane.centroid);

    // Robust extent: 1st to 99th percentile per axis.
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      values.reserve (finite.size());
      for (const int i : finite)
        values.push_back (cloud[i].getVector3fMap()[axis]);
      const std::size_t lo = values.size() / 100,
                        hi = values.size() - 1 - values.size() / 100;
      std::nth_element (values.begin(), values.begin() + lo, values.end());
      const double low = values[lo];
      std::nth_element (values.begin(), values.begin() + hi, values.end());
      plane.extent.min()[axis] = low;
      plane.extent.max()[axis] = values[hi];
    }
    plane.size = finite.size();
    plane.inliers.indices.assign (finite.begin(), finite.end());
    plane.inliers.header = cloud.header;
    planes.push_back (std::move (plane));
  }
  return true;
}

template <typename PointT>
void
SACPlaneExtraction<PointT>::extract (std::vector<pcl::PointIndices>& planes)
{
  planes.clear();
  if (!(distance_threshold_ > 0.0) || !std::isfinite (distance_threshold_) ||
      min_inliers_ < 3 || max_planes_ < 1 || max_iterations_ < 1) {
    PCL_ERROR (
        "[pcl_ext::SACPlaneExtraction::extract] Invalid parameters: distance threshold "
        "must be > 0, minimum inliers >= 3, maximum planes and iterations >= 1.\n");
    return;
  }
  if (!this->initCompute()) {
    PCL_ERROR ("[pcl_ext::SACPlaneExtraction::extract] No input cloud.\n");
    return;
  }
  // Finite points only: RANSAC would happily sample NaN. Sorted and unique, as the
  // removal of each plane's inliers below needs.
  pcl::IndicesPtr remaining (new pcl::Indices);
  if (!indicesInRange (
          *indices_, input_->size(), "[pcl_ext::SACPlaneExtraction::extract]")) {
    this->deinitCompute();
    return;
  }
  for (const auto i : *indices_) {
    const PointT& p = (*input_)[i];
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      remaining->push_back (i);
  }
  if (remaining->empty()) {
    PCL_ERROR (
        "[pcl_ext::SACPlaneExtraction::extract] The input has no finite point.\n");
    this->deinitCompute();
    return;
  }
  std::sort (remaining->begin(), remaining->end());
  remaining->erase (std::unique (remaining->begin(), remaining->end()),
                    remaining->end());
  pcl::SACSegmentation<PointT> sac;
  sac.setModelType (pcl::SACMODEL_PLANE);
  sac.setMethodType (pcl::SAC_RANSAC);
  sac.setDistanceThreshold (distance_threshold_);
  sac.setMaxIterations (max_iterations_);
  sac.setOptimizeCoefficients (true);
  sac.setInputCloud (input_);
  while (static_cast<int> (planes.size()) < max_planes_ &&
         static_cast<int> (remaining->size()) >= min_inliers_) {
    sac.setIndices (remaining);
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    sac.segment (inliers, coefficients);
    if (static_cast<int> (inliers.indices.size()) < min_inliers_)
      break;
    // RANSAC's plane rests on 3 samples (and a least-squares polish over a band as
    // thick as the threshold): refit on the inliers and take the inliers of the refit
    // plane, twice.
    for (int pass = 0; pass < 2; ++pass) {
      Eigen::Matrix3d covariance;
      Eigen::Vector3d centroid;
      EigenDecomposition eigen;
      if (computeLocalCovariance (*input_, inliers.indices, covariance, centroid) < 3 ||
          !computeEigenDecomposition (covariance, eigen))
        break;
      const Eigen::Vector3d n = eigen.normal();
      const double d = n.dot (centroid);
      pcl::Indices refit;
      for (const auto i : *remaining)
        if (std::abs (n.dot ((*input_)[i].getVector3fMap().template cast<double>()) -
                      d) <= distance_threshold_)
          refit.push_back (i);
      if (refit.size() < 3)
        break;
      inliers.indices.swap (refit);
    }
    std::sort (inliers.indices.begin(), inliers.indices.end());
    pcl::IndicesPtr rest (new pcl::Indices);
    rest->reserve (remaining->size() - inliers.indices.size());
    std::set_difference (remaining->begin(),
                         remaining->end(),
                         inliers.indices.begin(),
                         inliers.indices.end(),
                         std::back_inserter (*rest));
    remaining = rest;
    // Every inlier leaves the pool; the plane keeps those on its surface.
    inliers.indices = detail::withoutCrossingStrips (
        *input_, inliers.indices, static_cast<std::size_t> (min_inliers_));
    planes.push_back (std::move (inliers));
  }
  this->deinitCompute();
}

template <typename PointT>
PlaneExtractor<PointT>
SACPlaneExtraction<PointT>::asExtractor() const
{
  return makePlaneExtractor<PointT> (*this);
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_SACPlaneExtraction(T)                                      \
  template class pcl_ext::SACPlaneExtraction<T>;                                       \
  template bool pcl_ext::fitScanPlanes<T> (const pcl::PointCloud<T>&,                  \
                                           const std::vector<pcl::PointIndices>&,      \
                                           const pcl_ext::ScanViewpoints&,             \
                                           std::vector<pcl_ext::ScanPlane>&);
