/*
 * pcl_ext: adaptive super-voxels of Lim & Suter (2008), as a PCL segmenter.
 */
#pragma once

#include <pcl_ext/segmentation/supervoxel_set.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>

#include <vector>

namespace pcl_ext {
/** \brief Adaptive super-voxel over-segmentation (Lim & Suter, "Multi-scale conditional
 * random fields for over-segmented irregular 3D point clouds classification", CVPR
 * workshops 2008, section 3.1, eq. 1-4).
 *
 * Mid-points are drawn at random (seeded) among points no super-voxel holds yet. Each
 * gets a radius iterated from density, curvature, noise and colour variance (eq. 1-4,
 * restated in AdaptiveRadiusParameters), and every point within it belongs to the
 * super-voxel, so super-voxels overlap. Each super-voxel is joined to its l nearest
 * super-voxels (the regional edges of section 3.2).
 *
 * Departures from the text: the radius never falls below the distance to the 5th
 * nearest neighbour (a plane needs points); when no noise constant is given it is
 * estimated from the flattest sampled neighbourhoods (see
 * AdaptiveRadiusEstimator::estimateNoise); the colour factor is applied only when the
 * point type has rgb.
 *
 * extract() gives one PointIndices per super-voxel (overlaps included); segment() gives
 * the full SupervoxelSet (radii, membership, adjacency). Errors (PCL_ERROR, empty
 * output): no or empty cloud, no finite point, fewer finite points than k, invalid
 * parameters.
 */
template <typename PointT>
class AdaptiveSupervoxelSegmentation : public pcl::PCLBase<PointT> {
public:
  using Ptr = pcl::shared_ptr<AdaptiveSupervoxelSegmentation<PointT>>;
  using ConstPtr = pcl::shared_ptr<const AdaptiveSupervoxelSegmentation<PointT>>;

  /** \brief All radius parameters at once (eq. 1-4; see AdaptiveRadiusParameters). */
  void
  setRadiusParameters (const AdaptiveRadiusParameters& p)
  {
    parameters_.radius = p;
  }

  const AdaptiveRadiusParameters&
  getRadiusParameters () const
  {
    return parameters_.radius;
  }

  /** \brief Noise constant sigma (m). Default 0: estimated from the cloud. Range >= 0.
   */
  void
  setNoise (double sigma)
  {
    parameters_.radius.noise = sigma;
  }

  /** \brief k threshold: the radius stops growing when pi rho r^2 passes it. Default
   * 60; > initial k (15). */
  void
  setMaxK (int k)
  {
    parameters_.radius.max_k = k;
  }

  /** \brief damp of eq. 3. Default 0.2 (the paper's); range (0, 1]. */
  void
  setDamping (double damp)
  {
    parameters_.radius.damping = damp;
  }

  /** \brief l, the regional neighbours per super-voxel. Default 4 (the paper's); >= 0.
   */
  void
  setNumberOfRegionalNeighbours (int l)
  {
    parameters_.adjacency = l;
  }

  /** \brief Seed of the random choice of mid-points. Default 1. */
  void
  setSeed (std::uint64_t seed)
  {
    parameters_.seed = seed;
  }

  /** \brief Threads (0, the default: all cores); the result does not depend on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    parameters_.threads = threads;
  }

  const SupervoxelParameters&
  getParameters () const
  {
    return parameters_;
  }

  /** \brief Over-segment the indexed points (indices other than the input's are
   * ignored). */
  void
  segment (SupervoxelSet& supervoxels);

  /** \brief One PointIndices per super-voxel, members closest to the mid-point first.
   */
  void
  extract (std::vector<pcl::PointIndices>& clusters);

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  SupervoxelParameters parameters_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/segmentation/impl/adaptive_supervoxel_segmentation.hpp>
#endif
