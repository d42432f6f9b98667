/*
 * pcl_ext: stacks of contiguous profiles (Sithole & Mapurisa, section 2 and 4).
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace profiles {
/** \brief How stack normals are spread when the user gives none. */
enum class StackDistribution {
  Hemisphere, ///< evenly over the upper hemisphere (the paper's extension, figure 7)
  HorizontalHalfCircle ///< evenly over a horizontal half circle (Sithole 2005: vertical
                       ///< profiles)
};

/** \brief \a count unit stack normals spread as far apart as possible.
 *
 * Hemisphere: for 2 to 6 stacks the best known packings of lines through the origin (3:
 * orthogonal axes, 4: the cube diagonals, 5 and 6: the icosahedron's axes), turned so
 * that no normal lies along a coordinate axis (axis-aligned walls would otherwise fall
 * into a single profile); from 7 on a Fibonacci spiral over the hemisphere. Every
 * normal has z >= 0. HorizontalHalfCircle: angles k pi / count in the xy plane. \return
 * an empty list when \a count is 0 */
std::vector<Eigen::Vector3f>
makeStackNormals (unsigned int count, StackDistribution distribution);

/** \brief A sampled point of a cloud and its nearest other points. */
struct SampledNeighbourhood {
  std::uint32_t index = 0; ///< the point's position in the cloud
  Eigen::Vector3f point = Eigen::Vector3f::Zero(); ///< its coordinates
  /** \brief (squared distance, coordinates) of its nearest points at a distance above
   * 0, ascending by distance (ties by position in the cloud), at most the k asked. */
  std::vector<std::pair<float, Eigen::Vector3f>> nearest;
};

/** \brief The axis along which sampleNeighbourhoods samples a cloud whose coordinates
 * lie in [\a lo, \a hi]: that of the largest extent (the first of equal ones). */
inline int
sampleAxis (const Eigen::Vector3f& lo, const Eigen::Vector3f& hi)
{
  int axis = 0;
  (hi - lo).maxCoeff (&axis);
  return axis;
}

/** \brief The rank, in the order of the points along the sample axis (ties by
 * position), of sample \a s of the \a m = min(samples, n) samples of \a n points. */
inline std::size_t
sampleRank (std::size_t s, std::size_t n, std::size_t m)
{
  return s * n / m;
}

/** \brief Up to \a samples points of \a xyz, spread evenly along sampleAxis (those of
 * sampleRank), each with its \a k nearest other points (distance above 0), found by a
 * sweep along that axis without a tree. The sweep stops once the coordinate gap alone
 * exceeds the k-th distance, or after 8192 points on either side (an upper bound on
 * pathological clouds, everything at one coordinate, instead of a quadratic time). */
std::vector<SampledNeighbourhood>
sampleNeighbourhoods (const std::vector<Eigen::Vector3f>& xyz,
                      std::size_t samples,
                      std::size_t k);

/** \brief The spacing estimatePointSpacing gives from sampled neighbourhoods (of at
 * least 6 nearest): the mean of sqrt(pi r6^2 / 6) over those with 6, in their order;
 * 0 when none has. */
double
pointSpacingOf (const std::vector<SampledNeighbourhood>& neighbourhoods);

/** \brief Average point spacing of a surface cloud: the square root of the surface area
 * per point, sqrt(pi r6^2 / 6) with r6 the distance to the 6th nearest distinct
 * neighbour, averaged over a sample of points.
 *
 * Unlike the nearest-neighbour distance this does not shrink on anisotropic scan
 * patterns (close points along a scan line, wide gaps between lines) and is the grid
 * step on a square grid. The points are sorted along the axis of largest extent and
 * each sampled point sweeps outwards in that order until the sweep distance exceeds its
 * 6th distance, so no tree and no whole-cloud kNN is built. Up to \a samples points,
 * evenly spread over the array, are sampled (deterministic). Coincident points are
 * skipped: duplicates do not make the spacing zero. \return the spacing, or 0 when no
 * sampled point has 6 distinct neighbours */
double
estimatePointSpacing (const std::vector<Eigen::Vector3f>& xyz,
                      std::size_t samples = 2048);

/** \brief One stack: every point falls into exactly one profile (slab) of width \a
 * width along the stack normal.
 *
 * Profiles are numbered from the lowest coordinate along the normal; only non-empty
 * profiles are kept, in order. */
struct Stack {
  Eigen::Vector3f normal =
      Eigen::Vector3f::UnitZ();                 ///< the stack normal (phi in the paper)
  Eigen::Vector3f u = Eigen::Vector3f::UnitX(); ///< first in-profile axis
  Eigen::Vector3f v = Eigen::Vector3f::UnitY(); ///< second in-profile axis
  double origin = 0.0; ///< coordinate along normal of profile 0
  double width = 0.0;  ///< profile width
  std::vector<std::uint32_t>
      offsets; ///< profile p holds order[offsets[p] .. offsets[p + 1])
  std::vector<std::uint32_t>
      order; ///< point positions grouped by profile, ascending within
  std::vector<std::uint32_t>
      profile_of_point; ///< the (non-empty) profile of each point

  std::size_t
  numProfiles () const
  {
    return offsets.empty() ? 0 : offsets.size() - 1;
  }
};

/** \brief The direction a stack measures its points along: \a normal made unit length,
 * in double (the coordinate of a point p along it is stackDirection (normal).dot
 * (p.cast<double> ())). */
inline Eigen::Vector3d
stackDirection (const Eigen::Vector3f& normal)
{
  return normal.normalized().cast<double>();
}

/** \brief Slice \a xyz into contiguous profiles of \a width along \a normal (unit
 * length).
 *
 * Profile 0 starts at \a origin, the coordinate along stackDirection (normal); NaN (the
 * default) starts it at the lowest point. A part of a cloud given its whole cloud's
 * origin gets the whole cloud's profiles (those the part holds, each whole when the
 * part holds every point between two profile borders). Bucketing by profile number (a
 * counting sort, O(N)) when there are not many more profiles than points, a comparison
 * sort otherwise. Deterministic. \return false when the width is not positive and
 * finite, there is no point or a point lies below \a origin */
bool
buildStack (const std::vector<Eigen::Vector3f>& xyz,
            const Eigen::Vector3f& normal,
            double width,
            Stack& stack,
            double origin = std::numeric_limits<double>::quiet_NaN());
} // namespace profiles
} // namespace pcl_ext
