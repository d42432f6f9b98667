/*
 * pcl_ext: EdgeLocalisation implementation.
 */
#pragma once

#include <pcl_ext/classification/edge_localisation.h>
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/segmentation/local_planes.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

template <typename PointT>
bool
pcl_ext::EdgeLocalisation<PointT>::checkInputs (const char* name) const
{
  const std::size_t n = input_->size();
  if (n == 0) {
    PCL_ERROR ("%s The input cloud is empty.\n", name);
    return false;
  }
  if (!onePerPoint (classes_.get(), n, name, "point class", "setPointClasses") ||
      !indicesInRange (*indices_, n, name))
    return false;
  if (!this->checkNeighbourhoodOptions (name, 3))
    return false;
  if (normal_k_ < 3) {
    PCL_ERROR (
        "%s normal k = %d; a normal needs at least 3 points.\n", name, normal_k_);
    return false;
  }
  if (!(max_patch_curvature_ >= 0.0 && max_patch_curvature_ <= 1.0 / 3.0)) {
    PCL_ERROR ("%s maximum patch curvature = %g; valid: 0 .. 1/3.\n",
               name,
               max_patch_curvature_);
    return false;
  }
  if (!(min_angle_ > 0.0 && min_angle_ < 0.5 * M_PI)) {
    PCL_ERROR (
        "%s minimum crease angle = %g rad; valid: (0, pi/2).\n", name, min_angle_);
    return false;
  }
  if (!(max_residual_ > 0.0) || !std::isfinite (max_residual_)) {
    PCL_ERROR (
        "%s maximum residual = %g; it must be finite and > 0.\n", name, max_residual_);
    return false;
  }
  if (!(noise_factor_ >= 0.0) || !std::isfinite (noise_factor_)) {
    PCL_ERROR (
        "%s noise factor = %g; it must be finite and >= 0.\n", name, noise_factor_);
    return false;
  }
  if (!(kink_significance_ >= 0.0) || !std::isfinite (kink_significance_)) {
    PCL_ERROR ("%s kink significance = %g; it must be finite and >= 0.\n",
               name,
               kink_significance_);
    return false;
  }
  if (!(band_width_ > 0.0) || !std::isfinite (band_width_)) {
    PCL_ERROR ("%s band width = %g; it must be finite and > 0.\n", name, band_width_);
    return false;
  }
  return true;
}

namespace pcl_ext {
namespace detail {
/** \brief Whether the neighbourhood's cross-section across the line where two planes
 * meet has a kink there: the section's height y over the distance x across the line,
 * with its axis between the two faces, is fitted by y = c0 + c1 x + c2 |x| (two lines
 * meeting at the line: a crease) and by y = c0 + c1 x + c2 x^2 (a smooth bend: the
 * curved side of a pipe, which two planes also fit); the crease's model must fit
 * better, and its kink c2 must exceed \a significance times its standard error (noise
 * alone bends a section as often one way as the other). */
inline bool
kinkedSection (const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::uint8_t>& on_a,
               const Eigen::Vector3d& normal_a,
               const Eigen::Vector3d& normal_b,
               const Eigen::Vector3d& foot,
               const Eigen::Vector3d& direction,
               double significance)
{
  const Eigen::Vector3d d = direction.normalized();
  // Each face's direction away from the line, within the section: the side its points
  // lie on. The section's axes are their difference (across) and sum (up the V), so a
  // point's coordinates follow from its two projections.
  const Eigen::Vector3d along_a = d.cross (normal_a).normalized(),
                        along_b = d.cross (normal_b).normalized();
  double side_a = 0.0, side_b = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d v = points[i] - foot;
    if (on_a[i])
      side_a += along_a.dot (v);
    else
      side_b += along_b.dot (v);
  }
  const double sign_a = side_a < 0.0 ? -1.0 : 1.0, sign_b = side_b < 0.0 ? -1.0 : 1.0;
  const Eigen::Vector3d x_axis = (sign_a * along_a - sign_b * along_b).normalized(),
                        y_axis = (sign_a * along_a + sign_b * along_b).normalized();
  if (!x_axis.allFinite() || !y_axis.allFinite())
    return true;
  // The moments both fits need: n, x, |x|, x^2, x |x|, x^3, x^4, y, x y, |x| y, x^2 y.
  double n = 0.0, sx = 0.0, sa = 0.0, sxx = 0.0, sxa = 0.0, sx3 = 0.0, sx4 = 0.0,
         sy = 0.0, sxy = 0.0, say = 0.0, sx2y = 0.0, yy = 0.0;
  for (const auto& p : points) {
    const Eigen::Vector3d v = p - foot;
    const double x = x_axis.dot (v), y = y_axis.dot (v), a = std::abs (x), x2 = x * x;
    n += 1.0;
    sx += x;
    sa += a;
    sxx += x2;
    sxa += x * a;
    sx3 += x2 * x;
    sx4 += x2 * x2;
    sy += y;
    sxy += x * y;
    say += a * y;
    sx2y += x2 * y;
    yy += y * y;
  }
  Eigen::Matrix3d kink_g, bend_g;
  kink_g << n, sx, sa, sx, sxx, sxa, sa, sxa, sxx;
  bend_g << n, sx, sxx, sx, sxx, sx3, sxx, sx3, sx4;
  const Eigen::Vector3d kink_b (sy, sxy, say), bend_b (sy, sxy, sx2y);
  const Eigen::LDLT<Eigen::Matrix3d> kink_fit (kink_g), bend_fit (bend_g);
  const Eigen::Vector3d kink_c = kink_fit.solve (kink_b),
                        bend_c = bend_fit.solve (bend_b);
  if (!kink_c.allFinite() || !bend_c.allFinite())
    return true;
  const double kink_rss = std::max (yy - kink_c.dot (kink_b), 0.0),
               bend_rss = std::max (yy - bend_c.dot (bend_b), 0.0);
  if (!(kink_rss < bend_rss))
    return false;
  if (significance <= 0.0 || n <= 3.0)
    return true;
  // Var(c2) = sigma^2 [(G^-1)]_22, sigma^2 from the kink model's residual.
  const Eigen::Vector3d unit_c2 = kink_fit.solve (Eigen::Vector3d::UnitZ());
  const double variance = kink_rss / (n - 3.0) * unit_c2[2];
  return !(variance > 0.0) ||
         std::abs (kink_c[2]) > significance * std::sqrt (variance);
}
} // namespace detail
} // namespace pcl_ext

template <typename PointT>
bool
pcl_ext::EdgeLocalisation<PointT>::localise (LabelCloud& output)
{
  const char* const name = "[pcl_ext::EdgeLocalisation::localise]";
  output.clear();
  output.width = output.height = 0;
  report_ = Report();
  if (!initCompute()) {
    PCL_ERROR ("%s No input cloud.\n", name);
    return false;
  }
  if (!checkInputs (name)) {
    deinitCompute();
    return false;
  }
  const std::size_t n = input_->size();
  if (n > static_cast<std::size_t> (INT32_MAX)) {
    PCL_ERROR ("%s %zu points; at most %d.\n", name, n, INT32_MAX);
    deinitCompute();
    return false;
  }
  // Whole-cloud rows: an edge point's neighbours need not be among the indices.
  const Neighbourhoods<PointT>* const nb = this->prepareNeighbourhoods (
      "EdgeLocalisation::localise", input_, pcl::IndicesConstPtr());
  if (!nb) {
    deinitCompute();
    return false;
  }
  const auto edge = static_cast<std::uint32_t> (PointClass::Edge);

  // The edge points to examine, and every neighbour of theirs (slots: per-point arrays
  // hold only these).
  std::vector<pcl::index_t> candidates;
  std::vector<std::ptrdiff_t> candidate_row;
  for (const auto i : *indices_) {
    if ((*classes_)[i].label != edge || !pcl::isFinite ((*input_)[i]))
      continue;
    const std::ptrdiff_t r = nb->getRowOfPoint (i);
    if (r < 0 || (*nb)[static_cast<std::size_t> (r)].size() < 3)
      continue;
    candidates.push_back (i);
    candidate_row.push_back (r);
  }
  std::vector<std::int32_t> slot (n, -1);
  std::vector<std::ptrdiff_t> slot_row;
  for (const auto r : candidate_row)
    for (const auto j : (*nb)[static_cast<std::size_t> (r)]) {
      if (j < 0 || slot[static_cast<std::size_t> (j)] >= 0)
        continue;
      slot[static_cast<std::size_t> (j)] = static_cast<std::int32_t> (slot_row.size());
      slot_row.push_back (nb->getRowOfPoint (j));
    }
  report_.examined = candidates.size();

  // Each neighbour's normal from its nearest normal_k_ points (zero: none), the
  // surface variance of that patch (eq. 4), the RMS distance of its points from their
  // plane, and its distance to its nearest other point (-1: none).
  const std::size_t slots = slot_row.size();
  std::vector<Eigen::Vector3f> normal (slots, Eigen::Vector3f::Zero());
  std::vector<float> nearest (slots, -1.0f), patch_curvature (slots, -1.0f),
      patch_rms (slots, -1.0f);
  const std::size_t normal_k = static_cast<std::size_t> (normal_k_);
  const unsigned int threads = resolveThreadCount (this->threads_);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
  for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t> (slots); ++s) {
    const std::ptrdiff_t r = slot_row[static_cast<std::size_t> (s)];
    if (r < 0)
      continue;
    const auto row = (*nb)[static_cast<std::size_t> (r)];
    if (row.size() > 1)
      nearest[s] = std::sqrt (nb->getSquaredDistance (static_cast<std::size_t> (r), 1));
    const std::size_t m = std::min (row.size(), normal_k);
    float smallest = 0.0f;
    if (m >= 3 && fitPatchNormal (*input_,
                                  row.begin(),
                                  row.begin() + m,
                                  normal[s],
                                  patch_curvature[s],
                                  &smallest))
      patch_rms[s] = std::sqrt (smallest);
  }

  // Fewer normals than this in a neighbourhood: no faces to fit.
  constexpr std::size_t kMinNormals = 6;
  const double min_cos = std::cos (min_angle_);
  // What each edge point becomes: a surface point, an edge on its crease, or an edge
  // among scattered points.
  enum Verdict : std::uint8_t { kSmooth, kOnCrease, kScattered };
  std::vector<std::uint8_t> verdict (candidates.size(), kSmooth);
#pragma omp parallel num_threads(threads)
  {
    // Per thread, reused from point to point.
    std::vector<Eigen::Vector3d> points;
    std::vector<std::int32_t> with_normal; // positions in the row
    std::vector<std::uint8_t> on_a;        // per position: nearer plane a
    std::vector<float> values;
#pragma omp for schedule(dynamic, 64)
    for (std::ptrdiff_t c = 0; c < static_cast<std::ptrdiff_t> (candidates.size());
         ++c) {
      const std::size_t r = static_cast<std::size_t> (candidate_row[c]);
      const auto row = (*nb)[r];
      const std::size_t k = row.size();
      points.clear();
      with_normal.clear();
      for (std::size_t a = 0; a < k; ++a) {
        const pcl::index_t j = row[a];
        points.push_back ((*input_)[j].getVector3fMap().template cast<double>());
        if (!normal[slot[static_cast<std::size_t> (j)]].isZero())
          with_normal.push_back (static_cast<std::int32_t> (a));
      }
      const auto slotAt = [&] (std::size_t a) {
        return slot[static_cast<std::size_t> (row[a])];
      };
      // The median over the neighbours of a per-slot value (\a skip: those to leave
      // out); -1 when none is left.
      const auto median = [&] (const std::vector<float>& of, float skip) {
        values.clear();
        for (std::size_t a = 0; a < k; ++a)
          if (of[slotAt (a)] != skip)
            values.push_back (of[slotAt (a)]);
        if (values.empty())
          return -1.0f;
        std::nth_element (
            values.begin(), values.begin() + values.size() / 2, values.end());
        return values[values.size() / 2];
      };
      const auto normalAt = [&] (std::int32_t a) -> const Eigen::Vector3f& {
        return normal[slotAt (static_cast<std::size_t> (a))];
      };
      // Whether the neighbourhood spans a crease, and the point lies on it.
      enum Crease { kNone, kNear, kFar };
      const auto crease = [&] () {
        if (with_normal.size() < kMinNormals)
          return kNone;
        // The two normals furthest apart: from the point's own (or the first one's)
        // to the furthest, then from that to the furthest from it.
        const std::int32_t own = slot[static_cast<std::size_t> (candidates[c])];
        const Eigen::Vector3f start =
            normal[own].isZero() ? normalAt (with_normal[0]) : normal[own];
        const auto furthestFrom = [&] (const Eigen::Vector3f& from, float& cosine) {
          std::int32_t best = with_normal[0];
          cosine = 2.0f;
          for (const auto a : with_normal) {
            const float d = std::abs (from.dot (normalAt (a)));
            if (d < cosine) {
              cosine = d;
              best = a;
            }
          }
          return best;
        };
        float cosine;
        const std::int32_t seed_a = furthestFrom (start, cosine);
        const std::int32_t seed_b = furthestFrom (normalAt (seed_a), cosine);
        if (cosine > min_cos)
          return kNone;
        // Two planes, through the seeds with their normals; then every point to the
        // nearer plane and the planes refitted, up to three times.
        LocalPlane plane_a, plane_b;
        static_cast<Plane&> (plane_a) =
            Plane::throughPoint (normalAt (seed_a).template cast<double>(),
                                 points[static_cast<std::size_t> (seed_a)]);
        static_cast<Plane&> (plane_b) =
            Plane::throughPoint (normalAt (seed_b).template cast<double>(),
                                 points[static_cast<std::size_t> (seed_b)]);
        on_a.assign (k, 2);
        bool fitted = true;
        for (int iteration = 0; iteration < 3 && fitted; ++iteration) {
          // Each point to the nearer plane, summed as it goes; an assignment that does
          // not change gives the same planes: done.
          CovarianceSums sums_a, sums_b;
          bool changed = false;
          for (std::size_t a = 0; a < k; ++a) {
            const std::uint8_t nearer_a =
                std::abs (plane_a.signedDistance (points[a])) <=
                std::abs (plane_b.signedDistance (points[a]));
            changed |= nearer_a != on_a[a];
            on_a[a] = nearer_a;
            (nearer_a ? sums_a : sums_b).add (points[a]);
          }
          if (!changed)
            break;
          fitted = fitLocalPlane (sums_a, nullptr, plane_a) &&
                   fitLocalPlane (sums_b, nullptr, plane_b);
        }
        if (!fitted || std::abs (plane_a.normal.dot (plane_b.normal)) > min_cos)
          return kNone;
        // The faces' residual limit: a share of the spacing, or a multiple of the
        // noise of the patches around the point where the noise is the larger (a
        // scan's near field, dense and noisy, whose creases two planes still fit).
        const float nearest_spacing = median (nearest, -1.0f);
        const float noise = median (patch_rms, -1.0f);
        if (!(nearest_spacing >= 0.0f) ||
            std::max (plane_a.rms, plane_b.rms) >
                std::max (max_residual_ * nearest_spacing,
                          noise_factor_ * std::max (noise, 0.0f)))
          return kNone;
        const double spacing =
            std::sqrt (M_PI * static_cast<double> (nb->getSquaredDistance (r, k - 1)) /
                       static_cast<double> (k));
        // The foot of the point on the line where the planes meet (eq. 10-17 with the
        // point itself for both surface points).
        const Eigen::Vector3d q =
            (*input_)[candidates[c]].getVector3fMap().template cast<double>();
        Eigen::Vector3d foot, direction;
        if (!intersectLocalPlanes (plane_a, plane_b, q, q, foot, direction))
          return kNone;
        if (!detail::kinkedSection (points,
                                    on_a,
                                    plane_a.normal,
                                    plane_b.normal,
                                    foot,
                                    direction,
                                    kink_significance_))
          return kNone;
        return (foot - q).norm() <= band_width_ * spacing ? kNear : kFar;
      };
      switch (crease()) {
      case kNear:
        verdict[c] = kOnCrease;
        break;
      case kFar:
        verdict[c] = kSmooth;
        break;
      case kNone: {
        // Without a crease, a neighbourhood of flat patches is a smooth (curved)
        // surface; one of rough patches (vegetation, clutter) stays an edge.
        const float curvature = median (patch_curvature, -1.0f);
        verdict[c] =
            curvature < 0.0f || curvature > max_patch_curvature_ ? kScattered : kSmooth;
        break;
      }
      }
    }
  }

  output = *classes_;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (verdict[c] == kOnCrease)
      ++report_.kept;
    else if (verdict[c] == kScattered)
      ++report_.scattered;
    else {
      output[static_cast<std::size_t> (candidates[c])].label =
          static_cast<std::uint32_t> (PointClass::Surface);
      ++report_.surface;
    }
  }
  this->releaseNeighbourhoods();
  deinitCompute();
  return true;
}

#define PCL_EXT_INSTANTIATE_EdgeLocalisation(T)                                        \
  template class pcl_ext::EdgeLocalisation<T>;
