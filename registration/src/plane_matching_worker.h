/*
 * pcl_ext: the search worker of matchPlanes (Khoshelham & Gorte 2009, section 3.3): one
 * thread's walk over the initial combinations, their hypotheses and their extension.
 */
#pragma once

#include "plane_matching_context.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace plane_matching {
/** \brief One thread's share of the initiate-and-extend search of Khoshelham & Gorte
 * (2009), section 3.3: the initial combinations of eq. 13 in the tasks it runs, each
 * tried with its sign patterns, screened and estimated (eq. 12, constraint 3), and the
 * survivors extended; keeps the best match set it has seen and its counts. Departures
 * from the text are those of matchPlanes.
 *
 * Its parts live in one source file each: the enumeration of combinations and sign
 * patterns (plane_matching_search.cpp), the scoring of a hypothesis against constraint
 * 3 and the bounds (plane_matching_scoring.cpp), and the extension of an accepted one
 * (plane_matching_extension.cpp). */
class Worker {
public:
  explicit Worker (const Context& c);

  /** \brief All combinations whose first pair is (scan_init[s0], map_init[m0]); \a task
   * numbers them in the enumeration order. */
  void
  run (int s0, int m0, std::uint64_t task);

  PlaneMatchingStatistics stats;
  Candidate best;
  /** \brief The best match set of every distinct pose seen (see keepAlternative). */
  std::vector<Candidate> alternatives;

private:
  double
  scanAngle (int a, int b) const
  {
    return c_.scan_angle[a * c_.scan_init.size() + b];
  }
  double
  mapAngle (int a, int b) const
  {
    return c_.map_angle[a * c_.map_init.size() + b];
  }
  double
  scanTriple (int a, int b, int l) const
  {
    const std::size_t m = c_.scan_init.size();
    return c_.scan_triple[(a * m + b) * m + l];
  }
  double
  mapTriple (int a, int b, int l) const
  {
    const std::size_t n = c_.map_init.size();
    return c_.map_triple[(a * n + b) * n + l];
  }

  /** \name The search over combinations (plane_matching_search.cpp)
   * \{ */
  void
  search (int depth, std::uint64_t used);
  bool
  degenerateMap () const;
  void
  leaf ();
  /** \} */

  /** \name Scoring a hypothesis (plane_matching_scoring.cpp)
   * \{ */
  bool
  estimate (const int* signs,
            int count,
            PlaneTransformationResult& result,
            bool per_pair = false);
  bool
  withinTolerance (const PlaneTransformationResult& r) const;
  bool
  withinBounds (const PlaneTransformationResult& r) const;
  bool
  extentsAgree (const std::vector<PlanePair>& pairs, const Eigen::Matrix4d& t) const;
  void
  prepareScreen ();
  bool
  passesScreen (unsigned mask) const;
  bool
  screen (unsigned mask);
  /** \} */

  /** \brief Extension of an accepted hypothesis (plane_matching_extension.cpp). */
  void
  extend (std::uint64_t order);
  /** \brief Keeps \a candidate among the alternatives unless one of the same pose is
   * better (plane_matching_extension.cpp). */
  void
  keepAlternative (const Candidate& candidate);

  struct Subset {
    int index[4];
    double lambda_q[4]; // lambda_i n_s,i . (a_i - p)
    double offset;      // sum lambda_i d_m,i
    double bound;
  };
  struct ScanSide {
    double q[4];         // n_s,i . (a_i - p)
    double allowance[4]; // distance_tol + normal_slack |a_i - p|
    double magnitude[4]; // for the rounding margin
  };

  const Context& c_;
  int s_[kMaxK] = {}, m_[kMaxK] = {};
  Subset subset_[kMaxSubsets] = {};
  ScanSide scan_side_[kMaxSubsets] = {};
  int screen_scan_[kMaxK] = {
      -1, -1, -1, -1, -1, -1, -1, -1}; // the scan tuple of scan_side_
  int subsets_ = 0;
  Eigen::Matrix3d outer_[kMaxK]; // n_s,i n_m,i^T
  bool screen_ready_ = false, outer_ready_ = false;
  unsigned up_pairs_ = 0,
           up_flipped_ = 0; // near-horizontal pairs; those whose z signs differ
  std::vector<std::uint64_t> known_,
      degenerate_; // degeneracy cache, see the constructor
  int initial_signs_[kMaxK] = {};
  std::uint64_t order_ = 0;
  std::vector<const Plane*> scan_ptr_, map_ptr_;
  std::vector<int> signs_;
  std::vector<PlanePair> pairs_;
  std::vector<char> used_scan_, used_map_;
  PlaneTransformationResult trial_, initial_;
};
} // namespace plane_matching
} // namespace pcl_ext
