/*
 * pcl_ext: initiate-and-extend plane matching (Khoshelham & Gorte 2009, section 3.3),
 * the public entry points: the checks, the search run over threads and the choice of
 * the best match set. The search itself is in plane_matching_context.cpp (candidate
 * generation), plane_matching_search.cpp, plane_matching_scoring.cpp and
 * plane_matching_extension.cpp.
 */
#include <pcl_ext/registration/plane_matching.h>

#include "plane_matching_context.h"
#include "plane_matching_worker.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcl_ext {
namespace {
bool
checkPlanes (const std::vector<Plane>& planes, const char* which)
{
  for (std::size_t i = 0; i < planes.size(); ++i)
    if (!planes[i].normal.allFinite() || !std::isfinite (planes[i].d) ||
        std::abs (planes[i].normal.norm() - 1.0) > 1e-6) {
      PCL_ERROR ("[pcl_ext::matchPlanes] %s plane %zu is not finite or its normal is "
                 "not of unit "
                 "length.\n",
                 which,
                 i);
      return false;
    }
  return true;
}
} // namespace

std::uint64_t
countInitialCombinations (int m, int n, int k)
{
  using namespace plane_matching;
  return saturate (binomial (m, k) * permutations (n, k));
}

bool
checkPlaneMatchingParameters (const PlaneMatchingParameters& p)
{
  using plane_matching::kMaxInitial;
  using plane_matching::kMaxK;
  const char* bad = nullptr;
  if (p.k < 3 || p.k > kMaxK)
    bad = "k must be in [3, 8]";
  else if (p.scan_initial < p.k || p.scan_initial > kMaxInitial)
    bad = "m (scan planes to initiate) must be in [k, 64]";
  else if (p.map_initial < p.k || p.map_initial > kMaxInitial)
    bad = "n (map planes to initiate) must be in [k, 64]";
  else if (!(p.vertical_tolerance_deg > 0.0 && p.vertical_tolerance_deg < 45.0))
    bad = "the vertical tolerance must be in (0, 45) degrees";
  else if (!(p.orientation_tolerance_deg > 0.0 && p.orientation_tolerance_deg < 90.0))
    bad = "the orientation tolerance must be in (0, 90) degrees";
  else if (!(p.angle_tolerance_deg > 0.0 && p.angle_tolerance_deg < 90.0))
    bad = "the angle tolerance must be in (0, 90) degrees";
  else if (!(p.distance_tolerance > 0.0) || !std::isfinite (p.distance_tolerance))
    bad = "the distance tolerance must be positive and finite";
  else if (!(p.extent_margin >= 0.0) || !std::isfinite (p.extent_margin))
    bad = "the extent margin must be >= 0 and finite";
  else if (!(p.max_rotation_from_guess_deg > 0.0))
    bad = "the rotation bound around the guess must be positive (infinity: no bound)";
  else if (!(p.max_translation_from_guess > 0.0))
    bad =
        "the translation bound around the guess must be positive (infinity: no bound)";
  else if (p.ambiguity_pairs < 0)
    bad = "the ambiguity tolerance must be >= 0 pairs";
  else if (!(p.ambiguity_support >= 0.0 && p.ambiguity_support <= 1.0))
    bad = "the ambiguity support ratio must be in [0, 1]";
  else if (p.coverage_pairs < 0)
    bad = "the pose score's tolerance must be >= 0 pairs";
  else if (!(p.coverage_margin >= 0.0 && p.coverage_margin <= 1.0))
    bad = "the pose score's margin must be in [0, 1]";
  else if (p.min_matches < 0)
    bad = "the minimum number of matches must be >= 0";
  else if (!(p.min_conditioning > 0.0 && p.min_conditioning < 1.0))
    bad = "the minimum conditioning must be in (0, 1)";
  if (bad) {
    PCL_ERROR ("[pcl_ext::matchPlanes] Invalid parameters: %s.\n", bad);
    return false;
  }
  return true;
}

namespace {
/** The points of the scan planes that \a matches pairs and \a other does not. */
std::size_t
supportOfPlanesNotIn (const std::vector<Plane>& scan,
                      const std::vector<PlanePair>& matches,
                      const std::vector<PlanePair>& other)
{
  std::size_t support = 0;
  for (const auto& pair : matches)
    if (std::none_of (other.begin(), other.end(), [&] (const PlanePair& o) {
          return o.scan == pair.scan;
        }))
      support += scan[static_cast<std::size_t> (pair.scan)].size;
  return support;
}
} // namespace

bool
matchPlanes (const std::vector<Plane>& scan,
             const std::vector<Plane>& map,
             const PlaneMatchingParameters& parameters,
             PlaneMatchingResult& result,
             const Eigen::Matrix4d& guess,
             const std::function<double (const Eigen::Matrix4d&)>& pose_score)
{
  using plane_matching::Candidate;
  using plane_matching::Worker;
  const auto start = std::chrono::steady_clock::now();
  result = PlaneMatchingResult();
  if (!checkPlaneMatchingParameters (parameters) || !checkPlanes (scan, "scan") ||
      !checkPlanes (map, "map"))
    return false;
  if (!guess.allFinite()) {
    PCL_ERROR ("[pcl_ext::matchPlanes] The guess is not finite.\n");
    return false;
  }
  const int k = parameters.k;
  auto& stats = result.statistics;
  // With a pose score, the workers keep the match sets that the score may choose and
  // those that may then be candidates beside it.
  PlaneMatchingParameters search = parameters;
  if (pose_score)
    search.ambiguity_pairs += parameters.coverage_pairs;
  plane_matching::Context c (scan, map, search);
  if (!plane_matching::prepareContext (c, guess, stats))
    return false;
  const int m = stats.m, n = stats.n;

  // Tasks: the first pair of each combination. Dynamic scheduling balances them; the
  // best match set is chosen by a total order that includes the enumeration order, so
  // threads do not matter.
  std::vector<std::pair<int, int>> tasks;
  for (int s0 = 0; s0 <= m - k; ++s0)
    for (int m0 = 0; m0 < n; ++m0)
      tasks.emplace_back (s0, m0);
  int threads = 1;
#ifdef _OPENMP
  threads = parameters.threads == 0 ? omp_get_max_threads()
                                    : static_cast<int> (parameters.threads);
#endif
  threads = std::max (1, std::min<int> (threads, static_cast<int> (tasks.size())));
  std::vector<Worker> workers (threads, Worker (c));
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (std::ptrdiff_t t = 0; t < static_cast<std::ptrdiff_t> (tasks.size()); ++t) {
    int id = 0;
#ifdef _OPENMP
    id = omp_get_thread_num();
#endif
    workers[id].run (tasks[t].first, tasks[t].second, static_cast<std::uint64_t> (t));
  }

  Candidate best;
  std::vector<Candidate> alternatives;
  for (auto& w : workers) {
    alternatives.insert (
        alternatives.end(), w.alternatives.begin(), w.alternatives.end());
    stats.orientation += w.stats.orientation;
    stats.degenerate += w.stats.degenerate;
    stats.residual += w.stats.residual;
    stats.estimations += w.stats.estimations;
    if (plane_matching::better (w.best, best))
      best = std::move (w.best);
  }
  stats.seconds =
      std::chrono::duration<double> (std::chrono::steady_clock::now() - start).count();
  const std::size_t needed = parameters.min_matches > 0 ? parameters.min_matches : k;
  if (!best.valid) {
    PCL_ERROR ("[pcl_ext::matchPlanes] No combination of %d pairs gave a valid "
               "transform (%llu "
               "combinations after the constraints, %llu degenerate).\n",
               k,
               static_cast<unsigned long long> (stats.orientation),
               static_cast<unsigned long long> (stats.degenerate));
    return false;
  }
  std::sort (alternatives.begin(), alternatives.end(), plane_matching::better);
  // The pose score: the first match set (best first, one per pose) within
  // coverage_pairs of the best whose score is within coverage_margin of the highest
  // there. Those within coverage_pairs come first (more matches first), so the first
  // that passes is one of them.
  std::vector<const Candidate*> distinct{&best};
  for (const auto& a : alternatives)
    if (a.valid &&
        std::none_of (distinct.begin(), distinct.end(), [&] (const Candidate* d) {
          return plane_matching::samePose (d->estimate.transformation,
                                           a.estimate.transformation);
        }))
      distinct.push_back (&a);
  std::vector<double> scores (distinct.size(), 0.0);
  double least_score = -std::numeric_limits<double>::infinity();
  if (pose_score) {
    double highest = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < distinct.size(); ++i) {
      scores[i] = pose_score (distinct[i]->estimate.transformation);
      if (distinct[i]->matches.size() +
              static_cast<std::size_t> (parameters.coverage_pairs) >=
          best.matches.size())
        highest = std::max (highest, scores[i]);
    }
    least_score = highest - parameters.coverage_margin;
  }
  std::size_t chosen = 0;
  if (pose_score)
    while (scores[chosen] < least_score)
      ++chosen;
  const Candidate& top = *distinct[chosen];
  result.matches = top.matches;
  result.estimate = top.estimate;
  // Poses the map cannot tell apart: the best of each distinct pose, best first.
  result.candidates.push_back ({top.support, top.matches, top.estimate});
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const Candidate& a = *distinct[i];
    // As many pairs (within ambiguity_pairs), and the scan planes only it pairs hold as
    // many points as those only the chosen pairs (within ambiguity_support): a ceiling
    // or a roof in the floor's place pairs as many planes as the ground but holds a
    // fraction of its points; the poses of a symmetric map pair the same scan planes.
    // With a pose score, those it turned down are not candidates either.
    if (i == chosen || (pose_score && scores[i] < least_score) ||
        a.matches.size() + static_cast<std::size_t> (parameters.ambiguity_pairs) <
            top.matches.size() ||
        static_cast<double> (supportOfPlanesNotIn (scan, a.matches, top.matches)) <
            parameters.ambiguity_support * static_cast<double> (supportOfPlanesNotIn (
                                               scan, top.matches, a.matches)))
      continue;
    result.candidates.push_back ({a.support, a.matches, a.estimate});
  }
  if (top.matches.size() < needed) {
    PCL_ERROR (
        "[pcl_ext::matchPlanes] The best match set has %zu pairs, fewer than the %zu "
        "required.\n",
        top.matches.size(),
        needed);
    return false;
  }
  result.converged = true;
  return true;
}
} // namespace pcl_ext
