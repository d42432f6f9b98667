/*
 * pcl_ext: the distances between the matched planes of a registration, template part.
 */
#pragma once

#include <pcl_ext/registration/plane_distances.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

template <typename PointT>
bool
pcl_ext::computePlaneDistances (const pcl::PointCloud<PointT>& scan,
                                const std::vector<pcl::PointIndices>& scan_planes,
                                const std::vector<Eigen::Vector4d>& map_planes,
                                const pcl::Correspondences& matches,
                                const Eigen::Matrix4d& transformation,
                                PlaneDistanceMetrics& metrics)
{
  metrics = PlaneDistanceMetrics();
  for (const auto& match : matches) {
    if (match.index_query < 0 ||
        static_cast<std::size_t> (match.index_query) >= scan_planes.size() ||
        match.index_match < 0 ||
        static_cast<std::size_t> (match.index_match) >= map_planes.size()) {
      PCL_ERROR (
          "[pcl_ext::computePlaneDistances] correspondence (%d, %d) is out of range "
          "(%zu scan planes, %zu map planes).\n",
          match.index_query,
          match.index_match,
          scan_planes.size(),
          map_planes.size());
      return false;
    }
    const Eigen::Vector3d normal = map_planes[match.index_match].template head<3>();
    if (!map_planes[match.index_match].allFinite() || !(normal.norm() > 0.0)) {
      PCL_ERROR ("[pcl_ext::computePlaneDistances] map plane %d has no valid normal.\n",
                 match.index_match);
      return false;
    }
  }

  const Eigen::Matrix3d rotation = transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3d translation = transformation.topRightCorner<3, 1>();
  double sum = 0.0, sum_squares = 0.0, sum_plane_means = 0.0, sum_centroids = 0.0;
  std::size_t used_pairs = 0;
  for (const auto& match : matches) {
    const Eigen::Vector4d& plane = map_planes[match.index_match];
    const double norm = plane.head<3>().norm();
    const Eigen::Vector3d n = plane.head<3>() / norm;
    const double d = -plane[3] / norm;

    PlaneDistance pair;
    pair.scan_plane = static_cast<std::size_t> (match.index_query);
    pair.map_plane = static_cast<std::size_t> (match.index_match);
    double pair_sum = 0.0, pair_squares = 0.0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    // Inlier coordinates are summed relative to the first one so large coordinates lose
    // nothing.
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
    Eigen::Vector3d offset_sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto index : scan_planes[match.index_query].indices) {
      if (index < 0 || static_cast<std::size_t> (index) >= scan.size() ||
          !pcl::isXYZFinite (scan[index]))
        continue;
      const Eigen::Vector3d p =
          rotation * scan[index].getVector3fMap().template cast<double>() + translation;
      if (pair.points == 0)
        anchor = p;
      const Eigen::Vector3d q = p - anchor;
      offset_sum += q;
      scatter += q * q.transpose();
      const double distance = std::abs (n.dot (p) - d);
      pair_sum += distance;
      pair_squares += distance * distance;
      pair.max = std::max (pair.max, distance);
      ++pair.points;
    }
    if (pair.points > 0) {
      const double count = static_cast<double> (pair.points);
      pair.mean = pair_sum / count;
      pair.rms = std::sqrt (pair_squares / count);
      centroid = anchor + offset_sum / count;
      pair.centroid_distance = std::abs (n.dot (centroid) - d);
      // The transformed scan plane's normal: the direction of least spread of its
      // inliers.
      if (pair.points >= 3) {
        const Eigen::Vector3d mean_offset = offset_sum / count;
        const Eigen::Matrix3d covariance =
            scatter / count - mean_offset * mean_offset.transpose();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
        const double c =
            std::min (1.0, std::abs (solver.eigenvectors().col (0).dot (n)));
        pair.angle_deg = std::acos (c) * 180.0 / M_PI;
      }
      sum += pair_sum;
      sum_squares += pair_squares;
      metrics.points += pair.points;
      metrics.max = std::max (metrics.max, pair.max);
      metrics.max_angle_deg = std::max (metrics.max_angle_deg, pair.angle_deg);
      sum_plane_means += pair.mean;
      sum_centroids += pair.centroid_distance;
      ++used_pairs;
    }
    metrics.pairs.push_back (pair);
  }
  if (metrics.points > 0) {
    metrics.mean = sum / static_cast<double> (metrics.points);
    metrics.rms = std::sqrt (sum_squares / static_cast<double> (metrics.points));
    metrics.mean_of_planes = sum_plane_means / static_cast<double> (used_pairs);
    metrics.mean_centroid_distance = sum_centroids / static_cast<double> (used_pairs);
  }
  return true;
}

template <typename PointT>
bool
pcl_ext::computePlaneDistances (const pcl::PointCloud<PointT>& scan,
                                const std::vector<ScanPlane>& scan_planes,
                                const std::vector<Plane>& target_planes,
                                const std::vector<PlanePair>& matches,
                                const Eigen::Matrix4d& transformation,
                                PlaneDistanceMetrics& metrics)
{
  std::vector<pcl::PointIndices> inliers;
  for (const auto& plane : scan_planes)
    inliers.push_back (plane.inliers);
  std::vector<Eigen::Vector4d> coefficients;
  for (const auto& plane : target_planes)
    coefficients.push_back (plane.coefficients());
  pcl::Correspondences correspondences;
  for (const auto& pair : matches)
    correspondences.emplace_back (pair.scan, pair.map, 0.f);
  return computePlaneDistances (
      scan, inliers, coefficients, correspondences, transformation, metrics);
}

#define PCL_EXT_INSTANTIATE_computePlaneDistances(T)                                   \
  template bool pcl_ext::computePlaneDistances<T> (                                    \
      const pcl::PointCloud<T>&,                                                       \
      const std::vector<pcl::PointIndices>&,                                           \
      const std::vector<Eigen::Vector4d>&,                                             \
      const pcl::Correspondences&,                                                     \
      const Eigen::Matrix4d&,                                                          \
      pcl_ext::PlaneDistanceMetrics&);                                                 \
  template bool pcl_ext::computePlaneDistances<T> (                                    \
      const pcl::PointCloud<T>&,                                                       \
      const std::vector<pcl_ext::ScanPlane>&,                                          \
      const std::vector<pcl_ext::Plane>&,                                              \
      const std::vector<pcl_ext::PlanePair>&,                                          \
      const Eigen::Matrix4d&,                                                          \
      pcl_ext::PlaneDistanceMetrics&);
