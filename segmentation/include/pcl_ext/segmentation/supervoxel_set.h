/*
 * pcl_ext: adaptive super-voxels (Lim & Suter 2008, section 3.1) without the point
 * type.
 */
#pragma once

#include <pcl_ext/segmentation/adaptive_radius.h>

#include <cstdint>
#include <vector>

namespace pcl_ext {
/** \brief One super-voxel: every point within \a radius of its \a seed (its mid-point).
 */
struct Supervoxel {
  pcl::index_t seed = 0; ///< the mid-point, a point index
  float radius = 0.f;    ///< r of eq. 3 at the last step
  int steps = 0;         ///< iterations of eq. 1-4 done
  pcl::Indices members;  ///< point indices within radius, closest first (seed included)
};

/** \brief The over-segmentation: super-voxels, which super-voxels each point belongs to
 * (several when they overlap), and the adjacency (the l nearest super-voxels by
 * mid-point). */
struct SupervoxelSet {
  std::vector<Supervoxel> supervoxels;
  /** membership_offsets[i] .. [i+1] spans point i's super-voxels in \a membership;
   * empty for non-finite points. Size: cloud size + 1. */
  std::vector<std::size_t> membership_offsets;
  std::vector<std::uint32_t> membership;
  /** adjacency[v]: the l nearest other super-voxels of v, closest first. */
  std::vector<std::vector<std::uint32_t>> adjacency;

  std::size_t
  size () const
  {
    return supervoxels.size();
  }

  bool
  empty () const
  {
    return supervoxels.empty();
  }

  void
  clear ()
  {
    *this = SupervoxelSet();
  }

  /** \brief Number of points that belong to more than one super-voxel. */
  std::size_t
  countOverlappingPoints () const;
};

/** \brief Parameters of the over-segmentation on top of the radius (section 3.1). */
struct SupervoxelParameters {
  AdaptiveRadiusParameters radius; ///< eq. 1-4
  int adjacency = 4; ///< l, the regional neighbours per super-voxel (paper: 4); >= 0
  std::uint64_t seed = 1;   ///< seeds the random choice of mid-points
  unsigned int threads = 0; ///< 0 = all cores; the result does not depend on it
};

/** \brief Over-segment a cloud into adaptive super-voxels (Lim & Suter 2008,
 * section 3.1).
 *
 * Mid-points are drawn at random (seeded) among the points that no super-voxel holds
 * yet, in the order of a seeded hash of each point's coordinates (hashPosition): the
 * draw belongs to the points, not to their indices, so a part of the cloud with a
 * margin around it (a tile) draws the super-voxels of the whole cloud away from its
 * edge, and a shuffled cloud gives the same super-voxels. Each gets the radius of eq.
 * 1-4 and takes every point within it, so super-voxels may overlap. Candidates are
 * evaluated in fixed batches in parallel and accepted in draw order, so the result
 * depends on the seed only, never on the thread count.
 *
 * \param[in] cloud the points (non-finite points are skipped and belong to none)
 * \param[in] colours normalised RGB per point, or empty for no colour factor
 * \param[out] result the super-voxels (cleared on error)
 * \param[out] estimator if not null, receives the radius estimator (reused for local
 * points) \return false with a PCL_ERROR on bad input or parameters
 */
bool
computeAdaptiveSupervoxels (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                            const std::vector<Eigen::Vector3f>& colours,
                            const SupervoxelParameters& parameters,
                            SupervoxelSet& result,
                            AdaptiveRadiusEstimator* estimator = nullptr);
} // namespace pcl_ext
