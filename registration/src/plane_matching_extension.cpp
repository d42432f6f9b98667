/*
 * pcl_ext: plane matching, extending an accepted hypothesis (Khoshelham & Gorte 2009,
 * section 3.3): every other scan plane, moved by the current transform, paired with the
 * most similar unused map plane and kept when the transform re-estimated with it stays
 * within the tolerances.
 */
#include "plane_matching_worker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace plane_matching {
void
Worker::extend (std::uint64_t order)
{
  used_scan_.assign (c_.scan.size(), 0);
  used_map_.assign (c_.map.size(), 0);
  for (const auto& pair : pairs_) {
    used_scan_[pair.scan] = 1;
    used_map_[pair.map] = 1;
  }
  PlaneTransformationResult current = initial_;
  PlaneTransformer mover (current.transformation);
  // A pass that reaches, unchanged, the plane the previous pass last added sees the
  // state that pass saw from there on, so it would add nothing more: it ends there.
  std::size_t last_added = c_.scan_order.size();
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t position = 0; position < c_.scan_order.size(); ++position) {
      if (!changed && position == last_added)
        break;
      const int j = c_.scan_order[position];
      if (used_scan_[j])
        continue;
      const std::vector<int>& reachable = c_.reachable[j];
      if (std::all_of (
              reachable.begin(), reachable.end(), [&] (int i) { return used_map_[i]; }))
        continue;
      // The image of the scan plane, its extent only once a map plane is near enough.
      const Eigen::Vector3d normal = mover.normal (c_.scan[j]);
      const Eigen::Vector3d centroid = mover.point (c_.scan[j].centroid);
      Eigen::AlignedBox3d extent;
      bool have_extent = false;
      int best_map = -1, best_sign = 1;
      double best_score = std::numeric_limits<double>::infinity();
      for (const int i : reachable) {
        if (used_map_[i])
          continue;
        const double dot = normal.dot (c_.map[i].normal);
        const int sign = c_.p.oriented_normals || dot >= 0.0 ? 1 : -1;
        const double cosine = sign * dot;
        if (cosine < c_.cos_angle_tol)
          continue;
        const double distance = std::abs (c_.map[i].signedDistance (centroid));
        if (distance > c_.distance_tol)
          continue;
        if (c_.p.check_extents) {
          if (!have_extent) {
            extent = mover.extent (c_.scan[j]);
            have_extent = true;
          }
          if (!extentsOverlap (extent, c_.map[i].extent, c_.p.extent_margin))
            continue;
        }
        const double score = std::acos (std::min (1.0, cosine)) / c_.angle_tol +
                             distance / c_.distance_tol;
        if (score < best_score) {
          best_score = score;
          best_map = i;
          best_sign = sign;
        }
      }
      if (best_map < 0)
        continue;
      pairs_.push_back ({j, best_map, best_sign});
      scan_ptr_.clear();
      map_ptr_.clear();
      signs_.clear();
      for (const auto& pair : pairs_) {
        scan_ptr_.push_back (&c_.scan[pair.scan]);
        map_ptr_.push_back (&c_.map[pair.map]);
        signs_.push_back (pair.sign);
      }
      if (estimate (signs_.data(), static_cast<int> (pairs_.size()), trial_) &&
          withinTolerance (trial_) && withinBounds (trial_)) {
        current = trial_;
        mover = PlaneTransformer (current.transformation);
        used_scan_[j] = 1;
        used_map_[best_map] = 1;
        changed = true;
        last_added = position;
      }
      else
        pairs_.pop_back();
    }
  }
  Candidate candidate;
  candidate.valid = true;
  candidate.order = order;
  candidate.estimate = current;
  candidate.matches = pairs_;
  for (const auto& pair : pairs_)
    candidate.support += c_.scan[pair.scan].size;
  if (better (candidate, best)) {
    // Per-pair residuals for the report: only for a new best.
    scan_ptr_.clear();
    map_ptr_.clear();
    signs_.clear();
    for (const auto& pair : pairs_) {
      scan_ptr_.push_back (&c_.scan[pair.scan]);
      map_ptr_.push_back (&c_.map[pair.map]);
      signs_.push_back (pair.sign);
    }
    estimate (
        signs_.data(), static_cast<int> (pairs_.size()), candidate.estimate, true);
  }
  keepAlternative (candidate);
  if (better (candidate, best))
    best = std::move (candidate);
}

void
Worker::keepAlternative (const Candidate& candidate)
{
  // Only match sets that can be within ambiguity_pairs of the best are kept.
  const std::size_t most = std::max (best.matches.size(), candidate.matches.size());
  if (candidate.matches.size() + static_cast<std::size_t> (c_.p.ambiguity_pairs) < most)
    return;
  for (auto& other : alternatives)
    if (samePose (other.estimate.transformation, candidate.estimate.transformation)) {
      if (better (candidate, other))
        other = candidate;
      return;
    }
  alternatives.push_back (candidate);
}
} // namespace plane_matching
} // namespace pcl_ext
