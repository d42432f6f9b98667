/*
 * pcl_ext: curves followed across the junctions of a profile (Sithole & Mapurisa,
 * section 4.1.2: entangled curves).
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "edge_adjacency.h"

#include <pcl_ext/common/union_find.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace pcl_ext {
namespace profiles {
namespace {
/** A junction is crossed only where at least this many arms meet it. */
constexpr std::size_t kMinArms = 3;
/** Ends farther apart than this many windows are not one curve through the junction. */
constexpr double kMaxGapWindows = 6.0;
/** The highest degree of the polynomial through a junction. */
constexpr int kMaxJointDegree = 2;
/** An end whose stretch is wider than this share of its length has no direction. */
constexpr double kMaxEndSpread = 0.3;

/** Where a junction meets an arm. */
struct Attachment {
  std::uint32_t junction;
  std::uint32_t arm;
  std::uint32_t point;
};

/** The stretch of an arm at a junction: its points within the window of the anchor. */
struct End {
  std::uint32_t arm = 0;
  std::vector<std::uint32_t> attachments;
  std::vector<std::uint32_t> stretch;
  Eigen::Vector2d anchor = Eigen::Vector2d::Zero();    ///< mean of the attachments
  Eigen::Vector2d direction = Eigen::Vector2d::Zero(); ///< away from the junction
  double window = 0.0;
};

/** The extent and spread of an arm's points. */
struct ArmShape {
  std::size_t size = 0;
  Eigen::Vector2f lo = Eigen::Vector2f::Constant (1e30f);
  Eigen::Vector2f hi = Eigen::Vector2f::Constant (-1e30f);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  Eigen::Vector2f first = Eigen::Vector2f::Zero(); ///< moments are taken about it

  void
  add (const Eigen::Vector2f& p)
  {
    if (size++ == 0)
      first = p;
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
    const Eigen::Vector2d d = (p - first).cast<double>();
    sum += d;
    second += d * d.transpose();
  }

  /** Too few points for an end, shorter than the window, or a blob (no direction) less
   * than two windows across. */
  bool
  partOfJunction (unsigned int min_points, double window) const
  {
    const double extent = (hi - lo).norm();
    if (size < min_points || extent < window)
      return true;
    if (extent >= 2.0 * window)
      return false;
    const Eigen::Vector2d mean = sum / static_cast<double> (size);
    const Eigen::Matrix2d cov =
        second / static_cast<double> (size) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig (cov,
                                                              Eigen::EigenvaluesOnly);
    return !(eig.eigenvalues()[1] > 0.0) ||
           eig.eigenvalues()[0] > kMaxEndSpread * eig.eigenvalues()[1];
  }
};

/** The arm's points reachable from the attachments along the arm's chain edges within
 * the window of the anchor, then the stretch's direction away from the junction.
 * \return false when the stretch is too short or has no direction */
bool
traceEnd (const ProfilePoints& profile,
          const std::vector<std::uint32_t>& arm_of,
          const std::vector<std::uint32_t>& offsets,
          const std::vector<std::uint32_t>& neighbours,
          unsigned int min_points,
          std::vector<std::uint8_t>& visited,
          End& end)
{
  const auto near = [&] (std::uint32_t j) {
    return (profile.uv[j].cast<double>() - end.anchor).norm() <= end.window;
  };
  end.stretch.clear();
  for (const std::uint32_t a : end.attachments)
    if (!visited[a]) {
      visited[a] = 1;
      end.stretch.push_back (a);
    }
  for (std::size_t k = 0; k < end.stretch.size(); ++k) {
    const std::uint32_t i = end.stretch[k];
    for (std::uint32_t q = offsets[i]; q < offsets[i + 1]; ++q) {
      const std::uint32_t j = neighbours[q];
      if (!visited[j] && arm_of[j] == end.arm && near (j)) {
        visited[j] = 1;
        end.stretch.push_back (j);
      }
    }
  }
  for (const std::uint32_t i : end.stretch)
    visited[i] = 0;
  if (end.stretch.size() < min_points)
    return false;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const std::uint32_t i : end.stretch)
    mean += profile.uv[i].cast<double>();
  mean /= static_cast<double> (end.stretch.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const std::uint32_t i : end.stretch) {
    const Eigen::Vector2d d = profile.uv[i].cast<double>() - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig (cov);
  if (!(eig.eigenvalues()[1] > 0.0) ||
      eig.eigenvalues()[0] > kMaxEndSpread * eig.eigenvalues()[1])
    return false;
  end.direction = eig.eigenvectors().col (1);
  if (end.direction.dot (mean - end.anchor) < 0.0)
    end.direction = -end.direction;
  return end.direction.allFinite();
}

/** The residual RMS of one polynomial through both ends, or infinity. */
double
jointResidual (const ProfilePoints& profile,
               const End& a,
               const End& b,
               bool corrected_aic)
{
  const Eigen::Vector2d origin = 0.5 * (a.anchor + b.anchor);
  const Eigen::Vector2d ex = (b.direction - a.direction).normalized();
  const Eigen::Vector2d ey (-ex[1], ex[0]);
  if (!ex.allFinite())
    return std::numeric_limits<double>::infinity();
  std::vector<double> x, y, t;
  double t_mean = 0.0;
  for (const End* end : {&a, &b})
    for (const std::uint32_t i : end->stretch)
      t_mean += profile.t[i];
  t_mean /= static_cast<double> (a.stretch.size() + b.stretch.size());
  for (const End* end : {&a, &b})
    for (const std::uint32_t i : end->stretch) {
      const Eigen::Vector2d d = profile.uv[i].cast<double>() - origin;
      x.push_back (ex.dot (d));
      y.push_back (ey.dot (d));
      t.push_back (profile.t[i] - t_mean);
    }
  // At most a parabola: a curve does not turn back on itself within a junction, and a
  // cubic's inflection would let two curves that touch (a pipe lying across another)
  // pass for one S-shaped curve.
  const PolynomialFit fit = fitPolynomialAic (
      x, y, t, std::max (a.window, b.window), corrected_aic, kMaxJointDegree);
  if (fit.degree < 0)
    return std::numeric_limits<double>::infinity();
  return std::sqrt (std::max (fit.residual_variance, 0.0));
}

/** The ends of the arms at one junction (its attachments, sorted by arm then point):
 * attachments of an arm within twice the threshold of one another are one end. */
void
makeEnds (const ProfilePoints& profile,
          const Attachment* begin,
          const Attachment* end,
          const JunctionParameters& parameters,
          std::vector<End>& ends)
{
  ends.clear();
  const double reach = 2.0 * parameters.threshold;
  for (const Attachment* a = begin; a != end;) {
    const Attachment* b = a;
    while (b != end && b->arm == a->arm)
      ++b;
    const std::size_t count = static_cast<std::size_t> (b - a);
    UnionFind groups (count);
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = i + 1; j < count; ++j)
        if ((profile.uv[a[i].point] - profile.uv[a[j].point]).norm() <= reach)
          groups.unite (static_cast<std::uint32_t> (i), static_cast<std::uint32_t> (j));
    const std::size_t first = ends.size();
    std::vector<std::uint32_t> end_of (count,
                                       std::numeric_limits<std::uint32_t>::max());
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t root = groups.find (static_cast<std::uint32_t> (i));
      if (end_of[root] == std::numeric_limits<std::uint32_t>::max()) {
        end_of[root] = static_cast<std::uint32_t> (ends.size());
        ends.emplace_back();
        ends.back().arm = a->arm;
      }
      ends[end_of[root]].attachments.push_back (a[i].point);
    }
    for (std::size_t e = first; e < ends.size(); ++e) {
      End& x = ends[e];
      for (const std::uint32_t i : x.attachments)
        x.anchor += profile.uv[i].cast<double>();
      x.anchor /= static_cast<double> (x.attachments.size());
      const std::uint32_t lead = x.attachments.front();
      const double scale =
          parameters.window_scale &&
                  parameters.window_scale->size() == profile.uv.size()
              ? std::max (1.0, double ((*parameters.window_scale)[lead]))
              : 1.0;
      x.window = parameters.window * scale;
    }
    a = b;
  }
}

/** The pair's nearest points that may carry a join, as an edge; {0, 0} when none. */
LocalEdge
nearestPoints (const ProfilePoints& profile,
               const End& a,
               const End& b,
               const std::vector<std::uint8_t>* removed)
{
  LocalEdge best{0, 0};
  float best_d = std::numeric_limits<float>::infinity();
  const auto usable = [&] (std::uint32_t i) { return !removed || !(*removed)[i]; };
  for (const std::uint32_t i : a.stretch)
    for (const std::uint32_t j : b.stretch) {
      const float d = (profile.uv[i] - profile.uv[j]).squaredNorm();
      if (d < best_d && usable (i) && usable (j)) {
        best_d = d;
        best = {std::min (i, j), std::max (i, j)};
      }
    }
  return best;
}
} // namespace

void
joinCurvesAcrossJunctions (const ProfilePoints& profile,
                           const std::vector<LocalEdge>& chain_edges,
                           const std::vector<std::uint8_t>& curve_ends,
                           const JunctionParameters& parameters,
                           std::vector<LocalEdge>& joins,
                           std::vector<std::uint32_t>* absorbed)
{
  joins.clear();
  if (absorbed)
    absorbed->clear();
  const std::size_t n = profile.uv.size();
  if (curve_ends.size() != n || !(parameters.window > 0.0) ||
      (parameters.removed && parameters.removed->size() != n) ||
      !(parameters.tolerance > 0.0) ||
      std::find (curve_ends.begin(), curve_ends.end(), 1) == curve_ends.end())
    return;

  // Arms: chains of points that are not curve ends. Within a junction the fits of a
  // few points pass by chance, and where curves cross their points make a blob whose
  // fits are not judged: an arm of fewer points than an end needs, shorter than the
  // window, or a blob less than two windows across is part of the junction.
  // Junctions: chains of the rest.
  UnionFind arms (n), junctions (n);
  for (const LocalEdge& e : chain_edges)
    if (!curve_ends[e.a] && !curve_ends[e.b])
      arms.unite (e.a, e.b);
  std::vector<ArmShape> shape (n);
  for (std::uint32_t i = 0; i < n; ++i)
    if (!curve_ends[i])
      shape[arms.find (i)].add (profile.uv[i]);
  std::vector<std::uint8_t> in_junction (curve_ends.begin(), curve_ends.end());
  for (std::uint32_t i = 0; i < n; ++i)
    if (!curve_ends[i])
      in_junction[i] = shape[arms.find (i)].partOfJunction (parameters.min_end_points,
                                                            parameters.window);
  for (const LocalEdge& e : chain_edges)
    if (in_junction[e.a] && in_junction[e.b])
      junctions.unite (e.a, e.b);
  std::vector<Attachment> attachments;
  for (const LocalEdge& e : chain_edges)
    if (in_junction[e.a] != in_junction[e.b]) {
      const std::uint32_t j = in_junction[e.a] ? e.a : e.b;
      const std::uint32_t p = in_junction[e.a] ? e.b : e.a;
      attachments.push_back ({junctions.find (j), arms.find (p), p});
    }
  if (attachments.empty())
    return;
  const auto key = [] (const Attachment& a) {
    return std::make_tuple (a.junction, a.arm, a.point);
  };
  std::sort (
      attachments.begin(),
      attachments.end(),
      [&] (const Attachment& a, const Attachment& b) { return key (a) < key (b); });
  attachments.erase (std::unique (attachments.begin(),
                                  attachments.end(),
                                  [&] (const Attachment& a, const Attachment& b) {
                                    return key (a) == key (b);
                                  }),
                     attachments.end());

  std::vector<std::uint32_t> arm_of (n);
  for (std::uint32_t i = 0; i < n; ++i)
    arm_of[i] =
        in_junction[i] ? std::numeric_limits<std::uint32_t>::max() : arms.find (i);
  std::vector<std::uint32_t> offsets, neighbours;
  detail::buildAdjacency (
      n,
      [&] (auto f) {
        for (const LocalEdge& e : chain_edges)
          f (e.a, e.b);
      },
      offsets,
      neighbours);
  std::vector<std::uint8_t> visited (n, 0), joined (n, 0);
  std::vector<End> ends;
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  const double cos_turn = std::cos (parameters.max_turn);

  for (std::size_t a = 0; a < attachments.size();) {
    std::size_t b = a;
    std::size_t num_arms = 0;
    while (b < attachments.size() &&
           attachments[b].junction == attachments[a].junction) {
      if (b == a || attachments[b].arm != attachments[b - 1].arm)
        ++num_arms;
      ++b;
    }
    if (num_arms >= kMinArms) {
      makeEnds (
          profile, attachments.data() + a, attachments.data() + b, parameters, ends);
      std::vector<std::uint8_t> usable (ends.size(), 0);
      for (std::size_t e = 0; e < ends.size(); ++e)
        usable[e] = traceEnd (profile,
                              arm_of,
                              offsets,
                              neighbours,
                              parameters.min_end_points,
                              visited,
                              ends[e]);
      pairs.clear();
      for (std::size_t p = 0; p < ends.size(); ++p)
        for (std::size_t q = p + 1; q < ends.size(); ++q) {
          const End &x = ends[p], &y = ends[q];
          // One curve: y continues x beyond the junction, turning by at most max_turn.
          if (!usable[p] || !usable[q] || x.arm == y.arm ||
              -x.direction.dot (y.direction) < cos_turn ||
              (x.anchor - y.anchor).norm() >
                  kMaxGapWindows * std::max (x.window, y.window))
            continue;
          const double rms = jointResidual (profile, x, y, parameters.corrected_aic);
          if (rms <= parameters.tolerance)
            pairs.emplace_back (rms, p, q);
        }
      std::sort (pairs.begin(), pairs.end());
      std::vector<std::uint8_t> taken (ends.size(), 0);
      for (const auto& [rms, p, q] : pairs)
        if (!taken[p] && !taken[q]) {
          const LocalEdge join =
              nearestPoints (profile, ends[p], ends[q], parameters.removed);
          if (join.a == join.b)
            continue;
          taken[p] = taken[q] = 1;
          joins.push_back (join);
          joined[attachments[a].junction] = 1;
        }
    }
    a = b;
  }
  if (absorbed) {
    absorbed->clear();
    for (std::uint32_t i = 0; i < n; ++i)
      if (in_junction[i] && !curve_ends[i] && joined[junctions.find (i)])
        absorbed->push_back (i);
  }
}
} // namespace profiles
} // namespace pcl_ext
