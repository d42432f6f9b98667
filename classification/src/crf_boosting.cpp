/*
 * pcl_ext: node potentials of the multi-scale CRF from gradient-boosted trees
 * (XGBoost), beside Lim & Suter's multinomial logistic regression (eq. 8).
 */
#include "crf_internal.h"

#include <pcl_ext/common/parallel.h>

#include <xgboost/c_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

namespace pcl_ext {
namespace crf {
namespace {
/** Owns a DMatrix handle. */
struct DMatrix {
  DMatrixHandle h = nullptr;
  ~DMatrix() { XGDMatrixFree (h); }
};

/** Owns a Booster handle. */
struct Booster {
  BoosterHandle h = nullptr;
  ~Booster() { XGBoosterFree (h); }
};

bool
failed (int code, const char* what, std::string& error)
{
  if (code == 0)
    return false;
  error = std::string (what) + ": " + XGBGetLastError();
  return true;
}

/** Rows \a rows of \a x (all rows when empty) as a row-major DMatrix. */
bool
makeMatrix (const Eigen::MatrixXf& x,
            const std::vector<std::size_t>& rows,
            DMatrix& m,
            std::string& error)
{
  const std::size_t n =
      rows.empty() ? static_cast<std::size_t> (x.rows()) : rows.size();
  const std::size_t d = static_cast<std::size_t> (x.cols());
  std::vector<float> data (std::max<std::size_t> (1, n * d));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < d; ++c)
      data[r * d + c] = x (static_cast<Eigen::Index> (rows.empty() ? r : rows[r]),
                           static_cast<Eigen::Index> (c));
  const float missing = std::numeric_limits<float>::quiet_NaN();
  return !failed (XGDMatrixCreateFromMat (data.data(), n, d, missing, &m.h),
                  "creating the feature matrix",
                  error);
}

bool
setParameters (BoosterHandle h,
               std::size_t classes,
               const CrfSettings& settings,
               std::string& error)
{
  char eta[32];
  std::snprintf (eta, sizeof (eta), "%.17g", settings.boost_eta);
  const std::string pairs[][2] = {
      {"objective", "multi:softprob"},
      {"num_class", std::to_string (classes)},
      {"tree_method", "hist"},
      {"max_depth", std::to_string (settings.boost_depth)},
      {"eta", eta},
      {"subsample", "1"},
      {"colsample_bytree", "1"},
      {"seed", "0"},
      {"seed_per_iteration", "0"},
      {"verbosity", "0"},
      // One thread: on the node counts of a scan (tens of thousands) the parallel
      // regions of the histogram method cost more than they gain (docs/lim_suter.md),
      // and the trees cannot depend on the thread count.
      {"nthread", "1"}};
  for (const auto& p : pairs)
    if (failed (XGBoosterSetParam (h, p[0].c_str(), p[1].c_str()),
                "setting the boosted trees' parameters",
                error))
      return false;
  return true;
}

bool
loadBooster (const std::vector<char>& model, Booster& b, std::string& error)
{
  if (failed (XGBoosterCreate (nullptr, 0, &b.h), "creating a booster", error))
    return false;
  if (model.empty()) {
    error = "empty booster";
    return false;
  }
  return !failed (XGBoosterLoadModelFromBuffer (b.h, model.data(), model.size()),
                  "reading the booster",
                  error);
}

/** At most this many cross-fitting folds (each trains two boosters). */
constexpr int kMaxFolds = 3;

const char kBase64[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
} // namespace

bool
trainBooster (const Eigen::MatrixXf& x,
              const std::vector<int>& labels,
              const std::vector<double>& weights,
              const std::vector<std::size_t>& rows,
              std::size_t classes,
              const CrfSettings& settings,
              std::vector<char>& model,
              std::string& error)
{
  model.clear();
  if (rows.empty()) {
    error = "no labelled node to train the boosted trees on";
    return false;
  }
  DMatrix m;
  if (!makeMatrix (x, rows, m, error))
    return false;
  std::vector<float> y (rows.size()), w (rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    y[r] = static_cast<float> (labels[rows[r]]);
    w[r] = static_cast<float> (weights[rows[r]]);
  }
  if (failed (XGDMatrixSetFloatInfo (m.h, "label", y.data(), y.size()),
              "setting the labels",
              error) ||
      failed (XGDMatrixSetFloatInfo (m.h, "weight", w.data(), w.size()),
              "setting the weights",
              error))
    return false;
  Booster b;
  if (failed (XGBoosterCreate (&m.h, 1, &b.h), "creating a booster", error) ||
      !setParameters (b.h, classes, settings, error))
    return false;
  for (int it = 0; it < settings.boost_rounds; ++it)
    if (failed (XGBoosterUpdateOneIter (b.h, it, m.h), "boosting", error))
      return false;
  bst_ulong len = 0;
  const char* data = nullptr;
  if (failed (XGBoosterSaveModelToBuffer (b.h, "{\"format\": \"ubj\"}", &len, &data),
              "saving the booster",
              error))
    return false;
  model.assign (data, data + len);
  return true;
}

bool
checkBooster (const std::vector<char>& model,
              std::size_t classes,
              std::size_t features,
              std::string& error)
{
  Booster b;
  if (!loadBooster (model, b, error))
    return false;
  bst_ulong n = 0;
  if (failed (XGBoosterGetNumFeature (b.h, &n), "reading the booster", error))
    return false;
  if (n != features) {
    error = "the booster has " + std::to_string (n) + " features, the model " +
            std::to_string (features);
    return false;
  }
  // The class count: one probability per class for one row.
  const Eigen::MatrixXf row =
      Eigen::MatrixXf::Zero (1, static_cast<Eigen::Index> (features));
  Eigen::MatrixXf logp;
  return boosterLogProbabilities (model, row, classes, 1, logp, error);
}

bool
boosterLogProbabilities (const std::vector<char>& model,
                         const Eigen::MatrixXf& x,
                         std::size_t classes,
                         unsigned int threads,
                         Eigen::MatrixXf& log_probabilities,
                         std::string& error)
{
  log_probabilities.resize (x.rows(), static_cast<Eigen::Index> (classes));
  if (x.rows() == 0)
    return true;
  Booster b;
  DMatrix m;
  if (!loadBooster (model, b, error) || !makeMatrix (x, {}, m, error))
    return false;
  const std::string nthread = std::to_string (resolveThreadCount (threads));
  if (failed (XGBoosterSetParam (b.h, "nthread", nthread.c_str()),
              "setting the threads",
              error))
    return false;
  bst_ulong len = 0;
  const float* p = nullptr;
  if (failed (XGBoosterPredict (b.h, m.h, 0, 0, 0, &len, &p), "predicting", error))
    return false;
  if (len != static_cast<bst_ulong> (x.rows()) * classes) {
    error = "the booster gives " + std::to_string (len) + " probabilities for " +
            std::to_string (x.rows()) + " rows of " + std::to_string (classes) +
            " classes";
    return false;
  }
  for (Eigen::Index r = 0; r < x.rows(); ++r)
    for (std::size_t c = 0; c < classes; ++c)
      log_probabilities (r, static_cast<Eigen::Index> (c)) =
          std::log (std::max (p[static_cast<std::size_t> (r) * classes + c], 1e-30f));
  return true;
}

std::string
encodeBase64 (const std::vector<char>& bytes)
{
  std::string out;
  out.reserve ((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = static_cast<unsigned char> (bytes[i]) << 16;
    if (i + 1 < bytes.size())
      v |= static_cast<unsigned char> (bytes[i + 1]) << 8;
    if (i + 2 < bytes.size())
      v |= static_cast<unsigned char> (bytes[i + 2]);
    out += kBase64[(v >> 18) & 63];
    out += kBase64[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kBase64[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kBase64[v & 63] : '=';
  }
  return out;
}

bool
decodeBase64 (const std::string& text, std::vector<char>& bytes)
{
  bytes.clear();
  if (text.size() % 4 != 0)
    return false;
  auto value = [] (char c) -> int {
    const char* p = std::find (kBase64, kBase64 + 64, c);
    return p == kBase64 + 64 ? -1 : static_cast<int> (p - kBase64);
  };
  bytes.reserve (text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    const bool last = i + 4 == text.size();
    const int pad = (text[i + 3] == '=') + (text[i + 2] == '=');
    if (pad > 0 && (!last || (pad == 2 && text[i + 3] != '=')))
      return false;
    unsigned v = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const int d = k >= 4 - static_cast<std::size_t> (pad) ? 0 : value (text[i + k]);
      if (d < 0)
        return false;
      v = (v << 6) | static_cast<unsigned> (d);
    }
    bytes.push_back (static_cast<char> ((v >> 16) & 255));
    if (pad < 2)
      bytes.push_back (static_cast<char> ((v >> 8) & 255));
    if (pad < 1)
      bytes.push_back (static_cast<char> (v & 255));
  }
  // Only the canonical encoding is accepted, so that a model's text round-trips.
  return encodeBase64 (bytes) == text;
}
namespace {
/** The rows \a rows of \a x. */
Eigen::MatrixXf
selectRows (const Eigen::MatrixXf& x, const std::vector<std::size_t>& rows)
{
  Eigen::MatrixXf out (static_cast<Eigen::Index> (rows.size()), x.cols());
  for (std::size_t r = 0; r < rows.size(); ++r)
    out.row (static_cast<Eigen::Index> (r)) =
        x.row (static_cast<Eigen::Index> (rows[r]));
  return out;
}

/** graph.phi of the nodes \a nodes by \a model. */
bool
predictInto (const std::vector<char>& model,
             const std::vector<std::size_t>& nodes,
             std::size_t classes,
             unsigned int threads,
             Graph& graph,
             std::string& error)
{
  Eigen::MatrixXf logp;
  if (!boosterLogProbabilities (
          model, selectRows (graph.z, nodes), classes, threads, logp, error))
    return false;
  for (std::size_t r = 0; r < nodes.size(); ++r)
    graph.phi.row (static_cast<Eigen::Index> (nodes[r])) =
        logp.row (static_cast<Eigen::Index> (r));
  return true;
}
} // namespace

bool
trainBoostedNodes (Graph& graph,
                   const std::vector<double>& node_weights,
                   const std::vector<int>& node_cloud,
                   std::size_t classes,
                   const CrfSettings& settings,
                   Boosters& boosters,
                   std::string& error)
{
  const std::size_t N = graph.size(), S = graph.num_supervoxels;
  // Cross-fitting folds: the clouds in at most kMaxFolds groups (cloud k in group k mod
  // kMaxFolds); none without edges to fit, whose training never reads graph.phi.
  const int clouds =
      node_cloud.empty() || settings.mode == CrfMode::NodeOnly
          ? 1
          : std::min (kMaxFolds,
                      *std::max_element (node_cloud.begin(), node_cloud.end()) + 1);
  auto fold_of = [&] (std::size_t n) { return node_cloud[n] % clouds; };
  graph.phi.resize (static_cast<Eigen::Index> (N), static_cast<Eigen::Index> (classes));
  boosters = Boosters();
  for (int type = 0; type < 2; ++type) {
    const std::size_t first = type == 0 ? 0 : S, last = type == 0 ? S : N;
    if (first == last)
      continue;
    std::vector<char>& model = type == 0 ? boosters.supervoxel : boosters.point;
    std::vector<std::size_t> rows;
    for (std::size_t n = first; n < last; ++n)
      if (graph.labels[n] >= 0 && node_weights[n] > 0.0)
        rows.push_back (n);
    if (!trainBooster (
            graph.z, graph.labels, node_weights, rows, classes, settings, model, error))
      return false;
    for (int k = 0; k < clouds; ++k) {
      std::vector<std::size_t> nodes, others;
      for (std::size_t n = first; n < last; ++n)
        if (clouds == 1 || fold_of (n) == k)
          nodes.push_back (n);
      for (const std::size_t n : rows)
        if (clouds > 1 && fold_of (n) != k)
          others.push_back (n);
      std::vector<char> fold;
      if (!others.empty() && !trainBooster (graph.z,
                                            graph.labels,
                                            node_weights,
                                            others,
                                            classes,
                                            settings,
                                            fold,
                                            error))
        return false;
      if (!predictInto (others.empty() ? model : fold,
                        nodes,
                        classes,
                        settings.threads,
                        graph,
                        error))
        return false;
    }
  }
  return true;
}

bool
boostedNodeInputs (const Boosters& boosters,
                   std::size_t classes,
                   unsigned int threads,
                   Graph& graph,
                   std::string& error)
{
  const std::size_t N = graph.size(), S = graph.num_supervoxels;
  graph.phi.resize (static_cast<Eigen::Index> (N), static_cast<Eigen::Index> (classes));
  std::vector<std::size_t> svs (S), points (N - S);
  for (std::size_t n = 0; n < N; ++n)
    (n < S ? svs[n] : points[n - S]) = n;
  if (!points.empty() && boosters.point.empty()) {
    error = "the model has no booster for local points";
    return false;
  }
  return predictInto (boosters.supervoxel, svs, classes, threads, graph, error) &&
         (points.empty() ||
          predictInto (boosters.point, points, classes, threads, graph, error));
}

void
setIdentityNodeWeights (std::size_t classes, Eigen::VectorXd& theta)
{
  const std::size_t block = classes * (classes + 1);
  for (std::size_t b = 0; b < 2; ++b)
    for (std::size_t c = 0; c < classes; ++c)
      theta[static_cast<Eigen::Index> (b * block + (c + 1) * classes + c)] = 1.0;
}
} // namespace crf
} // namespace pcl_ext
