/*
 * pcl_ext: loopy belief propagation over the multi-scale CRF (Lim & Suter 2008, eq.
 * 10).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace crf {
namespace {
/** Message entries (messages times classes) from which a BP sweep runs on several
 * threads: about 30 ms of work on one. */
constexpr std::size_t kParallelSweepEntries = std::size_t{1} << 20;

void
normaliseLog (double* v, std::size_t n)
{
  const double m = *std::max_element (v, v + n);
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    s += std::exp (v[i] - m);
  const double lse = m + std::log (s);
  for (std::size_t i = 0; i < n; ++i)
    v[i] -= lse;
}

/** The log message of a sender whose cavity (its belief without the receiver's
 * message, log, shifted or not) is \a h, over an edge whose diagonal potential is \a
 * exp_diag: normalised, into \a out. \a h is overwritten. */
void
edgeMessage (std::vector<double>& h, const double* exp_diag, std::vector<double>& out)
{
  const std::size_t C = h.size();
  double mx = -std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < C; ++c)
    mx = std::max (mx, h[c]);
  double sum = 0.0;
  for (std::size_t c = 0; c < C; ++c) {
    h[c] = std::exp (h[c] - mx);
    sum += h[c];
  }
  // The potential is diagonal: sum over c_a of exp(h + [c_a = c_b] d) is the plain sum
  // with the c_b term scaled by exp(d), O(C) per message instead of O(C^2). Normalised
  // in the linear domain (the terms are >= 1 after the shift by mx): one log each.
  double total = 0.0;
  for (std::size_t cb = 0; cb < C; ++cb) {
    out[cb] = sum + h[cb] * (exp_diag[cb] - 1.0);
    total += out[cb];
  }
  const double log_total = std::log (total);
  for (std::size_t cb = 0; cb < C; ++cb)
    out[cb] = std::log (out[cb]) - log_total;
}
} // namespace

void
beliefPropagation (const Graph& graph,
                   const MultiscaleCrfModel::Weights& w,
                   const CrfSettings& settings,
                   Eigen::MatrixXf& marginals,
                   int& iterations,
                   bool& converged,
                   Eigen::MatrixXd* messages)
{
  const std::size_t C = static_cast<std::size_t> (w.node_s.rows());
  const std::size_t N = graph.size();
  const std::size_t E = graph.edge_a.size();
  const Eigen::Index D = graph.z.cols();
  const int threads = static_cast<int> (resolveThreadCount (settings.threads));
  // Log node potentials (eq. 8) and the diagonal of each log edge potential (eq. 6-7).
  Eigen::MatrixXd unary (C, N), diag (C, E);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t n = 0; n < static_cast<std::ptrdiff_t> (N); ++n) {
    const Eigen::MatrixXd& W =
        static_cast<std::size_t> (n) < graph.num_supervoxels ? w.node_s : w.node_x;
    const Eigen::VectorXd x = graph.phi.row (n).transpose().cast<double>();
    unary.col (n) = W.col (0) + W.rightCols (graph.phi.cols()) * x;
  }
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t e = 0; e < static_cast<std::ptrdiff_t> (E); ++e) {
    const Eigen::MatrixXd& W = graph.edge_regional[e] ? w.regional_edge : w.local_edge;
    Eigen::VectorXd g (D);
    for (Eigen::Index d = 0; d < D; ++d)
      g (d) = edgeFeature (graph.z (graph.edge_a[e], d), graph.z (graph.edge_b[e], d));
    const Eigen::VectorXd u = W.col (0) + W.rightCols (D) * g;
    for (Eigen::Index c = 0; c < u.size(); ++c)
      diag (c, e) = w.edge_scale * std::min (softplus (u (c)), kMaxLogPotential);
  }
  const Eigen::MatrixXd exp_diag = diag.array().exp().matrix();
  // Messages in log space: column 2e goes a -> b, 2e + 1 goes b -> a.
  Eigen::MatrixXd msg = Eigen::MatrixXd::Zero (C, 2 * E), next (C, 2 * E);
  if (messages && messages->rows() == msg.rows() && messages->cols() == msg.cols())
    msg = *messages;
  const double damping = settings.bp_damping;
  // A node with one edge (every local point) hears only the receiver of its message,
  // so its cavity is its own node potential and its message, before damping, is the
  // same in every sweep: computed once.
  Eigen::MatrixXd leaf_out (C, N);
#pragma omp parallel num_threads(threads)
  {
    std::vector<double> h (C), out (C);
#pragma omp for schedule(static)
    for (std::ptrdiff_t n = 0; n < static_cast<std::ptrdiff_t> (N); ++n) {
      if (graph.adj_offsets[n + 1] - graph.adj_offsets[n] != 1)
        continue;
      for (std::size_t c = 0; c < C; ++c)
        h[c] = unary (c, n);
      edgeMessage (h, &exp_diag (0, graph.adj_edge[graph.adj_offsets[n]]), out);
      for (std::size_t c = 0; c < C; ++c)
        leaf_out (c, n) = out[c];
    }
  }
  // A sweep is parallel only when it holds enough work: each costs a synchronisation
  // of the threads, and on a shared machine a thread that has to wait for the
  // scheduler costs more than a small sweep (some 60,000 messages on a 100,000-point
  // scan, a few milliseconds) gains. The messages do not depend on it.
  const int sweep_threads = 2 * E * C >= kParallelSweepEntries ? threads : 1;
  converged = E == 0;
  iterations = 0;
  for (int it = 0; it < settings.bp_iterations && !converged; ++it) {
    // Synchronous sweep: every new message is computed from the previous sweep's
    // messages. One parallel loop over the senders: each node sums what it heard and
    // sends all its messages, so that a sweep has one synchronisation point (two, a
    // loop summing and a loop over the messages, cost twice the waiting on a loaded
    // machine for the same arithmetic).
    double change = 0.0;
#pragma omp parallel num_threads(sweep_threads)
    {
      std::vector<double> h (C), out (C);
      Eigen::VectorXd incoming (C);
#pragma omp for schedule(dynamic, 256) reduction(max : change)
      for (std::ptrdiff_t n = 0; n < static_cast<std::ptrdiff_t> (N); ++n) {
        const auto from = static_cast<std::uint32_t> (n);
        const std::size_t first = graph.adj_offsets[n], last = graph.adj_offsets[n + 1];
        const bool leaf = last - first == 1;
        if (!leaf) {
          incoming.setZero();
          for (std::size_t a = first; a < last; ++a) {
            const std::uint32_t e = graph.adj_edge[a];
            incoming += msg.col (2 * e + (graph.edge_a[e] == from ? 1 : 0));
          }
        }
        for (std::size_t a = first; a < last; ++a) {
          const std::uint32_t e = graph.adj_edge[a];
          const std::size_t m = 2 * e + (graph.edge_a[e] == from ? 0 : 1);
          if (leaf)
            for (std::size_t c = 0; c < C; ++c)
              out[c] = leaf_out (c, n);
          else {
            // Cavity: the sender's belief without what the receiver told it.
            for (std::size_t c = 0; c < C; ++c)
              h[c] = unary (c, n) + incoming (c) - msg (c, m ^ 1);
            edgeMessage (h, &exp_diag (0, e), out);
          }
          for (std::size_t c = 0; c < C; ++c) {
            const double v = (1.0 - damping) * out[c] + damping * msg (c, m);
            next (c, m) = v;
            change = std::max (change, std::abs (v - msg (c, m)));
          }
        }
      }
    }
    msg.swap (next);
    iterations = it + 1;
    converged = change < settings.bp_tolerance;
  }
  if (messages)
    *messages = msg;
  marginals.resize (static_cast<Eigen::Index> (graph.num_supervoxels),
                    static_cast<Eigen::Index> (C));
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t n = 0; n < static_cast<std::ptrdiff_t> (graph.num_supervoxels);
       ++n) {
    std::vector<double> b (C);
    for (std::size_t c = 0; c < C; ++c)
      b[c] = unary (c, n);
    for (std::size_t a = graph.adj_offsets[n]; a < graph.adj_offsets[n + 1]; ++a) {
      const std::uint32_t e = graph.adj_edge[a];
      const auto col =
          msg.col (2 * e + (graph.edge_a[e] == static_cast<std::uint32_t> (n) ? 1 : 0));
      for (std::size_t c = 0; c < C; ++c)
        b[c] += col[c];
    }
    normaliseLog (b.data(), C);
    for (std::size_t c = 0; c < C; ++c)
      marginals (n, c) = static_cast<float> (std::exp (b[c]));
  }
}

double
fitEdgeScale (const Graph& graph,
              const MultiscaleCrfModel::Weights& w,
              const std::vector<double>& node_weights,
              const CrfSettings& settings)
{
  constexpr double kStep = 0.1, kMax = 1.5;
  double best_scale = 1.0, best_loss = std::numeric_limits<double>::infinity();
  int worse = 0;
  // Each scale's BP starts from the messages of the scale before: its fixed point is
  // near, and the search then costs a few sweeps per scale instead of a full BP.
  Eigen::MatrixXd messages;
  for (int k = 1; k * kStep <= kMax + 1e-9; ++k) {
    MultiscaleCrfModel::Weights scaled = w;
    scaled.edge_scale = k * kStep;
    Eigen::MatrixXf marginals;
    int iterations = 0;
    bool converged = false;
    beliefPropagation (
        graph, scaled, settings, marginals, iterations, converged, &messages);
    double loss = 0.0;
    for (std::size_t n = 0; n < graph.num_supervoxels; ++n)
      if (graph.labels[n] >= 0 && node_weights[n] > 0.0)
        loss -=
            node_weights[n] *
            std::log (std::max (1e-30,
                                static_cast<double> (marginals (
                                    static_cast<Eigen::Index> (n), graph.labels[n]))));
    if (loss < best_loss) {
      best_loss = loss;
      best_scale = scaled.edge_scale;
      worse = 0;
    }
    else if (++worse ==
             2) // rising twice in a row: past the minimum (larger scales cost
      break;    // the most sweeps)
  }
  return best_scale;
}
} // namespace crf
} // namespace pcl_ext
