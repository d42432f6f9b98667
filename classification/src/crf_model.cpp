/*
 * pcl_ext: training and classification of the multi-scale CRF (Lim & Suter 2008,
 * section 3.2).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <set>

namespace pcl_ext {
namespace {
/** The one of \a values whose name (\a name) is \a text, into \a value; false when
 * none is. */
template <typename Enum>
bool
parseByName (const std::string& text,
             std::initializer_list<Enum> values,
             const char* (*name) (Enum),
             Enum& value)
{
  for (const Enum v : values)
    if (text == name (v)) {
      value = v;
      return true;
    }
  return false;
}
} // namespace

const char*
crfModeName (CrfMode mode)
{
  switch (mode) {
  case CrfMode::NodeOnly:
    return "node";
  case CrfMode::LocalCrf:
    return "crf";
  default:
    return "mcrf";
  }
}

bool
parseCrfMode (const std::string& text, CrfMode& mode)
{
  return parseByName (text,
                      {CrfMode::NodeOnly, CrfMode::LocalCrf, CrfMode::MultiscaleCrf},
                      crfModeName,
                      mode);
}

const char*
crfNodeExpansionName (CrfNodeExpansion expansion)
{
  switch (expansion) {
  case CrfNodeExpansion::Linear:
    return "linear";
  case CrfNodeExpansion::Spline:
    return "spline";
  default:
    return "spline_products";
  }
}

bool
parseCrfNodeExpansion (const std::string& text, CrfNodeExpansion& expansion)
{
  return parseByName (text,
                      {CrfNodeExpansion::Linear,
                       CrfNodeExpansion::Spline,
                       CrfNodeExpansion::SplineProducts},
                      crfNodeExpansionName,
                      expansion);
}

const char*
crfNodeModelName (CrfNodeModel model)
{
  return model == CrfNodeModel::BoostedTrees ? "boosted_trees" : "logistic";
}

bool
parseCrfNodeModel (const std::string& text, CrfNodeModel& model)
{
  return parseByName (text,
                      {CrfNodeModel::Logistic, CrfNodeModel::BoostedTrees},
                      crfNodeModelName,
                      model);
}

const char*
crfTrainingName (CrfTraining training)
{
  return training == CrfTraining::Staged ? "staged" : "pseudo_likelihood";
}

bool
parseCrfTraining (const std::string& text, CrfTraining& training)
{
  if (text == "staged")
    training = CrfTraining::Staged;
  else if (text == "pseudo_likelihood")
    training = CrfTraining::PseudoLikelihood;
  else
    return false;
  return true;
}

bool
checkCrfSettings (const CrfSettings& s, const char* caller)
{
  const char* bad = nullptr;
  if (s.supervoxels.adjacency < 0)
    bad = "the number of regional neighbours l must be >= 0";
  else if (s.local_edges < 0)
    bad = "the number of local edges m must be >= 0";
  else if (s.draws < 1 || s.draws > 64)
    bad = "the number of draws must be in [1, 64]";
  else if (!(s.sigma > 0.0) || !std::isfinite (s.sigma))
    bad = "the prior's sigma must be positive and finite";
  else if (s.spline_knots < 1 || s.spline_knots > 64)
    bad = "the number of spline knots must be in [1, 64]";
  else if (s.max_training_iterations < 1 || s.bp_iterations < 1)
    bad = "iteration limits must be at least 1";
  else if (!(s.edge_scale >= 0.0) || !std::isfinite (s.edge_scale))
    bad = "the edge scale must be 0 (fitted at training) or positive and finite";
  else if (!(s.bp_damping >= 0.0 && s.bp_damping < 1.0))
    bad = "the BP damping must be in [0, 1)";
  else if (!(s.bp_tolerance > 0.0) || !std::isfinite (s.bp_tolerance))
    bad = "the BP tolerance must be positive and finite";
  else if (!(s.features.ground_cell > 0.f) || !std::isfinite (s.features.ground_cell) ||
           s.features.ground_reach < 0 || !s.features.up.allFinite() ||
           s.features.up.norm() == 0.f)
    bad = "the ground grid needs a positive cell, a reach >= 0 and a non-zero up axis";
  else if (!validFeatureScales (s.features.scales))
    bad = "the feature scales must be positive, finite and ascending";
  else if (s.boost_rounds < 1 || s.boost_rounds > 10000 || s.boost_depth < 1 ||
           s.boost_depth > 32 || !(s.boost_eta > 0.0 && s.boost_eta <= 1.0))
    bad = "the boosted trees need rounds in [1, 10000], a depth in [1, 32] and a "
          "learning rate in (0, 1]";
  else if (s.node_model == CrfNodeModel::BoostedTrees &&
           s.training == CrfTraining::PseudoLikelihood)
    bad = "the paper's pseudo-likelihood training fits logistic node weights, not "
          "boosted trees";
  else if (s.node_model == CrfNodeModel::BoostedTrees &&
           s.node_expansion != CrfNodeExpansion::Linear)
    bad = "the spline expansions are inputs of the logistic node model, not of the "
          "boosted trees";
  if (bad) {
    PCL_ERROR ("[pcl_ext::%s] Invalid CRF settings: %s.\n", caller, bad);
    return false;
  }
  return checkAdaptiveRadiusParameters (s.supervoxels.radius, caller);
}

MultiscaleCrfModel::MultiscaleCrfModel() : weights_ (new Weights) {}
MultiscaleCrfModel::~MultiscaleCrfModel() = default;
MultiscaleCrfModel::MultiscaleCrfModel (const MultiscaleCrfModel& o)
: settings_ (o.settings_)
, names_ (o.names_)
, class_ids_ (o.class_ids_)
, weights_ (new Weights (*o.weights_))
, trained_ (o.trained_)
{}

MultiscaleCrfModel&
MultiscaleCrfModel::operator= (const MultiscaleCrfModel& o)
{
  if (this != &o) {
    settings_ = o.settings_;
    names_ = o.names_;
    class_ids_ = o.class_ids_;
    *weights_ = *o.weights_;
    trained_ = o.trained_;
  }
  return *this;
}

std::vector<std::string>
MultiscaleCrfModel::getFeatureNames() const
{
  return weights_->feature_names;
}

bool
crf::checkInput (const CrfInput& in, const char* caller)
{
  if (!in.xyz || in.xyz->empty()) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::%s] Empty input cloud.\n", caller);
    return false;
  }
  if ((!in.colours.empty() && in.colours.size() != in.xyz->size()) ||
      (!in.intensity.empty() && in.intensity.size() != in.xyz->size())) {
    PCL_ERROR (
        "[pcl_ext::MultiscaleCrfModel::%s] Colours or intensities do not match the "
        "cloud.\n",
        caller);
    return false;
  }
  return true;
}

bool
MultiscaleCrfModel::train (const std::vector<CrfInput>& inputs,
                           const std::vector<std::vector<std::uint32_t>>& labels)
{
  if (!checkCrfSettings (settings_, "MultiscaleCrfModel::train"))
    return false;
  if (inputs.empty() || inputs.size() != labels.size()) {
    PCL_ERROR (
        "[pcl_ext::MultiscaleCrfModel::train] Need at least one cloud and one label "
        "list per cloud.\n");
    return false;
  }
  CrfSettings settings = settings_;
  settings.features.colour = settings.features.intensity = true;
  std::set<std::uint32_t> found;
  for (std::size_t c = 0; c < inputs.size(); ++c) {
    if (!crf::checkInput (inputs[c], "train"))
      return false;
    if (labels[c].size() != inputs[c].xyz->size()) {
      PCL_ERROR (
          "[pcl_ext::MultiscaleCrfModel::train] Cloud %zu has %zu points but %zu "
          "labels.\n",
          c,
          inputs[c].xyz->size(),
          labels[c].size());
      return false;
    }
    settings.features.colour = settings.features.colour && !inputs[c].colours.empty();
    settings.features.intensity =
        settings.features.intensity && !inputs[c].intensity.empty();
    for (const auto l : labels[c])
      if (l != 0)
        found.insert (l);
  }
  // The classes: the named ones (each must occur), else those found.
  std::vector<std::uint32_t> ids;
  if (!names_.empty()) {
    for (const auto& [id, name] : names_) {
      if (id == 0 || !found.count (id)) {
        PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::train] Class %u (%s) has no training "
                   "points.\n",
                   id,
                   name.c_str());
        return false;
      }
      ids.push_back (id);
    }
  }
  else
    ids.assign (found.begin(), found.end());
  if (ids.size() < 2) {
    PCL_ERROR (
        "[pcl_ext::MultiscaleCrfModel::train] Need at least two classes with labelled "
        "points (found %zu); is the input labelled?\n",
        ids.size());
    return false;
  }
  auto class_index = [&] (std::uint32_t l) -> int {
    const auto it = std::lower_bound (ids.begin(), ids.end(), l);
    return it != ids.end() && *it == l ? static_cast<int> (it - ids.begin()) : -1;
  };
  const std::size_t C = ids.size();

  // One graph per cloud, merged into one (features are standardised after all are
  // known).
  CrfStatistics stats;
  crf::Graph graph;
  Eigen::MatrixXf raw;
  SupervoxelSet last;
  std::vector<int> node_cloud; // the input each node comes from
  for (std::size_t c = 0; c < inputs.size(); ++c) {
    crf::Graph g;
    Eigen::MatrixXf r;
    CrfStatistics s;
    if (!crf::buildGraph (inputs[c], settings, last, r, g, s))
      return false;
    stats.supervoxels_ms += s.supervoxels_ms;
    stats.features_ms += s.features_ms;
    stats.points += inputs[c].xyz->size();
    stats.supervoxels += s.supervoxels;
    stats.local_points += s.local_points;
    stats.local_edges += s.local_edges;
    stats.regional_edges += s.regional_edges;
    // Labels: super-voxels by majority of their members, local points their own.
    for (std::size_t v = 0; v < g.num_supervoxels; ++v) {
      std::vector<std::size_t> votes (C, 0);
      for (const auto i : last.supervoxels[v].members) {
        const int k = class_index (labels[c][i]);
        if (k >= 0)
          ++votes[k];
      }
      const auto best = std::max_element (votes.begin(), votes.end());
      g.labels[v] = *best > 0 ? static_cast<int> (best - votes.begin()) : -1;
    }
    for (std::size_t n = g.num_supervoxels; n < g.size(); ++n)
      g.labels[n] = class_index (labels[c][g.node_point[n]]);
    // Append: super-voxel nodes stay first so that node type is "index <
    // num_supervoxels".
    const std::size_t S0 = graph.num_supervoxels, L0 = graph.size() - S0;
    const std::size_t S1 = g.num_supervoxels;
    auto remap_old = [&] (std::uint32_t n) {
      return n < S0 ? n : static_cast<std::uint32_t> (n + S1);
    };
    auto remap_new = [&] (std::uint32_t n) {
      return n < S1 ? static_cast<std::uint32_t> (S0 + n)
                    : static_cast<std::uint32_t> (S0 + S1 + L0 + (n - S1));
    };
    crf::Graph merged;
    merged.num_supervoxels = S0 + S1;
    Eigen::MatrixXf mraw (raw.rows() + r.rows(), r.cols());
    auto put = [&] (std::size_t at,
                    const Eigen::MatrixXf& src,
                    std::size_t from,
                    std::size_t count,
                    const crf::Graph& gsrc) {
      for (std::size_t k = 0; k < count; ++k) {
        mraw.row (at + k) = src.row (from + k);
        merged.node_point[at + k] = gsrc.node_point[from + k];
        merged.labels[at + k] = gsrc.labels[from + k];
      }
    };
    merged.node_point.resize (mraw.rows());
    merged.labels.resize (mraw.rows());
    put (0, raw, 0, S0, graph);
    put (S0, r, 0, S1, g);
    put (S0 + S1, raw, S0, L0, graph);
    put (S0 + S1 + L0, r, S1, g.size() - S1, g);
    for (std::size_t e = 0; e < graph.edge_a.size(); ++e) {
      merged.edge_a.push_back (remap_old (graph.edge_a[e]));
      merged.edge_b.push_back (remap_old (graph.edge_b[e]));
      merged.edge_regional.push_back (graph.edge_regional[e]);
    }
    for (std::size_t e = 0; e < g.edge_a.size(); ++e) {
      merged.edge_a.push_back (remap_new (g.edge_a[e]));
      merged.edge_b.push_back (remap_new (g.edge_b[e]));
      merged.edge_regional.push_back (g.edge_regional[e]);
    }
    std::vector<int> cloud_of (merged.size(), static_cast<int> (c));
    std::copy (node_cloud.begin(), node_cloud.begin() + S0, cloud_of.begin());
    std::copy (node_cloud.begin() + S0, node_cloud.end(), cloud_of.begin() + S0 + S1);
    node_cloud = std::move (cloud_of);
    graph = std::move (merged);
    raw = std::move (mraw);
  }

  // Feature scaling from every node's features.
  const Eigen::Index D = raw.cols();
  Eigen::VectorXd mean = Eigen::VectorXd::Zero (D), scale = Eigen::VectorXd::Ones (D);
  for (Eigen::Index d = 0; d < D; ++d) {
    double s = 0, ss = 0;
    for (Eigen::Index n = 0; n < raw.rows(); ++n) {
      s += raw (n, d);
      ss += static_cast<double> (raw (n, d)) * raw (n, d);
    }
    mean (d) = s / raw.rows();
    const double var = ss / raw.rows() - mean (d) * mean (d);
    scale (d) = var > 1e-12 ? std::sqrt (var) : 1.0;
  }
  crf::finishGraph (raw, mean, scale, graph);
  const bool boosted = settings.node_model == CrfNodeModel::BoostedTrees;
  const std::vector<std::vector<double>> knots =
      boosted ? std::vector<std::vector<double>> (static_cast<std::size_t> (D))
              : crf::fitKnots (graph.z, settings.node_expansion, settings.spline_knots);
  if (!boosted)
    crf::expandFeatures (settings.node_expansion, knots, graph);

  // Node weights: nodes that take part in this mode, balanced by class frequency.
  std::vector<double> node_weights (graph.size(), 0.0);
  std::vector<double> count (C, 0.0);
  const bool use_local = settings.mode != CrfMode::NodeOnly;
  for (std::size_t n = 0; n < graph.size(); ++n)
    if (graph.labels[n] >= 0 && (n < graph.num_supervoxels || use_local)) {
      node_weights[n] = 1.0;
      count[graph.labels[n]] += 1.0;
    }
  double total = 0.0;
  for (const double c : count)
    total += c;
  if (total == 0.0) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::train] No labelled super-voxel.\n");
    return false;
  }
  for (std::size_t k = 0; k < C; ++k)
    if (count[k] == 0.0) {
      PCL_ERROR (
          "[pcl_ext::MultiscaleCrfModel::train] Class %u has no labelled super-voxel "
          "or point in the graph.\n",
          ids[k]);
      return false;
    }
  if (settings.balance_classes)
    for (std::size_t n = 0; n < graph.size(); ++n)
      if (node_weights[n] > 0.0)
        node_weights[n] = std::sqrt (total / (C * count[graph.labels[n]]));

  auto t0 = std::chrono::steady_clock::now();
  // Stage 1: node potentials alone (all of NodeOnly). Boosted trees: their log class
  // probabilities become the node inputs, with identity weights held fixed.
  crf::Boosters boosters;
  if (boosted) {
    std::string error;
    if (!crf::trainBoostedNodes (
            graph, node_weights, node_cloud, C, settings, boosters, error)) {
      PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::train] %s.\n", error.c_str());
      return false;
    }
  }
  const Eigen::Index Dn = graph.phi.cols();
  Eigen::VectorXd theta = Eigen::VectorXd::Zero (
      static_cast<Eigen::Index> (2 * C * (Dn + 1) + 2 * C * (D + 1)));
  bool converged = !boosted;
  double value = 0.0;
  int iterations = 0;
  if (boosted)
    crf::setIdentityNodeWeights (C, theta);
  else
    iterations = crf::trainWeights (graph,
                                    node_weights,
                                    Eigen::MatrixXd(),
                                    C,
                                    settings,
                                    false,
                                    theta,
                                    converged,
                                    value);
  const bool paper = settings.training == CrfTraining::PseudoLikelihood &&
                     settings.mode != CrfMode::NodeOnly;
  if (paper) {
    // Eq. 9: every weight at once, each node scored given its neighbours' true labels
    // (unlabelled neighbours send nothing), from the node-only fit.
    Eigen::MatrixXd labels = Eigen::MatrixXd::Zero (
        static_cast<Eigen::Index> (C), static_cast<Eigen::Index> (graph.size()));
    for (std::size_t n = 0; n < graph.size(); ++n)
      if (graph.labels[n] >= 0)
        labels (graph.labels[n], static_cast<Eigen::Index> (n)) = 1.0;
    iterations += crf::trainWeights (
        graph, node_weights, labels, C, settings, false, theta, converged, value);
  }
  else if (settings.mode != CrfMode::NodeOnly) {
    // Stage 2: the edge weights, with the node weights held at stage 1. Each node hears
    // from its neighbours the message BP's first sweep sends, computed from their
    // stage-1 class probabilities (stacked pseudo-likelihood). The node weights stay
    // fixed and the neighbours enter through their probabilities, not their labels:
    // otherwise the edges explain the labels alone, rare classes get large edge
    // potentials that a small belief already triggers in BP, and inference collapses
    // onto those classes.
    const Eigen::Index D1 = Dn + 1;
    const Eigen::Map<const Eigen::MatrixXd> ws (
        theta.data(), static_cast<Eigen::Index> (C), D1);
    const Eigen::Map<const Eigen::MatrixXd> wx (
        theta.data() + C * D1, static_cast<Eigen::Index> (C), D1);
    Eigen::MatrixXd context (static_cast<Eigen::Index> (C),
                             static_cast<Eigen::Index> (graph.size()));
    for (std::size_t n = 0; n < graph.size(); ++n) {
      const auto& W = n < graph.num_supervoxels ? ws : wx;
      const Eigen::VectorXd score =
          W.col (0) +
          W.rightCols (Dn) *
              graph.phi.row (static_cast<Eigen::Index> (n)).transpose().cast<double>();
      const Eigen::VectorXd p = (score.array() - score.maxCoeff()).exp().matrix();
      context.col (static_cast<Eigen::Index> (n)) = p / p.sum();
    }
    iterations += crf::trainWeights (
        graph, node_weights, context, C, settings, true, theta, converged, value);
  }
  Weights w;
  w.feature_names = crf::crfFeatureNames (settings.features);
  w.mean = mean;
  w.scale = scale;
  w.expansion = settings.node_expansion;
  w.knots = knots;
  w.node_model = settings.node_model;
  w.boosters = std::move (boosters);
  crf::unpackWeights (
      theta, C, static_cast<std::size_t> (Dn), static_cast<std::size_t> (D), w);
  // Stage 3: the weight of the edges against the nodes at inference (see crf_model.h).
  w.edge_scale = settings.edge_scale > 0.0 ? settings.edge_scale : 1.0;
  if (settings.mode != CrfMode::NodeOnly && settings.edge_scale == 0.0 && !paper)
    w.edge_scale = crf::fitEdgeScale (graph, w, node_weights, settings);
  stats.training_ms = crf::msSince (t0);
  stats.iterations = iterations;
  stats.converged = converged;
  stats.objective = value / total;
  *weights_ = std::move (w);
  class_ids_ = ids;
  for (const auto id : ids)
    if (!names_.count (id))
      names_[id] = std::to_string (id);
  settings_.features.colour = settings.features.colour;
  settings_.features.intensity = settings.features.intensity;
  trained_ = true;
  last_supervoxels_ = std::move (last);
  last_draws_.clear();
  statistics_ = stats;
  return true;
}
} // namespace pcl_ext
