/*
 * Tests of the multi-scale CRF's loopy belief propagation (Lim & Suter 2008, eq. 10) on
 * hand-built graphs: exact on a tree, the same messages for any thread count.
 */
#include "crf_internal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {
using pcl_ext::crf::Graph;

/** A graph of \a nodes nodes (the first \a supervoxels are super-voxels) with the
 * given undirected edges, one node input and one edge feature per node drawn from \a
 * seed. */
Graph
makeGraph (std::size_t nodes,
           std::size_t supervoxels,
           const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
           std::uint64_t seed)
{
  Graph g;
  g.num_supervoxels = supervoxels;
  g.node_point.assign (nodes, 0);
  std::mt19937_64 rng (seed);
  std::uniform_real_distribution<float> u (-1.5f, 1.5f);
  Eigen::MatrixXf raw (static_cast<Eigen::Index> (nodes), 1);
  for (Eigen::Index n = 0; n < raw.rows(); ++n)
    raw (n, 0) = u (rng);
  for (const auto& [a, b] : edges) {
    g.edge_a.push_back (a);
    g.edge_b.push_back (b);
    g.edge_regional.push_back (a < supervoxels && b < supervoxels ? 1 : 0);
  }
  pcl_ext::crf::finishGraph (
      raw, Eigen::VectorXd::Zero (1), Eigen::VectorXd::Ones (1), g);
  g.phi = g.z;
  return g;
}

pcl_ext::MultiscaleCrfModel::Weights
makeWeights (Eigen::Index classes, std::uint64_t seed)
{
  std::mt19937_64 rng (seed);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  auto draw = [&] () {
    Eigen::MatrixXd m (classes, 2);
    for (Eigen::Index i = 0; i < m.size(); ++i)
      m (i) = u (rng);
    return m;
  };
  pcl_ext::MultiscaleCrfModel::Weights w;
  w.node_s = draw();
  w.node_x = draw();
  w.local_edge = draw();
  w.regional_edge = draw();
  w.edge_scale = 1.0;
  return w;
}

/** Log node and edge potentials as beliefPropagation builds them. */
double
logPotential (const Graph& g,
              const pcl_ext::MultiscaleCrfModel::Weights& w,
              const std::vector<int>& labels)
{
  double s = 0.0;
  for (std::size_t n = 0; n < g.size(); ++n) {
    const auto& W = n < g.num_supervoxels ? w.node_s : w.node_x;
    s += W (labels[n], 0) + W (labels[n], 1) * g.phi (static_cast<Eigen::Index> (n), 0);
  }
  for (std::size_t e = 0; e < g.edge_a.size(); ++e) {
    const int c = labels[g.edge_a[e]];
    if (c != labels[g.edge_b[e]])
      continue;
    const auto& W = g.edge_regional[e] ? w.regional_edge : w.local_edge;
    const double f =
        pcl_ext::crf::edgeFeature (g.z (g.edge_a[e], 0), g.z (g.edge_b[e], 0));
    s += w.edge_scale * std::min (pcl_ext::crf::softplus (W (c, 0) + W (c, 1) * f),
                                  pcl_ext::crf::kMaxLogPotential);
  }
  return s;
}
} // namespace

TEST (CrfInference, ExactOnATree)
{
  // A chain of three super-voxels, leaves (local points) on each, one leaf on a leaf's
  // super-voxel only: BP on a tree gives the exact marginals, which enumeration of
  // the 3^7 labellings checks, local points' shortcut included.
  const Graph g = makeGraph (7, 3, {{0, 1}, {1, 2}, {0, 3}, {1, 4}, {1, 5}, {2, 6}}, 7);
  const auto w = makeWeights (3, 11);
  pcl_ext::CrfSettings settings;
  settings.bp_iterations = 500;
  settings.bp_tolerance = 1e-12;
  settings.threads = 1;
  Eigen::MatrixXf marginals;
  int iterations = 0;
  bool converged = false;
  pcl_ext::crf::beliefPropagation (g, w, settings, marginals, iterations, converged);
  ASSERT_TRUE (converged);
  ASSERT_EQ (marginals.rows(), 3);
  ASSERT_EQ (marginals.cols(), 3);
  Eigen::MatrixXd exact = Eigen::MatrixXd::Zero (3, 3);
  std::vector<int> labels (7, 0);
  double z = 0.0;
  for (int code = 0; code < 2187; ++code) {
    for (int n = 0, c = code; n < 7; ++n, c /= 3)
      labels[n] = c % 3;
    const double p = std::exp (logPotential (g, w, labels));
    z += p;
    for (int n = 0; n < 3; ++n)
      exact (n, labels[n]) += p;
  }
  exact /= z;
  double spread = 0.0;
  for (Eigen::Index n = 0; n < 3; ++n)
    for (Eigen::Index c = 0; c < 3; ++c) {
      EXPECT_NEAR (marginals (n, c), exact (n, c), 1e-5)
          << "node " << n << " class " << c;
      spread = std::max (spread, std::abs (exact (n, c) - 1.0 / 3.0));
    }
  EXPECT_GT (spread, 0.1)
      << "the potentials should make the marginals far from uniform";
}

TEST (CrfInference, SameMessagesForAnyThreadCount)
{
  // Enough edges (5 classes) for the sweeps to run on several threads: the marginals,
  // the sweeps and the last messages are the same for one and two threads.
  const std::size_t S = 40000, L = 80000;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::mt19937_64 rng (3);
  for (std::uint32_t v = 0; v < S; ++v)
    for (int k = 0; k < 2; ++k) {
      const auto o = static_cast<std::uint32_t> (rng() % S);
      if (o != v)
        edges.emplace_back (v, o);
    }
  for (std::uint32_t j = 0; j < L; ++j)
    edges.emplace_back (static_cast<std::uint32_t> (j % S),
                        static_cast<std::uint32_t> (S + j));
  ASSERT_GE (2 * edges.size() * 5, std::size_t{1} << 20);
  const Graph g = makeGraph (S + L, S, edges, 5);
  const auto w = makeWeights (5, 9);
  pcl_ext::CrfSettings settings;
  Eigen::MatrixXf m1, m2;
  Eigen::MatrixXd msg1, msg2;
  int it1 = 0, it2 = 0;
  bool c1 = false, c2 = false;
  settings.threads = 1;
  pcl_ext::crf::beliefPropagation (g, w, settings, m1, it1, c1, &msg1);
  settings.threads = 2;
  pcl_ext::crf::beliefPropagation (g, w, settings, m2, it2, c2, &msg2);
  EXPECT_GT (it1, 1);
  EXPECT_EQ (it1, it2);
  EXPECT_EQ (c1, c2);
  ASSERT_EQ (m1.rows(), static_cast<Eigen::Index> (S));
  EXPECT_TRUE (m1 == m2);
  EXPECT_TRUE (msg1 == msg2);
}
