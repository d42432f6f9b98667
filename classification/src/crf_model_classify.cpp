/*
 * pcl_ext: classification with the multi-scale CRF (Lim & Suter 2008, section 3.2,
 * eq. 11), averaged over draws of the super-voxels.
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace pcl_ext {
bool
MultiscaleCrfModel::classify (const CrfInput& input,
                              std::vector<std::uint32_t>& labels,
                              Eigen::MatrixXf& probabilities)
{
  labels.clear();
  probabilities.resize (0, 0);
  last_supervoxels_.clear();
  last_marginals_.resize (0, 0);
  if (!trained_) {
    PCL_ERROR (
        "[pcl_ext::MultiscaleCrfModel::classify] The model is not trained (train or "
        "loadModel first).\n");
    return false;
  }
  if (!checkCrfSettings (settings_, "MultiscaleCrfModel::classify") ||
      !crf::checkInput (input, "classify"))
    return false;
  if ((settings_.features.colour && input.colours.empty()) ||
      (settings_.features.intensity && input.intensity.empty())) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::classify] The model uses %s%s%s, which "
               "the input "
               "does not have.\n",
               settings_.features.colour ? "colour" : "",
               settings_.features.colour && settings_.features.intensity ? " and " : "",
               settings_.features.intensity ? "intensity" : "");
    return false;
  }
  // Each draw of the super-voxels classified on its own (eq. 11), the points' class
  // probabilities averaged over the draws.
  CrfStatistics stats;
  const std::size_t N = input.xyz->size();
  const Eigen::Index C = static_cast<Eigen::Index> (class_ids_.size());
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero (static_cast<Eigen::Index> (N), C);
  std::vector<char> covered (N, 0);
  last_draws_.clear();
  const std::size_t draws = static_cast<std::size_t> (settings_.draws);
  std::vector<crf::Graph> graphs (draws);
  std::vector<SupervoxelSet> sets (draws);
  std::vector<CrfStatistics> st (draws);
  std::vector<Eigen::MatrixXf> marginals (draws);
  for (std::size_t d = 0; d < draws; ++d) {
    CrfSettings draw = settings_;
    draw.supervoxels.seed = settings_.supervoxels.seed + d;
    Eigen::MatrixXf raw;
    if (!crf::buildGraph (input, draw, sets[d], raw, graphs[d], st[d]))
      return false;
    crf::finishGraph (raw, weights_->mean, weights_->scale, graphs[d]);
    if (weights_->node_model == CrfNodeModel::BoostedTrees) {
      std::string error;
      if (!crf::boostedNodeInputs (weights_->boosters,
                                   class_ids_.size(),
                                   settings_.threads,
                                   graphs[d],
                                   error)) {
        PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::classify] %s.\n", error.c_str());
        return false;
      }
    }
    else
      crf::expandFeatures (weights_->expansion, weights_->knots, graphs[d]);
  }
  // The draws' belief propagations side by side, one thread each (the result of each
  // does not depend on its threads): a small graph's sweeps run on one thread anyway.
  const int threads = static_cast<int> (resolveThreadCount (settings_.threads));
  const auto bp_start = std::chrono::steady_clock::now();
#pragma omp parallel for num_threads(std::min(threads, settings_.draws))               \
    schedule(dynamic, 1)
  for (std::ptrdiff_t d = 0; d < static_cast<std::ptrdiff_t> (draws); ++d) {
    crf::beliefPropagation (graphs[d],
                            *weights_,
                            settings_,
                            marginals[d],
                            st[d].iterations,
                            st[d].converged);
  }
  stats.inference_ms = crf::msSince (bp_start);
  for (std::size_t d = 0; d < draws; ++d) {
    const auto t0 = std::chrono::steady_clock::now();
    const SupervoxelSet& svs = sets[d];
    // Eq. 11: a point in several super-voxels takes the label maximising the product
    // of their probabilities (summed logs, normalised into per-point probabilities).
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t> (N); ++i) {
      const std::size_t b = svs.membership_offsets[i],
                        e = svs.membership_offsets[i + 1];
      if (b == e)
        continue;
      Eigen::VectorXd logp = Eigen::VectorXd::Zero (C);
      for (std::size_t k = b; k < e; ++k)
        logp += marginals[d]
                    .row (svs.membership[k])
                    .transpose()
                    .cast<double>()
                    .cwiseMax (1e-30)
                    .array()
                    .log()
                    .matrix();
      const Eigen::VectorXd p = (logp.array() - logp.maxCoeff()).exp().matrix();
      sum.row (i) += (p / p.sum()).transpose();
      covered[static_cast<std::size_t> (i)] = 1;
    }
    stats.supervoxels_ms += st[d].supervoxels_ms;
    stats.features_ms += st[d].features_ms;
    stats.inference_ms += crf::msSince (t0);
    stats.iterations = std::max (stats.iterations, st[d].iterations);
  }
  stats.supervoxels = st[0].supervoxels;
  stats.local_points = st[0].local_points;
  stats.local_edges = st[0].local_edges;
  stats.regional_edges = st[0].regional_edges;
  stats.converged = std::all_of (
      st.begin(), st.end(), [] (const CrfStatistics& x) { return x.converged; });
  last_marginals_ = std::move (marginals[0]);
  last_draws_ = std::move (sets);
  probabilities = Eigen::MatrixXf::Zero (static_cast<Eigen::Index> (N), C);
  labels.assign (N, 0);
  for (std::size_t i = 0; i < N; ++i) {
    if (!covered[i])
      continue;
    const Eigen::Index row = static_cast<Eigen::Index> (i);
    Eigen::Index best;
    sum.row (row).maxCoeff (&best);
    probabilities.row (row) = (sum.row (row) / settings_.draws).cast<float>();
    labels[i] = class_ids_[best];
  }
  stats.points = N;
  statistics_ = stats;
  last_supervoxels_ = last_draws_.front();
  return true;
}
} // namespace pcl_ext
