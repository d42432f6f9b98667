/*
 * pcl_ext: pseudo-likelihood training of the multi-scale CRF (Lim & Suter 2008, eq. 9).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace pcl_ext {
namespace crf {
namespace {
// Nodes per partial sum: fixed, so that the summation order (and the result, bit for
// bit) does not depend on the thread count.
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
} // namespace

double
pseudoLikelihood (const Graph& graph,
                  const std::vector<double>& node_weights,
                  const Eigen::MatrixXd& context,
                  const Eigen::VectorXd& theta,
                  std::size_t classes,
                  double sigma,
                  Eigen::VectorXd& gradient,
                  unsigned int threads)
{
  const std::size_t C = classes;
  const Eigen::Index D = graph.z.cols();    // edge features
  const Eigen::Index Dn = graph.phi.cols(); // node inputs
  const std::size_t D1 = static_cast<std::size_t> (D) + 1;
  const std::size_t block = C * (static_cast<std::size_t> (Dn) + 1); // a node block
  const std::size_t edge_block = C * D1;
  // node block b, class c, input d (d = 0: bias), column-major C x (Dn + 1)
  auto at = [&] (std::size_t b, std::size_t c, std::size_t d) {
    return b * block + d * C + c;
  };
  const std::size_t N = graph.size();
  const std::size_t E = graph.edge_a.size();
  const bool use_context = context.cols() == static_cast<Eigen::Index> (N) && E > 0;
  const int nthreads = static_cast<int> (resolveThreadCount (threads));
  const Eigen::Index Ci = static_cast<Eigen::Index> (C);

  // Per edge, once: its features g (row 0: the constant 1), the diagonal d of its log
  // potential and dd/du.
  Eigen::MatrixXd features, potential, exp_potential, slope;
  if (use_context) {
    features.resize (static_cast<Eigen::Index> (D1), static_cast<Eigen::Index> (E));
    potential.resize (Ci, static_cast<Eigen::Index> (E));
    exp_potential.resize (Ci, static_cast<Eigen::Index> (E));
    slope.resize (Ci, static_cast<Eigen::Index> (E));
    const Eigen::Map<const Eigen::MatrixXd> local (theta.data() + 2 * block, Ci, D1);
    const Eigen::Map<const Eigen::MatrixXd> regional (
        theta.data() + 2 * block + edge_block, Ci, D1);
#pragma omp parallel for num_threads(nthreads) schedule(static)
    for (std::ptrdiff_t e = 0; e < static_cast<std::ptrdiff_t> (E); ++e) {
      features (0, e) = 1.0;
      for (Eigen::Index d = 0; d < D; ++d)
        features (d + 1, e) =
            edgeFeature (graph.z (graph.edge_a[e], d), graph.z (graph.edge_b[e], d));
      const Eigen::VectorXd u =
          (graph.edge_regional[e] ? regional : local) * features.col (e);
      for (Eigen::Index c = 0; c < Ci; ++c) {
        const double sp = softplus (u (c));
        potential (c, e) = std::min (sp, kMaxLogPotential);
        exp_potential (c, e) = std::exp (potential (c, e));
        slope (c, e) = sp < kMaxLogPotential ? sigmoid (u (c)) : 0.0;
      }
    }
  }
  // d loss / d u for each edge end: column 2e is edge e's term in edge_a's score, 2e +
  // 1 in edge_b's. Each node writes only its own ends, so the node loop needs no locks.
  Eigen::MatrixXd end_gradient =
      Eigen::MatrixXd::Zero (Ci, use_context ? static_cast<Eigen::Index> (2 * E) : 0);

  const std::size_t chunks = (N + kChunk - 1) / kChunk;
  std::vector<Eigen::VectorXd> partial_grad (chunks);
  std::vector<double> partial_loss (chunks, 0.0);
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 1)
  for (std::ptrdiff_t ch = 0; ch < static_cast<std::ptrdiff_t> (chunks); ++ch) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero (static_cast<Eigen::Index> (2 * block));
    double loss = 0.0;
    std::vector<double> score (C), p (C), dmessage;
    for (std::size_t n = ch * kChunk; n < std::min (N, (ch + 1) * kChunk); ++n) {
      const int y = graph.labels[n];
      const double w = node_weights[n];
      if (y < 0 || w <= 0.0)
        continue;
      const std::size_t nb = n < graph.num_supervoxels ? 0 : 1;
      const auto z = graph.phi.row (static_cast<Eigen::Index> (n));
      for (std::size_t c = 0; c < C; ++c) {
        double s = theta[at (nb, c, 0)];
        for (Eigen::Index d = 0; d < Dn; ++d)
          s += theta[at (nb, c, d + 1)] * z (d);
        score[c] = s;
      }
      // Each neighbour o sends the message an undamped first BP sweep sends: with q its
      // class probabilities and d the diagonal of the edge's log potential, log sum_c'
      // q(c') psi(c', c) = log(1 + q(c) (e^d - 1)).
      const std::size_t a0 = graph.adj_offsets[n];
      const std::size_t a1 = use_context ? graph.adj_offsets[n + 1] : a0;
      dmessage.assign ((a1 - a0) * C, 0.0);
      for (std::size_t a = a0; a < a1; ++a) {
        const std::uint32_t e = graph.adj_edge[a];
        const std::uint32_t o = graph.other (e, static_cast<std::uint32_t> (n));
        for (std::size_t c = 0; c < C; ++c) {
          const Eigen::Index ci = static_cast<Eigen::Index> (c);
          const double q = context (ci, o);
          const double grow = q * (exp_potential (ci, e) - 1.0);
          score[c] += std::log1p (grow);
          dmessage[(a - a0) * C + c] =
              q * exp_potential (ci, e) / (1.0 + grow) * slope (ci, e);
        }
      }
      const double lse = logSumExp (score.data(), C);
      loss += w * (lse - score[y]);
      for (std::size_t c = 0; c < C; ++c)
        p[c] = std::exp (score[c] - lse) - (static_cast<int> (c) == y ? 1.0 : 0.0);
      for (std::size_t c = 0; c < C; ++c) {
        const double r = w * p[c];
        g[at (nb, c, 0)] += r;
        for (Eigen::Index d = 0; d < Dn; ++d)
          g[at (nb, c, d + 1)] += r * z (d);
      }
      for (std::size_t a = a0; a < a1; ++a) {
        const std::uint32_t e = graph.adj_edge[a];
        const Eigen::Index col =
            2 * static_cast<Eigen::Index> (e) + (graph.edge_a[e] == n ? 0 : 1);
        for (std::size_t c = 0; c < C; ++c)
          end_gradient (static_cast<Eigen::Index> (c), col) =
              w * p[c] * dmessage[(a - a0) * C + c];
      }
    }
    partial_grad[ch] = std::move (g);
    partial_loss[ch] = loss;
  }
  gradient = theta / (sigma * sigma);
  double value = theta.squaredNorm() / (2.0 * sigma * sigma);
  for (std::size_t ch = 0; ch < chunks; ++ch) {
    gradient.head (static_cast<Eigen::Index> (2 * block)) += partial_grad[ch];
    value += partial_loss[ch];
  }
  if (use_context) {
    // Edge blocks: sum over edges of (both ends' d loss / d u) x g, in fixed edge
    // chunks.
    const std::size_t echunks = (E + kChunk - 1) / kChunk;
    std::vector<Eigen::MatrixXd> local (echunks), regional (echunks);
#pragma omp parallel for num_threads(nthreads) schedule(static)
    for (std::ptrdiff_t ch = 0; ch < static_cast<std::ptrdiff_t> (echunks); ++ch) {
      local[ch] = Eigen::MatrixXd::Zero (Ci, static_cast<Eigen::Index> (D1));
      regional[ch] = Eigen::MatrixXd::Zero (Ci, static_cast<Eigen::Index> (D1));
      for (std::size_t e = ch * kChunk; e < std::min (E, (ch + 1) * kChunk); ++e) {
        const Eigen::Index ei = static_cast<Eigen::Index> (e);
        (graph.edge_regional[e] ? regional[ch] : local[ch]) +=
            (end_gradient.col (2 * ei) + end_gradient.col (2 * ei + 1)) *
            features.col (ei).transpose();
      }
    }
    Eigen::Map<Eigen::MatrixXd> g_local (gradient.data() + 2 * block, Ci, D1);
    Eigen::Map<Eigen::MatrixXd> g_regional (
        gradient.data() + 2 * block + edge_block, Ci, D1);
    for (std::size_t ch = 0; ch < echunks; ++ch) {
      g_local += local[ch];
      g_regional += regional[ch];
    }
  }
  return value;
}

template <typename Objective>
int
minimiseLbfgs (Objective&& f,
               Eigen::VectorXd& x,
               int max_iterations,
               bool& converged,
               double& value)
{
  constexpr std::size_t kMemory = 10;
  std::deque<Eigen::VectorXd> s_hist, y_hist;
  Eigen::VectorXd g;
  value = f (x, g);
  converged = false;
  int it = 0;
  for (; it < max_iterations; ++it) {
    if (g.lpNorm<Eigen::Infinity>() < 1e-6 * std::max (1.0, std::abs (value))) {
      converged = true;
      break;
    }
    // Two-loop recursion for the quasi-Newton direction.
    Eigen::VectorXd q = g;
    std::vector<double> alpha (s_hist.size());
    for (std::size_t i = s_hist.size(); i-- > 0;) {
      alpha[i] = s_hist[i].dot (q) / y_hist[i].dot (s_hist[i]);
      q -= alpha[i] * y_hist[i];
    }
    if (!s_hist.empty())
      q *= s_hist.back().dot (y_hist.back()) / y_hist.back().squaredNorm();
    else
      q /= std::max (1.0, g.norm());
    for (std::size_t i = 0; i < s_hist.size(); ++i) {
      const double beta = y_hist[i].dot (q) / y_hist[i].dot (s_hist[i]);
      q += s_hist[i] * (alpha[i] - beta);
    }
    Eigen::VectorXd dir = -q;
    double slope = g.dot (dir);
    if (slope >= 0.0) // not a descent direction: restart from steepest descent
    {
      s_hist.clear();
      y_hist.clear();
      dir = -g / std::max (1.0, g.norm());
      slope = g.dot (dir);
    }
    // Backtracking line search (Armijo).
    double step = 1.0;
    Eigen::VectorXd x_new, g_new;
    double v_new = value;
    bool accepted = false;
    for (int ls = 0; ls < 30; ++ls, step *= 0.5) {
      x_new = x + step * dir;
      v_new = f (x_new, g_new);
      if (std::isfinite (v_new) && v_new <= value + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      converged = true; // no further decrease possible at this precision
      break;
    }
    const Eigen::VectorXd s = x_new - x, y = g_new - g;
    const double decrease = value - v_new;
    x = x_new;
    g = g_new;
    value = v_new;
    if (s.dot (y) > 1e-12) {
      s_hist.push_back (s);
      y_hist.push_back (y);
      if (s_hist.size() > kMemory) {
        s_hist.pop_front();
        y_hist.pop_front();
      }
    }
    if (decrease < 1e-9 * std::max (1.0, std::abs (value))) {
      converged = true;
      ++it;
      break;
    }
  }
  return it;
}

/** Train: returns iterations; fills theta. */
int
trainWeights (const Graph& graph,
              const std::vector<double>& node_weights,
              const Eigen::MatrixXd& context,
              std::size_t classes,
              const CrfSettings& settings,
              bool edges_only,
              Eigen::VectorXd& theta,
              bool& converged,
              double& value)
{
  if (!edges_only) {
    auto objective = [&] (const Eigen::VectorXd& x, Eigen::VectorXd& g) {
      return pseudoLikelihood (graph,
                               node_weights,
                               context,
                               x,
                               classes,
                               settings.sigma,
                               g,
                               settings.threads);
    };
    return minimiseLbfgs (
        objective, theta, settings.max_training_iterations, converged, value);
  }
  // The node blocks stay as they are: only the edge blocks at the end move.
  const Eigen::Index half =
      2 * static_cast<Eigen::Index> (classes) * (graph.z.cols() + 1);
  Eigen::VectorXd full = theta, edges = theta.tail (half), g_full;
  auto objective = [&] (const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    full.tail (half) = x;
    const double v = pseudoLikelihood (graph,
                                       node_weights,
                                       context,
                                       full,
                                       classes,
                                       settings.sigma,
                                       g_full,
                                       settings.threads);
    g = g_full.tail (half);
    return v;
  };
  const int it = minimiseLbfgs (
      objective, edges, settings.max_training_iterations, converged, value);
  theta.tail (half) = edges;
  return it;
}
} // namespace crf
} // namespace pcl_ext
