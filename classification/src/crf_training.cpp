/*
 * pcl_ext: pseudo-likelihood training of the multi-scale CRF (Lim & Suter 2008, eq. 9).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace pcl_ext
{
namespace crf
{
namespace
{
// Nodes per partial sum: fixed, so that the summation order (and the result, bit for bit)
// does not depend on the thread count.
constexpr std::size_t kChunk = 256;

double
logSumExp (const double* v, std::size_t n)
{
  const double m = *std::max_element (v, v + n);
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    s += std::exp (v[i] - m);
  return m + std::log (s);
}
}  // namespace

double
pseudoLikelihood (const Graph& graph, const std::vector<double>& node_weights,
                  const std::vector<int>& context_labels, const Eigen::VectorXd& theta,
                  std::size_t classes, double sigma, Eigen::VectorXd& gradient,
                  unsigned int threads)
{
  const std::size_t C = classes;
  const std::size_t D = static_cast<std::size_t> (graph.z.cols ());
  const std::size_t D1 = D + 1;
  const std::size_t block = C * D1;
  // theta block b, class c, feature d (d = 0: bias), column-major C x D1
  auto at = [&] (std::size_t b, std::size_t c, std::size_t d) { return b * block + d * C + c; };
  const std::size_t N = graph.size ();
  const std::size_t chunks = (N + kChunk - 1) / kChunk;
  std::vector<Eigen::VectorXd> partial_grad (chunks);
  std::vector<double> partial_loss (chunks, 0.0);
  const int nthreads = static_cast<int> (resolveThreadCount (threads));
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 1)
  for (std::ptrdiff_t ch = 0; ch < static_cast<std::ptrdiff_t> (chunks); ++ch)
  {
    Eigen::VectorXd g = Eigen::VectorXd::Zero (theta.size ());
    double loss = 0.0;
    std::vector<double> score (C), p (C), edge_feature (D1);
    for (std::size_t n = ch * kChunk; n < std::min (N, (ch + 1) * kChunk); ++n)
    {
      const int y = graph.labels[n];
      const double w = node_weights[n];
      if (y < 0 || w <= 0.0)
        continue;
      const std::size_t nb = n < graph.num_supervoxels ? 0 : 1;
      const auto z = graph.z.row (static_cast<Eigen::Index> (n));
      for (std::size_t c = 0; c < C; ++c)
      {
        double s = theta[at (nb, c, 0)];
        for (std::size_t d = 0; d < D; ++d)
          s += theta[at (nb, c, d + 1)] * z (static_cast<Eigen::Index> (d));
        score[c] = s;
      }
      // Labelled neighbours raise the score of their own label (associative potentials).
      for (std::size_t a = graph.adj_offsets[n]; a < graph.adj_offsets[n + 1]; ++a)
      {
        const std::uint32_t e = graph.adj_edge[a];
        const std::uint32_t o = graph.other (e, static_cast<std::uint32_t> (n));
        const int yo = context_labels[o];
        if (yo < 0)
          continue;
        const std::size_t eb = graph.edge_regional[e] ? 3 : 2;
        const auto zo = graph.z.row (o);
        double s = theta[at (eb, yo, 0)];
        for (std::size_t d = 0; d < D; ++d)
          s += theta[at (eb, yo, d + 1)] * edgeFeature (z (d), zo (d));
        score[yo] += softplus (s);
      }
      const double lse = logSumExp (score.data (), C);
      loss += w * (lse - score[y]);
      for (std::size_t c = 0; c < C; ++c)
        p[c] = std::exp (score[c] - lse) - (static_cast<int> (c) == y ? 1.0 : 0.0);
      for (std::size_t c = 0; c < C; ++c)
      {
        const double r = w * p[c];
        g[at (nb, c, 0)] += r;
        for (std::size_t d = 0; d < D; ++d)
          g[at (nb, c, d + 1)] += r * z (d);
      }
      for (std::size_t a = graph.adj_offsets[n]; a < graph.adj_offsets[n + 1]; ++a)
      {
        const std::uint32_t e = graph.adj_edge[a];
        const std::uint32_t o = graph.other (e, static_cast<std::uint32_t> (n));
        const int yo = context_labels[o];
        if (yo < 0)
          continue;
        const std::size_t eb = graph.edge_regional[e] ? 3 : 2;
        const auto zo = graph.z.row (o);
        double u = theta[at (eb, yo, 0)];
        for (std::size_t d = 0; d < D; ++d)
          u += theta[at (eb, yo, d + 1)] * edgeFeature (z (d), zo (d));
        const double r = w * p[yo] * sigmoid (u);
        g[at (eb, yo, 0)] += r;
        for (std::size_t d = 0; d < D; ++d)
          g[at (eb, yo, d + 1)] += r * edgeFeature (z (d), zo (d));
      }
    }
    partial_grad[ch] = std::move (g);
    partial_loss[ch] = loss;
  }
  gradient = theta / (sigma * sigma);
  double value = theta.squaredNorm () / (2.0 * sigma * sigma);
  for (std::size_t ch = 0; ch < chunks; ++ch)
  {
    gradient += partial_grad[ch];
    value += partial_loss[ch];
  }
  return value;
}

template <typename Objective> int
minimiseLbfgs (Objective&& f, Eigen::VectorXd& x, int max_iterations, bool& converged,
               double& value)
{
  constexpr std::size_t kMemory = 10;
  std::deque<Eigen::VectorXd> s_hist, y_hist;
  Eigen::VectorXd g;
  value = f (x, g);
  converged = false;
  int it = 0;
  for (; it < max_iterations; ++it)
  {
    if (g.lpNorm<Eigen::Infinity> () < 1e-6 * std::max (1.0, std::abs (value)))
    {
      converged = true;
      break;
    }
    // Two-loop recursion for the quasi-Newton direction.
    Eigen::VectorXd q = g;
    std::vector<double> alpha (s_hist.size ());
    for (std::size_t i = s_hist.size (); i-- > 0;)
    {
      alpha[i] = s_hist[i].dot (q) / y_hist[i].dot (s_hist[i]);
      q -= alpha[i] * y_hist[i];
    }
    if (!s_hist.empty ())
      q *= s_hist.back ().dot (y_hist.back ()) / y_hist.back ().squaredNorm ();
    else
      q /= std::max (1.0, g.norm ());
    for (std::size_t i = 0; i < s_hist.size (); ++i)
    {
      const double beta = y_hist[i].dot (q) / y_hist[i].dot (s_hist[i]);
      q += s_hist[i] * (alpha[i] - beta);
    }
    Eigen::VectorXd dir = -q;
    double slope = g.dot (dir);
    if (slope >= 0.0)  // not a descent direction: restart from steepest descent
    {
      s_hist.clear ();
      y_hist.clear ();
      dir = -g / std::max (1.0, g.norm ());
      slope = g.dot (dir);
    }
    // Backtracking line search (Armijo).
    double step = 1.0;
    Eigen::VectorXd x_new, g_new;
    double v_new = value;
    bool accepted = false;
    for (int ls = 0; ls < 30; ++ls, step *= 0.5)
    {
      x_new = x + step * dir;
      v_new = f (x_new, g_new);
      if (std::isfinite (v_new) && v_new <= value + 1e-4 * step * slope)
      {
        accepted = true;
        break;
      }
    }
    if (!accepted)
    {
      converged = true;  // no further decrease possible at this precision
      break;
    }
    const Eigen::VectorXd s = x_new - x, y = g_new - g;
    const double decrease = value - v_new;
    x = x_new;
    g = g_new;
    value = v_new;
    if (s.dot (y) > 1e-12)
    {
      s_hist.push_back (s);
      y_hist.push_back (y);
      if (s_hist.size () > kMemory)
      {
        s_hist.pop_front ();
        y_hist.pop_front ();
      }
    }
    if (decrease < 1e-9 * std::max (1.0, std::abs (value)))
    {
      converged = true;
      ++it;
      break;
    }
  }
  return it;
}

/** Train: returns iterations; fills theta. */
int
trainWeights (const Graph& graph, const std::vector<double>& node_weights,
              const std::vector<int>& context_labels, std::size_t classes,
              const CrfSettings& settings, Eigen::VectorXd& theta, bool& converged,
              double& value)
{
  auto objective = [&] (const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    return pseudoLikelihood (graph, node_weights, context_labels, x, classes, settings.sigma, g,
                             settings.threads);
  };
  return minimiseLbfgs (objective, theta, settings.max_training_iterations, converged, value);
}
}  // namespace crf
}  // namespace pcl_ext
