/*
 * pcl_ext: curve fitting in a profile (Sithole & Mapurisa, section 4.1.2, figure 9).
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include "profile_grid.h"
#include <pcl_ext/common/union_find.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace profiles {
namespace {
/** Normal equations of y = sum a_k phi_k over phi = (1, x, x^2, x^3, t), all scaled. */
struct Gram {
  Eigen::Matrix<double, 5, 5> g = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> b = Eigen::Matrix<double, 5, 1>::Zero();
  double yy = 0.0;
  std::size_t n = 0;

  void
  add (double x, double y, double t)
  {
    const double x2 = x * x;
    const double phi[5] = {1.0, x, x2, x2 * x, t};
    // The upper triangle, element by element: Eigen's general rank update costs several
    // times as much on a 5 x 5 matrix.
    for (int c = 0; c < 5; ++c) {
      for (int r = 0; r <= c; ++r)
        g (r, c) += phi[r] * phi[c];
      b[c] += y * phi[c];
    }
    yy += y * y;
    ++n;
  }
};

/** Least squares over the basis functions listed in \a columns; the residual and the
 * AIC. */
template <int K>
bool
fitModel (const Gram& gram,
          const Eigen::Matrix<double, 5, 5>& g,
          const int (&columns)[K],
          Eigen::Vector3d& terms,
          double& rss,
          Eigen::Matrix3d& covariance)
{
  Eigen::Matrix<double, K, K> gs;
  Eigen::Matrix<double, K, 1> bs;
  for (int r = 0; r < K; ++r) {
    bs[r] = gram.b[columns[r]];
    for (int c = 0; c < K; ++c)
      gs (r, c) = g (columns[r], columns[c]);
  }
  // A tiny ridge keeps the t column solvable when the points share one t.
  gs.diagonal().array() += 1e-10 * (gs.trace() / K + 1e-30);
  const Eigen::LDLT<Eigen::Matrix<double, K, K>> ldlt (gs);
  const Eigen::Matrix<double, K, 1> a = ldlt.solve (bs);
  if (!a.allFinite())
    return false;
  terms =
      Eigen::Vector3d (a[1], K > 3 && columns[2] == 2 ? a[2] : 0.0, K > 4 ? a[3] : 0.0);
  rss = std::max (gram.yy - 2.0 * a.dot (bs) + a.dot (gs * a), 0.0);
  // (Phi^T Phi)^-1 for a1..a_degree (columns 1..K-2): their covariance per unit noise
  // variance.
  const Eigen::Matrix<double, K, K> inverse =
      ldlt.solve (Eigen::Matrix<double, K, K>::Identity());
  covariance.setZero();
  for (int r = 1; r + 1 < K; ++r)
    for (int c = 1; c + 1 < K; ++c)
      covariance (r - 1, c - 1) = inverse (r, c);
  return covariance.allFinite();
}

/** Fits the three models (degrees 1 to 3, each with the t term) and keeps the lowest
 * AIC (AICc when \a corrected). A model of p fitted terms has k = p + 1 parameters:
 * the terms and the noise variance (Hurvich & Tsai, 1989). Every model needs one
 * residual degree of freedom (n >= p + 1) for its residual variance. AICc's
 * correction 2 k (k + 1) / (n - k - 1) is infinite at n = k + 1 and undefined below:
 * there a parabola or a cubic is refused (never scored as if the correction were 0,
 * which favours the model that follows the points most closely), and the line, the
 * simplest model and the one kept when no other can be scored, gets an infinite AICc.
 */
PolynomialFit
selectModel (const Gram& gram, bool corrected, int max_degree = 3)
{
  static const int line[3] = {0, 1, 4}, parabola[4] = {0, 1, 2, 4},
                   cubic[5] = {0, 1, 2, 3, 4};
  const Eigen::Matrix<double, 5, 5> g = gram.g.selfadjointView<Eigen::Upper>();
  PolynomialFit best;
  const double n = static_cast<double> (gram.n);
  for (int degree = 1; degree <= std::min (max_degree, 3); ++degree) {
    const int p = degree + 2;
    const int k = p + 1;
    const bool scored = n > k + 1; // AICc's correction is finite
    if (gram.n < static_cast<std::size_t> (p + 1) ||
        (corrected && !scored && degree > 1))
      break;
    Eigen::Vector3d terms;
    Eigen::Matrix3d covariance;
    double rss = 0.0;
    const bool ok = degree == 1   ? fitModel (gram, g, line, terms, rss, covariance)
                    : degree == 2 ? fitModel (gram, g, parabola, terms, rss, covariance)
                                  : fitModel (gram, g, cubic, terms, rss, covariance);
    if (!ok)
      continue;
    // Hurvich & Tsai's small-sample term: a side holds about ten points, where plain
    // AIC still picks the cubic for noise and the cubic's end slopes follow the noise.
    const double aic = !corrected ? n * std::log (rss / n + 1e-12) + 2.0 * k
                       : scored   ? n * std::log (rss / n + 1e-12) + 2.0 * k +
                                      2.0 * k * (k + 1) / (n - k - 1)
                                : std::numeric_limits<double>::infinity();
    if (best.degree < 0 || aic < best.aic) {
      best.degree = degree;
      best.slope = terms[0];
      best.terms = terms;
      best.rss = rss;
      best.residual_variance = rss / (n - p);
      best.aic = aic;
      best.unit_covariance = covariance;
    }
  }
  return best;
}
} // namespace

PolynomialFit
fitPolynomialAic (const std::vector<double>& x,
                  const std::vector<double>& y,
                  const std::vector<double>& t,
                  double scale,
                  bool corrected,
                  int max_degree)
{
  if (!(scale > 0.0) || x.size() != y.size() || x.size() != t.size())
    return PolynomialFit();
  Gram gram;
  for (std::size_t i = 0; i < x.size(); ++i)
    gram.add (x[i] / scale, y[i] / scale, t[i] / scale);
  PolynomialFit fit = selectModel (gram, corrected, max_degree);
  fit.rss *= scale * scale;
  fit.residual_variance *= scale * scale;
  fit.terms[1] /= scale;
  fit.terms[2] /= scale * scale;
  // y and the terms scale together, so (Phi^T Phi)^-1 scales as the terms squared over
  // y^2.
  const Eigen::Vector3d unscale (
      1.0 / scale, 1.0 / (scale * scale), 1.0 / (scale * scale * scale));
  fit.unit_covariance =
      unscale.asDiagonal() * fit.unit_covariance * unscale.asDiagonal();
  return fit;
}

void
scoreCurveTurns (const ProfilePoints& profile,
                 const std::vector<LocalEdge>& chain_edges,
                 const CurveFitParameters& parameters,
                 CurveScores& scores)
{
  const std::size_t n = profile.uv.size();
  scores.evaluated.assign (n, 0);
  scores.turn.assign (n, 0.f);
  scores.rms.assign (n, 0.f);
  scores.noise.assign (n, 0.f);
  scores.turn_sigma.assign (n, 0.f);
  const double window = parameters.window;
  const unsigned int min_side = std::max (parameters.min_side_points, 3u);
  if (n < 2 * min_side || !(window > 0.0) || !(parameters.tangent_radius > 0.0))
    return;

  // Only points of the same chain are fitted together: a curve never borrows points
  // across a gap.
  UnionFind chains (n);
  for (const LocalEdge& e : chain_edges)
    chains.unite (e.a, e.b);
  std::vector<std::uint32_t> chain (n);
  std::vector<Eigen::Vector2f> lo (n, Eigen::Vector2f::Constant (1e30f)),
      hi (n, Eigen::Vector2f::Constant (-1e30f));
  for (std::uint32_t i = 0; i < n; ++i) {
    chain[i] = chains.find (i);
    lo[chain[i]] = lo[chain[i]].cwiseMin (profile.uv[i]);
    hi[chain[i]] = hi[chain[i]].cwiseMax (profile.uv[i]);
  }

  detail::ProfileGrid grid;
  grid.build (profile.uv,
              static_cast<float> (std::max (parameters.threshold, window / 4)));
  const std::vector<float>* window_scale =
      parameters.window_scale && parameters.window_scale->size() == n
          ? parameters.window_scale
          : nullptr;
  std::vector<std::uint32_t> near_points;
  std::vector<float> near_d2;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double scale_i =
        window_scale ? std::max (1.0, double ((*window_scale)[i])) : 1.0;
    const double window_i = window * scale_i,
                 tangent_radius = parameters.tangent_radius * scale_i;
    // A chain shorter than two windows (a small closed curve where the profile grazes a
    // surface) cannot be judged: a turn within it is its shape, not a crease.
    if ((hi[chain[i]] - lo[chain[i]]).norm() < 2.0 * window_i)
      continue;
    const Eigen::Vector2f& p = profile.uv[i];
    // The chain's points within the larger of the window and the tangent radius,
    // searched once for the direction, the side frames and the fits, in the grid's
    // order: each radius's points come in the order a search of that radius gives (the
    // same sums, term by term).
    const float window_reach = static_cast<float> (window_i),
                tangent_reach = static_cast<float> (tangent_radius);
    const float window_reach2 = window_reach * window_reach,
                tangent_reach2 = tangent_reach * tangent_reach;
    near_points.clear();
    near_d2.clear();
    grid.forEachWithin (
        p, std::max (window_reach, tangent_reach), [&] (std::uint32_t j, float d2) {
          if (chain[j] == chain[i]) {
            near_points.push_back (j);
            near_d2.push_back (d2);
          }
        });
    // Local direction of the curve: principal axis of the nearby points of the chain.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    std::size_t count = 0;
    for (std::size_t w = 0; w < near_points.size(); ++w) {
      if (!(near_d2[w] <= tangent_reach2))
        continue;
      const Eigen::Vector2d d = (profile.uv[near_points[w]] - p).cast<double>();
      mean += d;
      cov += d * d.transpose();
      ++count;
    }
    if (count < 3)
      continue;
    mean /= static_cast<double> (count);
    cov = cov / static_cast<double> (count) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig (cov);
    // A blob rather than a curve (a surface lying in the profile, or a knot): no
    // direction.
    if (!(eig.eigenvalues()[1] > 0.0) ||
        eig.eigenvalues()[0] > 0.3 * eig.eigenvalues()[1])
      continue;
    const Eigen::Vector2d e = eig.eigenvectors().col (1);
    const Eigen::Vector2d f (-e[1], e[0]);
    // Where the tangent radius exceeds the window, the window's points alone are
    // fitted.
    if (tangent_reach > window_reach) {
      std::size_t kept = 0;
      for (std::size_t w = 0; w < near_points.size(); ++w)
        if (near_d2[w] <= window_reach2)
          near_points[kept++] = near_points[w];
      near_points.resize (kept);
    }

    Gram side[2];
    double reach[2] = {0.0, 0.0};
    const double scale = window_i;
    // Each side is fitted in its own frame, along the principal axis of its points: on
    // a tight bend (the oblique section of a thin cylinder) a side turns by tens of
    // degrees, and a polynomial in the frame of the point itself would have to follow
    // steep slopes.
    Eigen::Vector2d axis[2] = {e, e};
    if (parameters.side_frames) {
      Eigen::Vector2d sum[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
      Eigen::Matrix2d second[2] = {Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
      double count_side[2] = {0.0, 0.0};
      for (const std::uint32_t j : near_points) {
        const Eigen::Vector2d d = (profile.uv[j] - p).cast<double>() / scale;
        for (int k = 0; k < 2; ++k)
          if (k == 0 ? e.dot (d) <= 0.0 : e.dot (d) >= 0.0) {
            sum[k] += d;
            second[k] += d * d.transpose();
            count_side[k] += 1.0;
          }
      }
      for (int k = 0; k < 2; ++k)
        if (count_side[k] >= 3.0) {
          const Eigen::Vector2d m = sum[k] / count_side[k];
          const Eigen::Matrix2d c = second[k] / count_side[k] - m * m.transpose();
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> side_eig (c);
          Eigen::Vector2d a = side_eig.eigenvectors().col (1);
          if (a.dot (e) < 0.0)
            a = -a;
          if (a.allFinite() && a.dot (e) > 0.1)
            axis[k] = a;
        }
    }
    const Eigen::Vector2d normal_axis[2] = {Eigen::Vector2d (-axis[0][1], axis[0][0]),
                                            Eigen::Vector2d (-axis[1][1], axis[1][0])};
    double side_reach[2] = {0.0, 0.0};
    for (const std::uint32_t j : near_points) {
      const Eigen::Vector2d d = (profile.uv[j] - p).cast<double>();
      const double x = e.dot (d) / scale;
      const double t = (static_cast<double> (profile.t[j]) - profile.t[i]) / scale;
      for (int k = 0; k < 2; ++k)
        if (k == 0 ? x <= 0.0 : x >= 0.0) {
          const double xs = axis[k].dot (d) / scale,
                       ys = normal_axis[k].dot (d) / scale;
          side[k].add (xs, ys, t);
          reach[k] = std::max (reach[k], std::abs (x));
          side_reach[k] = std::max (side_reach[k], k == 0 ? -xs : xs);
        }
    }
    // A side shorter than 40% of the window is a curve end: nothing to compare with.
    if (side[0].n < min_side || side[1].n < min_side || reach[0] < 0.4 ||
        reach[1] < 0.4)
      continue;
    const PolynomialFit left = selectModel (side[0], parameters.corrected_aic),
                        right = selectModel (side[1], parameters.corrected_aic);
    if (left.degree < 0 || right.degree < 0)
      continue;
    // Normals compared at the middle of each side: a fitted polynomial's derivative is
    // steady there and wild at the ends of its range, where noise decides the slope.
    // The turn a smooth curve makes from each middle to the point (its curvature,
    // dtheta/dx = y'' / (1 + y'^2), times the distance) is not a crease and is taken
    // off.
    const double xl = -0.5 * side_reach[0], xr = 0.5 * side_reach[1];
    const double sl = left.slopeAt (xl), sr = right.slopeAt (xr);
    // The distance from each side's middle to the point; in one frame the mean of the
    // two (the sides' curvatures averaged over the whole stretch between the middles).
    const double reach_left = parameters.side_frames ? -xl : 0.5 * (xr - xl);
    const double reach_right = parameters.side_frames ? xr : 0.5 * (xr - xl);
    const double curvature_left = left.secondDerivativeAt (xl) / (1.0 + sl * sl),
                 curvature_right = right.secondDerivativeAt (xr) / (1.0 + sr * sr);
    const double bend =
        parameters.side_frames
            ? curvature_left * reach_left + curvature_right * reach_right
            : 0.5 * (curvature_left + curvature_right) * (xr - xl);
    // The angles of the two sides' axes from the point's direction.
    const double offset = parameters.side_frames
                              ? std::atan2 (f.dot (axis[1]), e.dot (axis[1])) -
                                    std::atan2 (f.dot (axis[0]), e.dot (axis[0]))
                              : 0.0;
    // Standard error of the turn, to first order in the fitted terms of the two
    // (independent) sides: turn = atan (sr) - atan (sl) - (kl Dl + kr Dr), k = y'' / (1
    // + y'^2), D the distances above.
    const auto side_variance =
        [&] (const PolynomialFit& fit, double xm, double s, double sign, double reach) {
          const double w = 1.0 / (1.0 + s * s), ypp = fit.secondDerivativeAt (xm);
          const Eigen::Vector3d ds (1.0, 2.0 * xm, 3.0 * xm * xm),
              dypp (0.0, 2.0, 6.0 * xm);
          const Eigen::Vector3d grad =
              sign * w * ds - reach * (w * dypp - 2.0 * ypp * s * w * w * ds);
          return grad.dot (fit.unit_covariance * grad);
        };
    const double turn_variance = side_variance (left, xl, sl, -1.0, reach_left) +
                                 side_variance (right, xr, sr, 1.0, reach_right);
    scores.evaluated[i] = 1;
    // Per metre of noise: x and y were divided by the window.
    scores.turn_sigma[i] =
        static_cast<float> (std::sqrt (std::max (turn_variance, 0.0)) / scale);
    scores.turn[i] =
        static_cast<float> (std::abs (offset + std::atan (sr) - std::atan (sl) - bend));
    // Each side's residual variance over its residual degrees of freedom (n - p), not
    // over n: at ten points a side and three terms, rss / n is 0.7 of the noise
    // variance.
    scores.rms[i] = static_cast<float> (
        scale * std::sqrt (std::max (left.residual_variance, right.residual_variance)));
    // The larger of two variance estimates is biased upwards, its median over a stack
    // by about 20 % at ten points a side: the noise of the significance test is the
    // pooled estimate of both sides, median-corrected.
    const double dof =
        static_cast<double> (side[0].n + side[1].n) - left.degree - right.degree - 4.0;
    const double median_ratio = std::pow (1.0 - 2.0 / (9.0 * dof), 3);
    scores.noise[i] = static_cast<float> (
        scale * std::sqrt ((left.rss + right.rss) / dof / median_ratio));
  }
}
} // namespace profiles
} // namespace pcl_ext
