/*
 * pcl_ext: plane matching, scoring a hypothesis (Khoshelham & Gorte 2009, section 3.3,
 * constraint 3): the estimate of a combination under a sign pattern, its residuals
 * against the tolerances, the bounds around a guess and the extents, and the screens
 * that reject a pattern before its estimate.
 */
#include "plane_matching_worker.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace plane_matching {
bool
Worker::estimate (const int* signs,
                  int count,
                  PlaneTransformationResult& result,
                  bool per_pair)
{
  ++stats.estimations;
  return estimatePlaneTransformation (scan_ptr_.data(),
                                      map_ptr_.data(),
                                      signs,
                                      count,
                                      c_.p.model,
                                      result,
                                      c_.p.min_conditioning,
                                      per_pair);
}

bool
Worker::withinTolerance (const PlaneTransformationResult& r) const
{
  return r.valid && r.max_angle <= c_.angle_tol && r.max_distance <= c_.distance_tol &&
         (!c_.p.vertical_constraint ||
          r.transformation (2, 2) >= c_.cos_up_tol * r.scale);
}

// The bounds around the guess: the rotation of R_g^T R (cos = (trace - 1) / 2) and the
// distance between the images of the centre.
bool
Worker::withinBounds (const PlaneTransformationResult& r) const
{
  if (!c_.bounded)
    return true;
  const Eigen::Matrix3d rotation = r.transformation.topLeftCorner<3, 3>() / r.scale;
  const double cosine =
      0.5 * ((c_.guess_rotation.transpose() * rotation).trace() - 1.0);
  if (!(cosine >= c_.cos_rotation_bound))
    return false;
  const Eigen::Vector3d moved = r.transformation.topLeftCorner<3, 3>() * c_.centre +
                                r.transformation.topRightCorner<3, 1>();
  return (moved - c_.guess_centre).norm() <= c_.translation_bound;
}

bool
Worker::extentsAgree (const std::vector<PlanePair>& pairs,
                      const Eigen::Matrix4d& t) const
{
  if (!c_.p.check_extents)
    return true;
  for (const auto& pair : pairs)
    if (!extentsOverlap (transformPlane (c_.scan[pair.scan], t).extent,
                         c_.map[pair.map].extent,
                         c_.p.extent_margin))
      return false;
  return true;
}

// Constraint 3 screened before the estimate by necessary conditions that need none: a
// sign pattern that breaks one cannot pass, so its estimate is skipped, and no
// combination the estimate would accept is rejected.
// 1. Distance (rigid transform, k >= 4). For any four pairs whose map normals span 3D,
// lambda_i
//    = (-1)^i det(the other three normals) gives sum lambda_i n_m,i = 0, which
//    eliminates the translation: for any point p,
//      sum lambda_i r_i = sum lambda_i (R^T n_m,i . (a_i - p) - d_m,i),
//    r_i the distance residual of pair i at its anchor a_i. If the combination passes,
//    |r_i|
//    <= distance_tol and R^T n_m,i = s_i n_s,i + e_i with |e_i| <= normal_slack, hence
//      |sum lambda_i (s_i n_s,i . (a_i - p) - d_m,i)| <= sum |lambda_i| (distance_tol +
//                                                       normal_slack |a_i - p|).
//    A margin of 1e-9 of the magnitudes involved covers rounding (sum lambda_i n_m,i is
//    zero only to rounding, times the map coordinates).
// 2. Up axis (vertical constraint). A near-horizontal pair, both normals within
//    vertical_tol of the z axes, R within angle_tol, turns the scan's up axis within
//    2 vertical_tol + angle_tol (< 90 degrees) of the map's times the sign of
//    s_i n_s,z n_m,z: where that sign is negative, R(2, 2) < 0 and the up test fails.
void
Worker::prepareScreen()
{
  const int k = c_.p.k;
  subsets_ = 0;
  if (c_.distance_screen) {
    // The scan side (p the mean of the four anchors) is shared by the leaves of a scan
    // tuple.
    if (!std::equal (s_, s_ + k, screen_scan_)) {
      std::copy (s_, s_ + k, screen_scan_);
      for (std::size_t t = 0; t < c_.subsets.size(); ++t) {
        const auto& index = c_.subsets[t];
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (int i = 0; i < 4; ++i)
          p += 0.25 * c_.scan_anchor[s_[index[i]]];
        for (int i = 0; i < 4; ++i) {
          const Eigen::Vector3d arm = c_.scan_anchor[s_[index[i]]] - p;
          const double q = c_.scan[c_.scan_init[s_[index[i]]]].normal.dot (arm);
          const double length = arm.norm();
          scan_side_[t].q[i] = q;
          scan_side_[t].allowance[i] = c_.distance_tol + c_.normal_slack * length;
          scan_side_[t].magnitude[i] =
              std::abs (q) + length + c_.scan_anchor_norm[s_[index[i]]];
        }
      }
    }
    for (std::size_t t = 0; t < c_.subsets.size(); ++t) {
      const auto& index = c_.subsets[t];
      Subset& sub = subset_[subsets_];
      int n[4];
      for (int i = 0; i < 4; ++i)
        n[i] = m_[index[i]];
      const double lambda[4] = {mapTriple (n[1], n[2], n[3]),
                                -mapTriple (n[0], n[2], n[3]),
                                mapTriple (n[0], n[1], n[3]),
                                -mapTriple (n[0], n[1], n[2])};
      if (lambda[0] == 0.0 && lambda[1] == 0.0 && lambda[2] == 0.0 && lambda[3] == 0.0)
        continue; // normals in a plane: no condition
      double bound = 0.0, magnitude = 1.0;
      sub.offset = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double dm = -map_ptr_[index[i]]->d; // the paper's d: n . x = d
        sub.index[i] = index[i];
        sub.lambda_q[i] = lambda[i] * scan_side_[t].q[i];
        sub.offset += lambda[i] * dm;
        bound += std::abs (lambda[i]) * scan_side_[t].allowance[i];
        magnitude +=
            std::abs (lambda[i]) * (scan_side_[t].magnitude[i] + std::abs (dm));
      }
      sub.bound = bound + 1e-9 * magnitude;
      ++subsets_;
    }
  }
  up_pairs_ = up_flipped_ = 0;
  if (c_.up_screen)
    for (int i = 0; i < k; ++i)
      if (c_.scan_class[s_[i]] == Horizontal) {
        up_pairs_ |= 1u << i;
        if (scan_ptr_[i]->normal.z() * map_ptr_[i]->normal.z() < 0.0)
          up_flipped_ |= 1u << i;
      }
}

// The screen of the pattern \a mask (bit i set: pair i flipped).
bool
Worker::passesScreen (unsigned mask) const
{
  if ((mask ^ up_flipped_) & up_pairs_)
    return false;
  for (int t = 0; t < subsets_; ++t) {
    const Subset& sub = subset_[t];
    double sum = -sub.offset;
    for (int i = 0; i < 4; ++i)
      sum += (mask >> sub.index[i] & 1u ? -1.0 : 1.0) * sub.lambda_q[i];
    if (std::abs (sum) > sub.bound)
      return false;
  }
  return true;
}

// Whether the pattern \a mask, as the estimate will keep it (mirrored when its affine
// block has a negative determinant), can pass constraint 3.
bool
Worker::screen (unsigned mask)
{
  const int k = c_.p.k;
  if (!screen_ready_) {
    prepareScreen();
    screen_ready_ = true;
  }
  if (c_.p.oriented_normals)
    return passesScreen (mask);
  const bool direct = passesScreen (mask),
             mirror = passesScreen (mask ^ ((1u << k) - 1));
  if (direct == mirror)
    return direct;
  // det (sum s_i n_s,i n_m,i^T) has the sign of the estimate's affine block (N^-1 is
  // positive definite): it tells which of a pattern and its mirror the estimate keeps.
  if (!outer_ready_) {
    for (int i = 0; i < k; ++i)
      outer_[i] = scan_ptr_[i]->normal * map_ptr_[i]->normal.transpose();
    outer_ready_ = true;
  }
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (int i = 0; i < k; ++i)
    c += (mask >> i & 1u ? -1.0 : 1.0) * outer_[i];
  const double det = c.determinant();
  return det > 1e-6 ? direct : det < -1e-6 ? mirror : true;
}
} // namespace plane_matching
} // namespace pcl_ext
