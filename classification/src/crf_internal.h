/*
 * pcl_ext: internals of MultiscaleCrfModel shared by its source files.
 */
#pragma once

#include <pcl_ext/classification/crf_model.h>

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
/** Standardisation, the node expansion and the four weight blocks (column 0: the bias):
 * the node blocks C x (Dn + 1) over the expanded features, the edge blocks C x (D + 1).
 */
struct MultiscaleCrfModel::Weights {
  std::vector<std::string> feature_names;
  Eigen::VectorXd mean, scale; // z = clamp((f - mean) / scale, -kClamp, kClamp)
  CrfNodeExpansion expansion = CrfNodeExpansion::Linear;
  std::vector<std::vector<double>>
      knots; // per feature, ascending (spline expansions only)
  Eigen::MatrixXd node_s, node_x, local_edge, regional_edge;
  CrfNodeModel node_model = CrfNodeModel::Logistic;
  /** BoostedTrees: the boosters (XGBoost models, UBJ bytes) of the super-voxel and
   * the local-point nodes, whose log class probabilities are graph.phi; node_s and
   * node_x are then the identity (C x (C + 1), bias 0). */
  struct Boosters {
    std::vector<char> supervoxel, point;
  } boosters;
  double edge_scale =
      1.0; // beta: the log edge potentials are multiplied by it (stage 3)
};

namespace crf {
constexpr float kClamp = 5.f;
/** Edge features z_i z_j are clamped to [-kEdgeClamp, kEdgeClamp]. */
constexpr double kEdgeClamp = 3.0;
/** The diagonal of a log edge potential is capped here, in training and inference
 * alike. */
constexpr double kMaxLogPotential = 50.0;

/** Edge potentials are kept associative: log psi(c, c) = softplus(lambda^c . g) >= 0,
 * so that an edge can only favour agreement (unbounded linear potentials turned
 * repulsive on unseen feature combinations and made loopy BP oscillate). */
inline double
softplus (double u)
{
  return u > 30.0 ? u : std::log1p (std::exp (u));
}

inline double
sigmoid (double u)
{
  return 1.0 / (1.0 + std::exp (-u));
}

inline double
edgeFeature (float a, float b)
{
  const double g = static_cast<double> (a) * b;
  return g < -kEdgeClamp ? -kEdgeClamp : (g > kEdgeClamp ? kEdgeClamp : g);
}

/** The graph: super-voxel nodes 0 .. S-1, then local point nodes; undirected edges. */
struct Graph {
  std::size_t num_supervoxels = 0;
  Eigen::MatrixXf z;   // one standardised feature row per node (edges)
  Eigen::MatrixXf phi; // its expansion (CrfNodeExpansion), the node inputs
  std::vector<pcl::index_t> node_point; // the point each node describes
  std::vector<std::uint32_t> edge_a, edge_b;
  std::vector<char> edge_regional; // 1: regional (eq. 7), 0: local (eq. 6)
  std::vector<int> labels;         // class index per node, -1 unknown
  // adjacency in CSR: for node n, entries [adj_offsets[n], adj_offsets[n+1]) of
  // adj_edge
  std::vector<std::size_t> adj_offsets;
  std::vector<std::uint32_t> adj_edge;

  std::size_t
  size () const
  {
    return node_point.size();
  }

  std::uint32_t
  other (std::uint32_t e, std::uint32_t n) const
  {
    return edge_a[e] == n ? edge_b[e] : edge_a[e];
  }
};

/** The names of the CRF's feature columns: saliencyFeatureNames(features), and with
 * the multi-scale features, the means of the shape, angle, height and dimension
 * features over each super-voxel and its regional neighbours ("neighbours_" and the
 * name; after CGAL's Cluster_mean_of_feature). */
std::vector<std::string>
crfFeatureNames (const SaliencyFeatureOptions& features);

/** Super-voxels, local points, raw features (crfFeatureNames) and edges of one cloud
 * (mode decides which). */
bool
buildGraph (const CrfInput& input,
            const CrfSettings& settings,
            SupervoxelSet& supervoxels,
            Eigen::MatrixXf& raw_features,
            Graph& graph,
            CrfStatistics& statistics);

/** Standardise raw features into graph.z and build the adjacency. */
void
finishGraph (const Eigen::MatrixXf& raw,
             const Eigen::VectorXd& mean,
             const Eigen::VectorXd& scale,
             Graph& graph);

/** The knots of the spline expansions: per feature (column of \a z), the K quantiles
 * k / (K + 1) of its values, without repeats and without the column's extremes (a hinge
 * there is zero or linear everywhere). Empty lists for the linear expansion. */
std::vector<std::vector<double>>
fitKnots (const Eigen::MatrixXf& z, CrfNodeExpansion expansion, int knots);

/** Number of node inputs of an expansion of \a dims features with \a knots. */
std::size_t
expandedSize (std::size_t dims,
              CrfNodeExpansion expansion,
              const std::vector<std::vector<double>>& knots);

/** graph.phi from graph.z (see CrfNodeExpansion). */
void
expandFeatures (CrfNodeExpansion expansion,
                const std::vector<std::vector<double>>& knots,
                Graph& graph);

/** Parameter vector layout: [node_s, node_x] each C x (Dn + 1), then [local_edge,
 * regional_edge] each C x (D + 1). */
Eigen::VectorXd
packWeights (const MultiscaleCrfModel::Weights& w);

void
unpackWeights (const Eigen::VectorXd& theta,
               std::size_t classes,
               std::size_t node_dims,
               std::size_t edge_dims,
               MultiscaleCrfModel::Weights& w);

/** Penalised negative pseudo-log-likelihood and its gradient (see crf_model.h); each
 * node hears from each neighbour o the message BP's first sweep would send given o's
 * class probabilities \a context.col(o) (C x N; with no columns, neighbours are
 * ignored). */
double
pseudoLikelihood (const Graph& graph,
                  const std::vector<double>& node_weights,
                  const Eigen::MatrixXd& context,
                  const Eigen::VectorXd& theta,
                  std::size_t classes,
                  double sigma,
                  Eigen::VectorXd& gradient,
                  unsigned int threads);

/** Minimise the penalised negative pseudo-log-likelihood by L-BFGS from \a theta;
 * returns the iterations done. With \a edges_only, the node blocks are held where they
 * are. */
int
trainWeights (const Graph& graph,
              const std::vector<double>& node_weights,
              const Eigen::MatrixXd& context,
              std::size_t classes,
              const CrfSettings& settings,
              bool edges_only,
              Eigen::VectorXd& theta,
              bool& converged,
              double& value);

using Boosters = MultiscaleCrfModel::Weights::Boosters;

/** Trains an XGBoost softmax classifier of \a classes classes on rows \a rows of \a
 * x with labels and weights per row of x (see CrfSettings for the parameters; the
 * histogram method on one thread, so the model does not depend on the thread count)
 * into \a model (UBJ bytes). */
bool
trainBooster (const Eigen::MatrixXf& x,
              const std::vector<int>& labels,
              const std::vector<double>& weights,
              const std::vector<std::size_t>& rows,
              std::size_t classes,
              const CrfSettings& settings,
              std::vector<char>& model,
              std::string& error);

/** Log class probabilities (rows of \a x by classes) of a booster. */
bool
boosterLogProbabilities (const std::vector<char>& model,
                         const Eigen::MatrixXf& x,
                         std::size_t classes,
                         unsigned int threads,
                         Eigen::MatrixXf& log_probabilities,
                         std::string& error);

/** Checks that \a model is a booster over \a features features and \a classes
 * classes. */
bool
checkBooster (const std::vector<char>& model,
              std::size_t classes,
              std::size_t features,
              std::string& error);

std::string
encodeBase64 (const std::vector<char>& bytes);

/** Decodes canonical base64 (what encodeBase64 writes); false for anything else. */
bool
decodeBase64 (const std::string& text, std::vector<char>& bytes);

/** Stage 1 with boosted trees: one booster for the super-voxel nodes and one for the
 * local points (when the graph has any), each on its labelled nodes of positive
 * weight; graph.phi becomes their log class probabilities. With several training
 * clouds and edges to fit, graph.phi of each cloud's nodes comes from boosters trained
 * on the other clouds (cross-fitting; the clouds in at most 3 folds, cloud k in fold k
 * mod 3), so that the edges (stage 2) and the edge scale (stage 3) are fitted against
 * node potentials as confident as on unseen data, not as on the data the trees were
 * fitted to. NodeOnly: graph.phi from the boosters kept (no cross-fitting). */
bool
trainBoostedNodes (Graph& graph,
                   const std::vector<double>& node_weights,
                   const std::vector<int>& node_cloud,
                   std::size_t classes,
                   const CrfSettings& settings,
                   Boosters& boosters,
                   std::string& error);

/** graph.phi from graph.z by the boosters (inference). */
bool
boostedNodeInputs (const Boosters& boosters,
                   std::size_t classes,
                   unsigned int threads,
                   Graph& graph,
                   std::string& error);

/** The node blocks of \a theta (see packWeights) as the identity on C inputs. */
void
setIdentityNodeWeights (std::size_t classes, Eigen::VectorXd& theta);

/** Loopy BP marginals of the super-voxel nodes (rows) over classes. \a messages, when
 * given and of the graph's size (C x 2E, log messages), are the starting messages (else
 * all zero), and receive the last ones. */
void
beliefPropagation (const Graph& graph,
                   const MultiscaleCrfModel::Weights& w,
                   const CrfSettings& settings,
                   Eigen::MatrixXf& marginals,
                   int& iterations,
                   bool& converged,
                   Eigen::MatrixXd* messages = nullptr);

/** Stage 3 of training: the factor beta on the log edge potentials that minimises the
 * weighted negative log-likelihood of the labelled super-voxels under their BP
 * marginals on the training graph, searched on the grid 0.1, 0.2, .., 1.5. */
double
fitEdgeScale (const Graph& graph,
              const MultiscaleCrfModel::Weights& w,
              const std::vector<double>& node_weights,
              const CrfSettings& settings);
/** Milliseconds since \a t0. */
inline double
msSince (std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now() -
                                                    t0)
      .count();
}

/** Whether \a in is a cloud train() or classify() (\a caller) can read; PCL_ERROR when
 * not. */
bool
checkInput (const CrfInput& in, const char* caller);
} // namespace crf
} // namespace pcl_ext
