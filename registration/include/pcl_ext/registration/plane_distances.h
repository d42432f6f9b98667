/*
 * pcl_ext: the distances between the matched planes of a registration (Khoshelham &
 * Gorte 2009, section 4, Tables 1-2).
 */
#pragma once

#include <pcl_ext/registration/plane_transformation_estimation.h>
#include <pcl_ext/registration/planes.h>

#include <pcl/PointIndices.h>
#include <pcl/correspondence.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl_ext {
/** \brief Distances between one transformed scan plane and its map plane. */
struct PlaneDistance {
  std::size_t scan_plane = 0; ///< index into the scan's planes
  std::size_t map_plane = 0;  ///< index into the map's planes
  std::size_t points = 0;     ///< finite inlier points used
  double mean = 0.0; ///< mean |distance| of the transformed inliers to the map plane
  double max = 0.0;  ///< largest |distance| among them
  double rms = 0.0;  ///< root mean square distance
  double centroid_distance = 0.0; ///< |distance| of the transformed inlier centroid
  double angle_deg = 0.0; ///< angle between the lines of the two normals, in [0, 90]
};

/** \brief Accuracy of a registration to planes, as Khoshelham & Gorte's Tables 1-2.
 *
 * The paper reports "the mean and the maximum distance between the transformed
 * pointcloud planes and the map planes" without defining it; pcl_ext measures it on the
 * points: every inlier point of every matched scan plane is transformed and its
 * orthogonal distance to the (infinite) matched map plane taken. With noise sigma and a
 * perfect transform, the mean is sigma sqrt(2 / pi) ~ 0.8 sigma and the maximum a few
 * sigma: the paper's 0.27 m mean and 1.03 m maximum at 20 cm noise are of that order,
 * the excess of the mean over 0.16 m being the residual misalignment. mean_of_planes
 * and mean_centroid_distance are given as well, since the point mean weights large
 * planes more.
 */
struct PlaneDistanceMetrics {
  std::vector<PlaneDistance> pairs; ///< one per valid correspondence, in input order
  std::size_t points = 0;           ///< inlier points over all pairs
  double mean = 0.0; ///< mean |distance| over all those points (Tables 1-2 "mean")
  double max = 0.0;  ///< largest |distance| (Tables 1-2 "max")
  double rms = 0.0;  ///< root mean square distance over all points
  double mean_of_planes =
      0.0; ///< mean over pairs of their mean (each plane counts once)
  double mean_centroid_distance = 0.0; ///< mean over pairs of centroid_distance
  double max_angle_deg = 0.0;          ///< largest normal angle over pairs
};

/** \brief Mean and maximum distance between matched planes after transformation.
 *
 * \param[in] scan the scan cloud (source coordinates)
 * \param[in] scan_planes inliers of each scan plane (e.g. a plane segmenter's output)
 * \param[in] map_planes map planes (a, b, c, d): points x on the plane satisfy
 * n . x + d = 0 with n = (a, b, c), as pcl::ModelCoefficients and
 * pcl_ext::Plane::coefficients() (Khoshelham & Gorte eq. 3's pi); n need not be unit,
 * it is normalised \param[in] matches index_query = scan plane, index_match = map plane
 * (as pcl::Correspondence) \param[in] transformation the scan-to-map transform to
 * assess \param[out] metrics the result (reset first) \return false (error printed,
 * empty metrics) when a correspondence is out of range or a map normal is zero or not
 * finite. Non-finite points are skipped; a pair without any finite inlier is reported
 * with points = 0 and left out of the means.
 */
template <typename PointT>
bool
computePlaneDistances (const pcl::PointCloud<PointT>& scan,
                       const std::vector<pcl::PointIndices>& scan_planes,
                       const std::vector<Eigen::Vector4d>& map_planes,
                       const pcl::Correspondences& matches,
                       const Eigen::Matrix4d& transformation,
                       PlaneDistanceMetrics& metrics);

/** \brief computePlaneDistances on a plane matching's own planes and match set: the
 * inliers of \a scan_planes, the coefficients() of \a target_planes and one
 * correspondence per pair of \a matches (scan plane to target plane).
 *
 * PlaneMatchingRegistration::getPlaneDistances() measures its last align() with it;
 * call it directly for another match set, such as one of
 * PlaneMatchingResult::candidates with its transform.
 * \param[in] scan the scan cloud (source coordinates), which the inliers index
 * \param[in] scan_planes the scan planes (PlaneMatchingRegistration::getSourcePlanes())
 * \param[in] target_planes the planes matched to (getTargetPlanes(): the map's, or scan
 * to scan the target cloud's)
 * \param[in] matches pairs of indices into \a scan_planes and \a target_planes
 * \param[in] transformation the scan-to-map transform to assess
 * \param[out] metrics the result (reset first)
 * \return as computePlaneDistances above */
template <typename PointT>
bool
computePlaneDistances (const pcl::PointCloud<PointT>& scan,
                       const std::vector<ScanPlane>& scan_planes,
                       const std::vector<Plane>& target_planes,
                       const std::vector<PlanePair>& matches,
                       const Eigen::Matrix4d& transformation,
                       PlaneDistanceMetrics& metrics);
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/registration/impl/plane_distances.hpp>
#endif
