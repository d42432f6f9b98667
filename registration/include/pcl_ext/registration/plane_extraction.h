/*
 * pcl_ext: planes of a scan for plane matching (Khoshelham & Gorte 2009, section 3.1).
 */
#pragma once

#include <pcl_ext/registration/planes.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcl_ext {
/** \brief Where a scan was taken from, to turn each plane's normal to the side it was
 * seen from. Either one position for the whole cloud or one per point (merged scans).
 */
struct ScanViewpoints {
  std::vector<Eigen::Vector3d> positions; ///< scanner positions (cloud frame)
  std::vector<std::uint16_t>
      scanner_of_point; ///< per point index into positions; empty: positions[0]
};

/** \brief Fit a plane to each inlier set and orient it (the common part of every
 * extractor).
 *
 * The fit is the double-precision covariance kernel of pcl_ext (normal = eigenvector of
 * the smallest eigenvalue, rms = sqrt(l0)); d = -n . centroid; the extent is the
 * 1st-99th percentile box of the inliers per axis, so that stray inliers far along the
 * infinite plane do not inflate it. The normal is turned to the scanner side: towards
 * the viewpoint of most inliers (the cloud's sensor origin when \a viewpoints is
 * empty). \return false (PCL_ERROR) when a viewpoint index is out of range; sets with
 * fewer than 3 finite points are skipped
 */
template <typename PointT>
bool
fitScanPlanes (const pcl::PointCloud<PointT>& cloud,
               const std::vector<pcl::PointIndices>& inliers,
               const ScanViewpoints& viewpoints,
               std::vector<ScanPlane>& planes);

/** \brief A plane extractor: inlier sets of the planes of a cloud, as indices of that
 * cloud, taken among the given indices only (none, after a PCL_ERROR, on bad input)
 * (all points when the pointer is null; this is how PlaneMatchingRegistration passes
 * its setIndices). Any segmenter fits (the Belton & Lichti region growing, a
 * range-image segmentation as in the paper, ...). Passing the whole cloud with indices,
 * rather than a copy of the indexed points, keeps per-point inputs of the extractor
 * (labels, viewpoints) aligned with the cloud. */
template <typename PointT>
using PlaneExtractor =
    std::function<void (const typename pcl::PointCloud<PointT>::ConstPtr&,
                        const pcl::IndicesConstPtr&,
                        std::vector<pcl::PointIndices>&)>;

/** \brief Counts the inlier sets whose fitted plane is within \a tolerance_deg of
 * vertical (|n_z| <= sin tolerance), i.e. the walls of Khoshelham & Gorte's constraint
 * 1 (section 3.3). */
template <typename PointT>
int
countVerticalPlanes (const pcl::PointCloud<PointT>& cloud,
                     const std::vector<pcl::PointIndices>& sets,
                     double tolerance_deg = 10.0)
{
  std::vector<ScanPlane> planes;
  if (!fitScanPlanes (cloud, sets, ScanViewpoints(), planes))
    return 0;
  const double limit = std::sin (tolerance_deg * 3.14159265358979323846 / 180.0);
  int count = 0;
  for (const auto& plane : planes)
    if (std::abs (plane.normal.z()) <= limit)
      ++count;
  return count;
}

/** \brief A plane extraction class as a PlaneExtractor: a copy of \a extraction, run on
 * the cloud and indices it is given. \a Extraction is a pcl::PCLBase<PointT> with void
 * extract (std::vector<pcl::PointIndices>&), as SACPlaneExtraction and
 * RoofOutlinePlaneExtraction. */
template <typename PointT, typename Extraction>
PlaneExtractor<PointT>
makePlaneExtractor (const Extraction& extraction)
{
  return [copy = extraction] (const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
                              const pcl::IndicesConstPtr& indices,
                              std::vector<pcl::PointIndices>& planes) mutable {
    copy.setInputCloud (cloud);
    // A null pointer resets to every point (PCLBase makes its own indices in
    // initCompute).
    copy.setIndices (indices ? pcl::make_shared<pcl::Indices> (*indices)
                             : pcl::IndicesPtr());
    copy.extract (planes);
  };
}

/** \brief Sequential RANSAC plane extraction with pcl::SACSegmentation: the largest
 * plane, then the largest of the rest, until \a max_planes or fewer than \a min_inliers
 * remain.
 *
 * Stands in for the gradient-based range image segmentation of Gorte (2007) the paper
 * uses (section 3.1). Deterministic: PCL's RANSAC draws from a fixed seed.
 *
 * Beyond a plain sequential RANSAC, a plane's set leaves out the strips of the surfaces
 * its infinite plane cuts across (the inliers split where they lie more than 2 m apart
 * along the plane's longer axis, the parts whose own plane turns from it by more than
 * 20 degrees left out; they still leave the pool). With them, every wall's extent
 * stretched over the whole building, and the initial walls "longest in plan" were in no
 * useful order: at m = n = 7 three of the five tuning buildings registered 12 or 28 m
 * off (docs/khoshelham_gorte.md).
 */
template <typename PointT>
class SACPlaneExtraction : public pcl::PCLBase<PointT> {
public:
  using PointCloudConstPtr = typename pcl::PointCloud<PointT>::ConstPtr;

  /** \brief Inlier distance (m), > 0; default 0.4 (twice the paper's 20 cm noise). */
  void
  setDistanceThreshold (double distance)
  {
    distance_threshold_ = distance;
  }
  double
  getDistanceThreshold () const
  {
    return distance_threshold_;
  }

  /** \brief Least inliers of a plane, >= 3; default 200. */
  void
  setMinInliers (int count)
  {
    min_inliers_ = count;
  }
  int
  getMinInliers () const
  {
    return min_inliers_;
  }

  /** \brief Most planes extracted, >= 1; default 30 (the paper's real scan gave 32). */
  void
  setMaxPlanes (int count)
  {
    max_planes_ = count;
  }
  int
  getMaxPlanes () const
  {
    return max_planes_;
  }

  /** \brief RANSAC iterations per plane, >= 1; default 500. */
  void
  setMaxIterations (int count)
  {
    max_iterations_ = count;
  }
  int
  getMaxIterations () const
  {
    return max_iterations_;
  }

  /** \brief Inlier sets of the planes, largest first; none when fewer than the minimum
   * of inliers lie on any plane (e.g. too few points). Non-finite points are never
   * inliers. No planes, after a PCL_ERROR, on bad parameters, no input, an index out of
   * range or no finite point. */
  void
  extract (std::vector<pcl::PointIndices>& planes);

  /** \brief As a PlaneExtractor for PlaneMatchingRegistration. */
  PlaneExtractor<PointT>
  asExtractor () const;

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;

  double distance_threshold_ = 0.4;
  int min_inliers_ = 200;
  int max_planes_ = 30;
  int max_iterations_ = 500;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/registration/impl/plane_extraction.hpp>
#endif
