/*
 * pcl_ext: the multi-scale CRF graph of one cloud (Lim & Suter 2008, section 3.2,
 * figure 3).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/common/random.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>

namespace pcl_ext {
namespace crf {
namespace {
/** m members of \a sv other than its mid-point, drawn with a stream seeded by the
 * mid-point's position, so that the choice depends neither on the order super-voxels
 * are processed in nor on the rest of the cloud (a tile draws the whole cloud's). */
void
pickLocalPoints (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                 const Supervoxel& sv,
                 std::uint64_t seed,
                 int m,
                 std::vector<pcl::index_t>& out)
{
  out.clear();
  std::vector<pcl::index_t> pool;
  for (const auto i : sv.members)
    if (i != sv.seed)
      pool.push_back (i);
  const auto& mid = cloud[static_cast<std::size_t> (sv.seed)];
  RandomStream rng (hashPosition (mid.x, mid.y, mid.z, seed));
  const std::size_t take = std::min (pool.size(), static_cast<std::size_t> (m));
  for (std::size_t j = 0; j < take; ++j) {
    std::swap (pool[j], pool[j + rng.index (pool.size() - j)]);
    out.push_back (pool[j]);
  }
}

/** The columns of saliencyFeatureNames(features) averaged over a super-voxel's
 * neighbourhood: the shape, angle, height and dimension features, not the radius,
 * colour, intensity, density or extents. */
std::vector<std::size_t>
neighbourMeanColumns (const SaliencyFeatureOptions& features)
{
  static const char* const kAveraged[] = {"clutterness",
                                          "surfaceness",
                                          "curveness",
                                          "normal_angle",
                                          "tangent_angle",
                                          "height",
                                          "linearity",
                                          "planarity",
                                          "scattering",
                                          "dimension"};
  const std::vector<std::string> names = saliencyFeatureNames (features);
  std::vector<std::size_t> columns;
  for (std::size_t d = 0; d < names.size(); ++d) {
    const std::string base = names[d].substr (0, names[d].find ('@'));
    for (const char* a : kAveraged)
      if (base == a)
        columns.push_back (d);
  }
  return columns;
}

/** Appends to \a raw the means of neighbourMeanColumns over each super-voxel and its
 * regional neighbours (the rows of the S super-voxel nodes); the local point node S + j
 * takes those of its super-voxel \a owner[j]. */
void
appendNeighbourMeans (const SupervoxelSet& supervoxels,
                      const std::vector<std::uint32_t>& owner,
                      const CrfSettings& settings,
                      Eigen::MatrixXf& raw)
{
  const std::size_t S = supervoxels.size();
  const std::vector<std::size_t> columns = neighbourMeanColumns (settings.features);
  const Eigen::Index D = raw.cols(), M = static_cast<Eigen::Index> (columns.size());
  Eigen::MatrixXf out (raw.rows(), D + M);
  out.leftCols (D) = raw;
  for (std::size_t v = 0; v < S; ++v) {
    const auto& adj = supervoxels.adjacency[v];
    for (Eigen::Index k = 0; k < M; ++k) {
      const Eigen::Index d = static_cast<Eigen::Index> (columns[k]);
      double sum = raw (static_cast<Eigen::Index> (v), d);
      for (const auto o : adj)
        sum += raw (static_cast<Eigen::Index> (o), d);
      out (static_cast<Eigen::Index> (v), D + k) =
          static_cast<float> (sum / static_cast<double> (adj.size() + 1));
    }
  }
  for (std::size_t j = 0; j < owner.size(); ++j)
    out.row (static_cast<Eigen::Index> (S + j)).tail (M) =
        out.row (static_cast<Eigen::Index> (owner[j])).tail (M);
  raw = std::move (out);
}
} // namespace

std::vector<std::string>
crfFeatureNames (const SaliencyFeatureOptions& features)
{
  std::vector<std::string> names = saliencyFeatureNames (features);
  if (features.scales.empty())
    return names;
  const std::vector<std::size_t> columns = neighbourMeanColumns (features);
  for (const std::size_t d : columns)
    names.push_back ("neighbours_" + names[d]);
  return names;
}

bool
buildGraph (const CrfInput& input,
            const CrfSettings& settings,
            SupervoxelSet& supervoxels,
            Eigen::MatrixXf& raw,
            Graph& graph,
            CrfStatistics& statistics)
{
  graph = Graph();
  auto t0 = std::chrono::steady_clock::now();
  AdaptiveRadiusEstimator estimator;
  SupervoxelParameters sv_parameters = settings.supervoxels;
  sv_parameters.threads = settings.threads;
  if (!computeAdaptiveSupervoxels (
          input.xyz,
          settings.features.colour ? input.colours : std::vector<Eigen::Vector3f>(),
          sv_parameters,
          supervoxels,
          &estimator))
    return false;
  const std::size_t S = supervoxels.size();
  const bool local = settings.mode != CrfMode::NodeOnly;
  // Local points and their own radii (section 3.1, last paragraph).
  std::vector<std::vector<pcl::index_t>> picked (S);
  if (local)
    for (std::size_t v = 0; v < S; ++v)
      pickLocalPoints (*input.xyz,
                       supervoxels.supervoxels[v],
                       settings.supervoxels.seed,
                       settings.local_edges,
                       picked[v]);
  graph.num_supervoxels = S;
  std::vector<float> radii;
  for (std::size_t v = 0; v < S; ++v) {
    graph.node_point.push_back (supervoxels.supervoxels[v].seed);
    radii.push_back (supervoxels.supervoxels[v].radius);
  }
  std::vector<std::uint32_t> owner; // the super-voxel of each local point node
  for (std::size_t v = 0; v < S; ++v)
    for (const auto i : picked[v]) {
      owner.push_back (static_cast<std::uint32_t> (v));
      graph.edge_a.push_back (static_cast<std::uint32_t> (v));
      graph.edge_b.push_back (static_cast<std::uint32_t> (graph.node_point.size()));
      graph.edge_regional.push_back (0);
      graph.node_point.push_back (i);
      radii.push_back (0.f);
    }
  const int threads = static_cast<int> (resolveThreadCount (settings.threads));
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16)
  for (std::ptrdiff_t n = static_cast<std::ptrdiff_t> (S);
       n < static_cast<std::ptrdiff_t> (graph.node_point.size());
       ++n)
    radii[n] = estimator.estimate (graph.node_point[n]);
  statistics.supervoxels_ms = msSince (t0);

  t0 = std::chrono::steady_clock::now();
  LocalGround ground;
  ground.build (*input.xyz,
                settings.features.up,
                settings.features.ground_cell,
                settings.features.ground_reach,
                settings.features.ground_estimate);
  if (!computeSaliencyFeatures (*input.xyz,
                                estimator.tree(),
                                input.colours,
                                input.intensity,
                                ground,
                                graph.node_point,
                                radii,
                                settings.features,
                                raw,
                                settings.threads))
    return false;
  if (!settings.features.scales.empty())
    appendNeighbourMeans (supervoxels, owner, settings, raw);
  if (settings.mode == CrfMode::MultiscaleCrf)
    for (std::size_t v = 0; v < S; ++v)
      for (const auto k : supervoxels.adjacency[v]) {
        // Regional edges are undirected: keep one of each pair that names the other.
        const auto& back = supervoxels.adjacency[k];
        if (k < v && std::find (back.begin(), back.end(), v) != back.end())
          continue;
        graph.edge_a.push_back (static_cast<std::uint32_t> (v));
        graph.edge_b.push_back (k);
        graph.edge_regional.push_back (1);
      }
  statistics.features_ms = msSince (t0);
  statistics.supervoxels = S;
  statistics.local_points = graph.node_point.size() - S;
  statistics.regional_edges = static_cast<std::size_t> (
      std::count (graph.edge_regional.begin(), graph.edge_regional.end(), 1));
  statistics.local_edges = graph.edge_regional.size() - statistics.regional_edges;
  graph.labels.assign (graph.node_point.size(), -1);
  return true;
}

void
finishGraph (const Eigen::MatrixXf& raw,
             const Eigen::VectorXd& mean,
             const Eigen::VectorXd& scale,
             Graph& graph)
{
  graph.z.resize (raw.rows(), raw.cols());
  for (Eigen::Index n = 0; n < raw.rows(); ++n)
    for (Eigen::Index d = 0; d < raw.cols(); ++d) {
      const double z = (raw (n, d) - mean (d)) / scale (d);
      graph.z (n, d) = std::isfinite (z)
                           ? static_cast<float> (std::max (-5.0, std::min (5.0, z)))
                           : 0.f;
    }
  const std::size_t N = graph.size();
  std::vector<std::size_t> counts (N + 1, 0);
  for (std::size_t e = 0; e < graph.edge_a.size(); ++e) {
    ++counts[graph.edge_a[e] + 1];
    ++counts[graph.edge_b[e] + 1];
  }
  for (std::size_t n = 0; n < N; ++n)
    counts[n + 1] += counts[n];
  graph.adj_offsets = counts;
  graph.adj_edge.resize (counts.back());
  std::vector<std::size_t> fill (counts.begin(), counts.end() - 1);
  for (std::size_t e = 0; e < graph.edge_a.size(); ++e) {
    graph.adj_edge[fill[graph.edge_a[e]]++] = static_cast<std::uint32_t> (e);
    graph.adj_edge[fill[graph.edge_b[e]]++] = static_cast<std::uint32_t> (e);
  }
}

std::vector<std::vector<double>>
fitKnots (const Eigen::MatrixXf& z, CrfNodeExpansion expansion, int knots)
{
  std::vector<std::vector<double>> out (static_cast<std::size_t> (z.cols()));
  if (expansion == CrfNodeExpansion::Linear || z.rows() == 0)
    return out;
  std::vector<float> v (static_cast<std::size_t> (z.rows()));
  for (Eigen::Index d = 0; d < z.cols(); ++d) {
    for (Eigen::Index n = 0; n < z.rows(); ++n)
      v[static_cast<std::size_t> (n)] = z (n, d);
    std::sort (v.begin(), v.end());
    auto& t = out[static_cast<std::size_t> (d)];
    for (int k = 1; k <= knots; ++k) {
      const double q = static_cast<double> (k) / (knots + 1);
      const double x = v[static_cast<std::size_t> (q * (v.size() - 1) + 0.5)];
      // Knots at a (clamped) extreme, or repeated where a feature takes few values,
      // would add inputs that are zero or copies of another.
      if (x > v.front() && x < v.back() && (t.empty() || x > t.back() + 1e-6))
        t.push_back (x);
    }
  }
  return out;
}

std::size_t
expandedSize (std::size_t dims,
              CrfNodeExpansion expansion,
              const std::vector<std::vector<double>>& knots)
{
  std::size_t n = dims;
  if (expansion != CrfNodeExpansion::Linear)
    for (const auto& t : knots)
      n += t.size();
  if (expansion == CrfNodeExpansion::SplineProducts)
    n += dims * (dims - 1) / 2;
  return n;
}

void
expandFeatures (CrfNodeExpansion expansion,
                const std::vector<std::vector<double>>& knots,
                Graph& graph)
{
  const Eigen::Index D = graph.z.cols();
  const Eigen::Index Dn = static_cast<Eigen::Index> (
      expandedSize (static_cast<std::size_t> (D), expansion, knots));
  graph.phi.resize (graph.z.rows(), Dn);
  for (Eigen::Index n = 0; n < graph.z.rows(); ++n) {
    const auto z = graph.z.row (n);
    auto out = graph.phi.row (n);
    out.head (D) = z;
    Eigen::Index col = D;
    if (expansion != CrfNodeExpansion::Linear)
      for (Eigen::Index d = 0; d < D; ++d)
        for (const double t : knots[static_cast<std::size_t> (d)])
          out (col++) = std::max (0.f, z (d) - static_cast<float> (t));
    if (expansion == CrfNodeExpansion::SplineProducts)
      for (Eigen::Index a = 0; a < D; ++a)
        for (Eigen::Index b = a + 1; b < D; ++b)
          out (col++) = z (a) * z (b);
  }
}

Eigen::VectorXd
packWeights (const MultiscaleCrfModel::Weights& w)
{
  const Eigen::Index nb = w.node_s.size(), eb = w.local_edge.size();
  Eigen::VectorXd theta (2 * nb + 2 * eb);
  theta.segment (0, nb) = Eigen::Map<const Eigen::VectorXd> (w.node_s.data(), nb);
  theta.segment (nb, nb) = Eigen::Map<const Eigen::VectorXd> (w.node_x.data(), nb);
  theta.segment (2 * nb, eb) =
      Eigen::Map<const Eigen::VectorXd> (w.local_edge.data(), eb);
  theta.segment (2 * nb + eb, eb) =
      Eigen::Map<const Eigen::VectorXd> (w.regional_edge.data(), eb);
  return theta;
}

void
unpackWeights (const Eigen::VectorXd& theta,
               std::size_t classes,
               std::size_t node_dims,
               std::size_t edge_dims,
               MultiscaleCrfModel::Weights& w)
{
  const Eigen::Index C = static_cast<Eigen::Index> (classes);
  const Eigen::Index N1 = static_cast<Eigen::Index> (node_dims) + 1;
  const Eigen::Index E1 = static_cast<Eigen::Index> (edge_dims) + 1;
  const Eigen::Index nb = C * N1, eb = C * E1;
  w.node_s = Eigen::Map<const Eigen::MatrixXd> (theta.data(), C, N1);
  w.node_x = Eigen::Map<const Eigen::MatrixXd> (theta.data() + nb, C, N1);
  w.local_edge = Eigen::Map<const Eigen::MatrixXd> (theta.data() + 2 * nb, C, E1);
  w.regional_edge =
      Eigen::Map<const Eigen::MatrixXd> (theta.data() + 2 * nb + eb, C, E1);
}
} // namespace crf
} // namespace pcl_ext
