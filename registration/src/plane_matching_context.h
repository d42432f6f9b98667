/*
 * pcl_ext: internals of matchPlanes shared by its source files (Khoshelham & Gorte
 * 2009, section 3.3): limits, plane classes, the candidate match sets and the search
 * context.
 */
#pragma once

#include <pcl_ext/registration/plane_matching.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace plane_matching {
constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr int kMaxInitial = 64; // map positions in use are kept in a 64-bit mask
constexpr int kMaxK = 8;
constexpr int kMaxSubsets = 70;                     // C(kMaxK, 4)
constexpr int kMaxPatternWords = (1 << kMaxK) / 64; // sign patterns as a bit set
constexpr double kMaxDegeneracyCache = 1
                                       << 20; // prefixes in a worker's degeneracy cache

enum PlaneClass { Other = -1, Vertical = 0, Horizontal = 1 };

/** \brief C(n, k), rounded; 0 outside 0 <= k <= n. */
double
binomial (int n, int k);

/** \brief P(n, k) = n! / (n - k)!; 0 outside 0 <= k <= n. */
double
permutations (int n, int k);

/** \brief \a x as a count, saturating at the largest std::uint64_t. */
std::uint64_t
saturate (double x);

/** \brief Whether two boxes overlap within \a margin; an empty box overlaps everything.
 */
inline bool
extentsOverlap (const Eigen::AlignedBox3d& a,
                const Eigen::AlignedBox3d& b,
                double margin)
{
  if (a.isEmpty() || b.isEmpty())
    return true;
  const Eigen::Vector3d m = Eigen::Vector3d::Constant (margin);
  return (a.min().array() - m.array() <= b.max().array()).all() &&
         (b.min().array() - m.array() <= a.max().array()).all();
}

/** \brief Whether two transforms are one pose: within 1 degree and 1 m (a candidate
 * pose of an ambiguous map is farther from the others). */
inline bool
samePose (const Eigen::Matrix4d& a, const Eigen::Matrix4d& b)
{
  const Eigen::Matrix3d r =
      a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>();
  const double cosine = std::min (1.0, std::max (-1.0, 0.5 * (r.trace() - 1.0)));
  return std::acos (cosine) < 3.14159265358979323846 / 180.0 &&
         (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).norm() < 1.0;
}

/** \brief A match set of section 3.3: one initial combination, extended. */
struct Candidate {
  bool valid = false;
  std::vector<PlanePair> matches;
  PlaneTransformationResult estimate;
  std::size_t support = 0; // inliers of the matched scan planes
  std::uint64_t order = 0;
};

/** \brief The best-first total order of match sets: valid first, then more matches,
 * then more support (the inliers of the matched scan planes: the ground rather than a
 * ceiling seen through the windows for the floor), then less residual norm, then
 * earlier in the enumeration (so the thread count does not matter). */
inline bool
better (const Candidate& a, const Candidate& b)
{
  if (!a.valid || !b.valid)
    return a.valid && !b.valid;
  if (a.matches.size() != b.matches.size())
    return a.matches.size() > b.matches.size();
  if (a.support != b.support)
    return a.support > b.support;
  if (a.estimate.residual_norm != b.estimate.residual_norm)
    return a.estimate.residual_norm < b.estimate.residual_norm;
  return a.order < b.order;
}

/** \brief What every search worker shares (Khoshelham & Gorte 2009, section 3.3): the
 * planes, the m and n initial planes of eq. 13, the tables of constraints 1 and 2, the
 * bounds around a guess (beyond the paper) and the sign pattern sets (papers/README.md:
 * unknown signs). */
struct Context {
  const std::vector<Plane>& scan;
  const std::vector<Plane>& map;
  const PlaneMatchingParameters& p;
  std::vector<int> scan_order; // all scan planes, largest first (extension order)
  std::vector<int> scan_init, map_init; // the m and n initial planes
  std::vector<int> scan_class, map_class;
  std::vector<double> scan_angle,
      map_angle; // angle between normals, row-major m x m, n x n
  // Extension: the map planes each scan plane may pair with (all of them, or see
  // matchPlanes).
  std::vector<std::vector<int>> reachable;
  std::vector<std::array<int, 4>>
      subsets; // the 4-subsets of k pairs, for the distance screen
  // Constraints 1 and 2: bit mp of compatible[(s * n + m) * m + sp] is set when the
  // pair (sp, mp) may join a combination that holds the pair (s, m) (initial plane
  // positions).
  std::vector<std::uint64_t> compatible;
  std::vector<double> scan_triple, map_triple; // det(n_a, n_b, n_c), row-major m^3, n^3
  // Sets of sign patterns (bit i of a pattern: pair i flipped), kMaxPatternWords words
  // at most: all of them; per index pair (i < j, in order) those flipping one of the
  // two; per index triple (i < j < l, in order) those flipping an odd number of the
  // three.
  std::vector<std::uint64_t> all_patterns, pair_opposite, triple_odd;
  std::vector<Eigen::Vector3d>
      scan_anchor; // of the m initial scan planes, as the estimate's
  std::vector<double> scan_anchor_norm;
  double angle_tol, cos_angle_tol, distance_tol, orientation_tol, cos_up_tol;
  double normal_slack; // largest |R^T n_m - s n_s| of a pair within the angle tolerance
  // Bounds around the guess: its rotation (nearest rotation to its 3 x 3 block), the
  // centre of the scan planes and where the guess puts it; guess_pairs[sp] has bit mp
  // set when the initial pair (sp, mp) passes the necessary conditions of the bounds
  // (all bits without them).
  bool bounded = false;
  Eigen::Matrix3d guess_rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(),
                  guess_centre = Eigen::Vector3d::Zero();
  double cos_rotation_bound = -1.0, translation_bound = 0.0;
  std::vector<std::uint64_t> guess_pairs;
  bool distance_screen, up_screen,
      screen; // the screens of constraint 3 in use (Worker::screen)

  Context (const std::vector<Plane>& s,
           const std::vector<Plane>& m,
           const PlaneMatchingParameters& params)
  : scan (s), map (m), p (params)
  {
    angle_tol = p.angle_tolerance_deg * kDegree;
    cos_angle_tol = std::cos (angle_tol);
    distance_tol = p.distance_tolerance;
    orientation_tol = p.orientation_tolerance_deg * kDegree;
    cos_up_tol = std::cos (p.vertical_tolerance_deg * kDegree);
    // |R^T n_m - s n_s|^2 = |n_m|^2 + |n_s|^2 - 2 cos, the norms within 1e-6 of 1
    // (checkPlanes).
    normal_slack =
        std::sqrt (2.0 * (1.0 + 1e-6) * (1.0 + 1e-6) - 2.0 * cos_angle_tol) + 1e-9;
    distance_screen =
        p.residual_constraint && p.k >= 4 && p.model == PlaneTransformationModel::Rigid;
    up_screen = p.residual_constraint && p.vertical_constraint &&
                2.0 * p.vertical_tolerance_deg + p.angle_tolerance_deg < 89.0;
    screen = distance_screen || up_screen;
  }
};

/** \brief Candidate generation: fills \a c for the search (the initial planes, the
 * tables of constraints 1 and 2, the bounds around \a guess, the map planes each scan
 * plane may extend to, the sign pattern sets) and the counts of \a stats before the
 * search (m, n, k, unconstrained, vertical). \return false with a PCL_ERROR when fewer
 * than k initial planes of either side remain */
bool
prepareContext (Context& c,
                const Eigen::Matrix4d& guess,
                PlaneMatchingStatistics& stats);
} // namespace plane_matching
} // namespace pcl_ext
