/*
 * pcl_ext: the multi-scale CRF model file: versioned text, parsed strictly.
 */
#include "crf_internal.h"

#include <pcl_ext/io/file_output.h>

#include <pcl/console/print.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace pcl_ext {
namespace {
constexpr const char* kMagic = "pcl_ext_crf_model";
constexpr int kVersion = 5;

/** FNV-1a (64 bits) of \a bytes in hexadecimal: a damaged booster is refused before
 * XGBoost reads it. */
std::string
checksum (const std::vector<char>& bytes)
{
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char> (c);
    h *= 1099511628211ull;
  }
  char buf[20];
  std::snprintf (buf, sizeof (buf), "%016llx", static_cast<unsigned long long> (h));
  return buf;
}

std::string
num (double v)
{
  char buf[40];
  std::snprintf (buf, sizeof (buf), "%.17g", v);
  return buf;
}

/** Reads the model line by line; the first problem is kept with its line number. */
class Reader {
public:
  Reader (const std::string& text, const std::string& source)
  : in_ (text), source_ (source)
  {}

  /** Next non-empty, non-comment line split into words; false at the end. */
  bool
  next (const char* what)
  {
    std::string line;
    while (std::getline (in_, line)) {
      ++line_no_;
      std::istringstream ls (line);
      words_.clear();
      for (std::string w; ls >> w;)
        words_.push_back (w);
      if (!words_.empty() && words_[0][0] != '#')
        return true;
    }
    return fail (std::string ("unexpected end of file, expected ") + what);
  }

  /** The current line must be "<key> v1 .. vn" with exactly \a n values. */
  bool
  expect (const std::string& key, std::size_t n)
  {
    if (words_.empty() || words_[0] != key)
      return fail ("expected '" + key + "'");
    if (words_.size() != n + 1)
      return fail ("'" + key + "' needs " + std::to_string (n) + " value(s)");
    return true;
  }

  bool
  number (std::size_t i, double& v, bool allow_inf = false)
  {
    const char* s = words_[i].c_str();
    char* end = nullptr;
    v = std::strtod (s, &end);
    if (end == s || *end != '\0' || std::isnan (v) || (!allow_inf && std::isinf (v)))
      return fail ("'" + words_[i] + "' is not a finite number");
    return true;
  }

  template <typename Int>
  bool
  integer (std::size_t i, Int& v, long long lo, long long hi)
  {
    const char* s = words_[i].c_str();
    char* end = nullptr;
    const long long x = std::strtoll (s, &end, 10);
    if (end == s || *end != '\0' || x < lo || x > hi)
      return fail ("'" + words_[i] + "' is not an integer in [" + std::to_string (lo) +
                   ", " + std::to_string (hi) + "]");
    v = static_cast<Int> (x);
    return true;
  }

  const std::string&
  word (std::size_t i) const
  {
    return words_[i];
  }

  std::size_t
  size () const
  {
    return words_.size();
  }

  bool
  fail (const std::string& message)
  {
    if (error_.empty())
      error_ = source_ + ":" + std::to_string (line_no_) + ": " + message;
    return false;
  }

  const std::string&
  error () const
  {
    return error_;
  }

private:
  std::istringstream in_;
  std::string source_;
  std::vector<std::string> words_;
  std::size_t line_no_ = 0;
  std::string error_;
};

void
writeMatrix (std::ostringstream& out, const char* name, const Eigen::MatrixXd& m)
{
  out << "weights " << name << ' ' << m.rows() << ' ' << m.cols() << '\n';
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c)
      out << (c ? " " : "") << num (m (r, c));
    out << '\n';
  }
}

bool
readMatrix (Reader& rd,
            const char* name,
            Eigen::Index rows,
            Eigen::Index cols,
            Eigen::MatrixXd& m)
{
  Eigen::Index r = 0, c = 0;
  if (!rd.next ("weights") || !rd.expect ("weights", 3))
    return false;
  if (rd.word (1) != name)
    return rd.fail (std::string ("expected the '") + name + "' weights");
  if (!rd.integer (2, r, 0, 1 << 20) || !rd.integer (3, c, 0, 1 << 20))
    return false;
  if (r != rows || c != cols)
    return rd.fail (std::string ("'") + name + "' weights are " + std::to_string (r) +
                    " x " + std::to_string (c) + ", expected " + std::to_string (rows) +
                    " x " + std::to_string (cols));
  m.resize (rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    if (!rd.next ("a row of weights"))
      return false;
    double v;
    for (Eigen::Index j = 0; j < cols; ++j) {
      if (!rd.expect (rd.word (0), static_cast<std::size_t> (cols - 1)))
        return false;
      if (!rd.number (static_cast<std::size_t> (j), v))
        return false;
      m (i, j) = v;
    }
  }
  return true;
}
} // namespace

std::string
MultiscaleCrfModel::toText() const
{
  std::ostringstream out;
  const auto& s = settings_;
  const auto& r = s.supervoxels.radius;
  out << kMagic << ' ' << kVersion << '\n';
  out << "# Multi-scale CRF over adaptive super-voxels (Lim & Suter 2008)\n";
  out << "mode " << crfModeName (s.mode) << '\n';
  out << "supervoxels " << r.initial_k << ' ' << num (r.damping) << ' '
      << r.max_iterations << ' ' << r.max_k << ' ' << num (r.saturation) << ' '
      << num (r.noise) << ' ' << num (r.c1) << ' ' << num (r.c2) << ' '
      << num (r.epsilon) << ' ' << num (r.colour_weight) << ' ' << num (r.min_radius)
      << ' ' << num (r.max_radius) << ' ' << s.supervoxels.adjacency << ' '
      << s.supervoxels.seed << ' ' << s.draws << '\n';
  out << "local_edges " << s.local_edges << '\n';
  out << "ground " << num (s.features.up.x()) << ' ' << num (s.features.up.y()) << ' '
      << num (s.features.up.z()) << ' ' << num (s.features.ground_cell) << ' '
      << s.features.ground_reach << ' '
      << groundEstimateName (s.features.ground_estimate) << '\n';
  out << "feature_scales " << s.features.scales.size();
  for (const float r : s.features.scales)
    out << ' ' << num (r);
  out << '\n';
  out << "prior_sigma " << num (s.sigma) << '\n';
  out << "node_expansion " << crfNodeExpansionName (s.node_expansion) << ' '
      << s.spline_knots << '\n';
  out << "node_model " << crfNodeModelName (s.node_model) << ' ' << s.boost_rounds
      << ' ' << s.boost_depth << ' ' << num (s.boost_eta) << '\n';
  out << "belief_propagation " << num (s.bp_damping) << ' ' << s.bp_iterations << ' '
      << num (s.bp_tolerance) << '\n';
  out << "classes " << class_ids_.size() << '\n';
  for (const auto id : class_ids_)
    out << "class " << id << ' ' << names_.at (id) << '\n';
  const auto& w = *weights_;
  out << "features " << w.feature_names.size() << '\n';
  for (std::size_t d = 0; d < w.feature_names.size(); ++d)
    out << "feature " << w.feature_names[d] << ' ' << num (w.mean (d)) << ' '
        << num (w.scale (d)) << '\n';
  if (w.expansion != CrfNodeExpansion::Linear)
    for (std::size_t d = 0; d < w.feature_names.size(); ++d) {
      out << "knots " << w.feature_names[d] << ' ' << w.knots[d].size();
      for (const double t : w.knots[d])
        out << ' ' << num (t);
      out << '\n';
    }
  if (w.node_model == CrfNodeModel::BoostedTrees) {
    // booster <nodes> <bytes> <checksum> <base64>, or "-" for a model without one.
    for (int type = 0; type < 2; ++type) {
      const std::vector<char>& b = type == 0 ? w.boosters.supervoxel : w.boosters.point;
      out << "booster " << (type == 0 ? "supervoxel" : "point");
      if (b.empty())
        out << " -\n";
      else
        out << ' ' << b.size() << ' ' << checksum (b) << ' ' << crf::encodeBase64 (b)
            << '\n';
    }
  }
  else {
    writeMatrix (out, "node_supervoxel", w.node_s);
    writeMatrix (out, "node_point", w.node_x);
  }
  writeMatrix (out, "local_edge", w.local_edge);
  writeMatrix (out, "regional_edge", w.regional_edge);
  out << "edge_scale " << num (w.edge_scale) << '\n';
  out << "end\n";
  return out.str();
}

bool
MultiscaleCrfModel::saveModel (const std::string& path) const
{
  if (!trained_) {
    PCL_ERROR (
        "[pcl_ext::MultiscaleCrfModel::saveModel] The model is not trained; nothing "
        "written to %s.\n",
        path.c_str());
    return false;
  }
  try {
    if (io::writeTextFile (path, toText()))
      return true;
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::saveModel] Cannot write %s.\n",
               path.c_str());
  }
  catch (const std::exception& e) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::saveModel] %s\n", e.what());
  }
  return false;
}

bool
MultiscaleCrfModel::loadModel (const std::string& path)
{
  struct stat st;
  if (::stat (path.c_str(), &st) != 0 || !S_ISREG (st.st_mode)) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::loadModel] %s is %s.\n",
               path.c_str(),
               ::stat (path.c_str(), &st) != 0 ? "missing" : "not a regular file");
    return false;
  }
  std::ifstream in (path);
  if (!in) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::loadModel] Cannot open %s.\n",
               path.c_str());
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseModel (text.str(), path);
}

bool
MultiscaleCrfModel::parseModel (const std::string& text, const std::string& source)
{
  Reader rd (text, source);
  CrfSettings s = settings_;
  auto& r = s.supervoxels.radius;
  std::map<std::uint32_t, std::string> names;
  std::vector<std::uint32_t> ids;
  Weights w;
  auto parse = [&] () -> bool {
    int version = 0;
    if (!rd.next (kMagic) || !rd.expect (kMagic, 1) ||
        !rd.integer (1, version, 0, 1 << 20))
      return rd.fail (std::string ("not a model file (expected '") + kMagic + " 1')");
    if (version != kVersion)
      return rd.fail ("model version " + std::to_string (version) +
                      ", this build reads only version " + std::to_string (kVersion) +
                      " (retrain the model with this build)");
    if (!rd.next ("mode") || !rd.expect ("mode", 1))
      return false;
    if (!parseCrfMode (rd.word (1), s.mode))
      return rd.fail ("unknown mode '" + rd.word (1) + "' (node, crf or mcrf)");
    double v[12];
    // 15 values; 14 in a model written before the draws (one draw).
    if (!rd.next ("supervoxels") ||
        !rd.expect ("supervoxels", rd.size() == 15 ? 14 : 15))
      return false;
    s.draws = 1;
    if (rd.size() == 16 && !rd.integer (15, s.draws, 1, 64))
      return false;
    if (!rd.integer (1, r.initial_k, 3, 1 << 20) ||
        !rd.integer (3, r.max_iterations, 1, 1 << 20) ||
        !rd.integer (4, r.max_k, 4, 1 << 30) ||
        !rd.integer (13, s.supervoxels.adjacency, 0, 1 << 20) ||
        !rd.integer (14, s.supervoxels.seed, 0, std::numeric_limits<long long>::max()))
      return false;
    const std::size_t positions[] = {2, 5, 6, 7, 8, 9, 10, 11, 12};
    for (std::size_t k = 0; k < 9; ++k)
      if (!rd.number (positions[k], v[k], positions[k] == 12))
        return false;
    r.damping = v[0];
    r.saturation = v[1];
    r.noise = v[2];
    r.c1 = v[3];
    r.c2 = v[4];
    r.epsilon = v[5];
    r.colour_weight = v[6];
    r.min_radius = v[7];
    r.max_radius = v[8];
    if (!rd.next ("local_edges") || !rd.expect ("local_edges", 1) ||
        !rd.integer (1, s.local_edges, 0, 1 << 20))
      return false;
    if (!rd.next ("ground") || !rd.expect ("ground", 6))
      return false;
    for (std::size_t k = 0; k < 4; ++k)
      if (!rd.number (k + 1, v[k]))
        return false;
    s.features.up = Eigen::Vector3d (v[0], v[1], v[2]).cast<float>();
    s.features.ground_cell = static_cast<float> (v[3]);
    if (!rd.integer (5, s.features.ground_reach, 0, 1 << 20))
      return false;
    if (!parseGroundEstimate (rd.word (6), s.features.ground_estimate))
      return rd.fail ("unknown ground estimate '" + rd.word (6) +
                      "' (lowest_in_block or opening)");
    std::size_t num_scales = 0;
    if (!rd.next ("feature_scales"))
      return false;
    if (rd.size() < 2 || rd.word (0) != "feature_scales")
      return rd.fail ("expected 'feature_scales N r1 .. rN'");
    if (!rd.integer (1, num_scales, 0, 64) ||
        !rd.expect ("feature_scales", num_scales + 1))
      return false;
    s.features.scales.clear();
    for (std::size_t k = 0; k < num_scales; ++k) {
      double scale = 0.0;
      if (!rd.number (k + 2, scale))
        return false;
      s.features.scales.push_back (static_cast<float> (scale));
    }
    if (!validFeatureScales (s.features.scales))
      return rd.fail ("feature scales must be positive, finite and ascending");
    if (!rd.next ("prior_sigma") || !rd.expect ("prior_sigma", 1) ||
        !rd.number (1, s.sigma))
      return false;
    if (!rd.next ("node_expansion") || !rd.expect ("node_expansion", 2))
      return false;
    if (!parseCrfNodeExpansion (rd.word (1), s.node_expansion))
      return rd.fail ("unknown node expansion '" + rd.word (1) +
                      "' (linear, spline or spline_products)");
    if (!rd.integer (2, s.spline_knots, 1, 64))
      return false;
    w.expansion = s.node_expansion;
    if (!rd.next ("node_model") || !rd.expect ("node_model", 4))
      return false;
    if (!parseCrfNodeModel (rd.word (1), s.node_model))
      return rd.fail ("unknown node model '" + rd.word (1) +
                      "' (logistic or boosted_trees)");
    if (!rd.integer (2, s.boost_rounds, 1, 10000) ||
        !rd.integer (3, s.boost_depth, 1, 32) || !rd.number (4, s.boost_eta))
      return false;
    if (!(s.boost_eta > 0.0 && s.boost_eta <= 1.0))
      return rd.fail ("the boosted trees' learning rate must be in (0, 1]");
    w.node_model = s.node_model;
    if (!rd.next ("belief_propagation") || !rd.expect ("belief_propagation", 3) ||
        !rd.number (1, s.bp_damping) || !rd.integer (2, s.bp_iterations, 1, 1 << 20) ||
        !rd.number (3, s.bp_tolerance))
      return false;
    std::size_t C = 0;
    if (!rd.next ("classes") || !rd.expect ("classes", 1) ||
        !rd.integer (1, C, 2, 1 << 16))
      return false;
    for (std::size_t k = 0; k < C; ++k) {
      std::uint32_t id = 0;
      if (!rd.next ("class") || !rd.expect ("class", 2) ||
          !rd.integer (1, id, 1, std::numeric_limits<std::uint32_t>::max()))
        return false;
      if (!ids.empty() && id <= ids.back())
        return rd.fail ("class ids must be unique and ascending");
      ids.push_back (id);
      names[id] = rd.word (2);
    }
    std::size_t D = 0;
    if (!rd.next ("features") || !rd.expect ("features", 1) ||
        !rd.integer (1, D, 1, 1 << 12))
      return false;
    w.mean.resize (static_cast<Eigen::Index> (D));
    w.scale.resize (static_cast<Eigen::Index> (D));
    for (std::size_t d = 0; d < D; ++d) {
      if (!rd.next ("feature") || !rd.expect ("feature", 3) ||
          !rd.number (2, w.mean (d)) || !rd.number (3, w.scale (d)))
        return false;
      if (!(w.scale (d) > 0.0))
        return rd.fail ("feature scale must be positive");
      w.feature_names.push_back (rd.word (1));
    }
    // The feature set must be one this build computes, in this order.
    SaliencyFeatureOptions options = s.features;
    options.colour =
        std::find (w.feature_names.begin(), w.feature_names.end(), "red") !=
        w.feature_names.end();
    options.intensity =
        std::find (w.feature_names.begin(), w.feature_names.end(), "intensity") !=
        w.feature_names.end();
    if (w.feature_names != crf::crfFeatureNames (options))
      return rd.fail (
          "the model's features are not the saliency feature set of this build "
          "(a model from another feature set?)");
    s.features.colour = options.colour;
    s.features.intensity = options.intensity;
    // The knots of the spline expansions: one line per feature, in the features' order,
    // at most spline_knots ascending values each.
    w.knots.assign (D, {});
    if (w.expansion != CrfNodeExpansion::Linear)
      for (std::size_t d = 0; d < D; ++d) {
        std::size_t K = 0;
        if (!rd.next ("knots"))
          return false;
        if (rd.size() < 3 || rd.word (0) != "knots" ||
            rd.word (1) != w.feature_names[d])
          return rd.fail ("expected 'knots " + w.feature_names[d] + " K t1 .. tK'");
        if (!rd.integer (2, K, 0, s.spline_knots) || !rd.expect ("knots", K + 2))
          return false;
        for (std::size_t k = 0; k < K; ++k) {
          double t = 0.0;
          if (!rd.number (k + 3, t))
            return false;
          if (!w.knots[d].empty() && !(t > w.knots[d].back()))
            return rd.fail ("knots must be strictly ascending");
          w.knots[d].push_back (t);
        }
      }
    const std::size_t Dn = crf::expandedSize (D, w.expansion, w.knots);
    const Eigen::Index rows = static_cast<Eigen::Index> (C),
                       cols = static_cast<Eigen::Index> (D + 1);
    const Eigen::Index node_cols = static_cast<Eigen::Index> (Dn + 1);
    if (w.node_model == CrfNodeModel::BoostedTrees) {
      // The boosters' log class probabilities are the node inputs, with identity
      // weights (not stored).
      for (int type = 0; type < 2; ++type) {
        const char* name = type == 0 ? "supervoxel" : "point";
        std::vector<char>& model = type == 0 ? w.boosters.supervoxel : w.boosters.point;
        if (!rd.next ("booster") || rd.size() < 3 || rd.word (0) != "booster" ||
            rd.word (1) != name)
          return rd.fail (std::string ("expected 'booster ") + name +
                          " <bytes> <checksum> <base64>'");
        if (type == 1 && rd.word (2) == "-" && rd.expect ("booster", 2))
          continue;
        std::size_t bytes = 0;
        if (!rd.expect ("booster", 4) || !rd.integer (2, bytes, 1, 1LL << 40))
          return false;
        if (!crf::decodeBase64 (rd.word (4), model) || model.size() != bytes ||
            checksum (model) != rd.word (3))
          return rd.fail (std::string ("the ") + name +
                          " booster is damaged (its size or checksum does not match)");
        std::string error;
        if (!crf::checkBooster (model, C, D, error))
          return rd.fail (std::string ("the ") + name + " booster: " + error);
      }
      if (w.boosters.point.empty() && s.mode != CrfMode::NodeOnly)
        return rd.fail ("a CRF needs the booster of the local points");
      Eigen::VectorXd theta = Eigen::VectorXd::Zero (rows * (rows + 1) * 2);
      crf::setIdentityNodeWeights (C, theta);
      w.node_s = Eigen::Map<const Eigen::MatrixXd> (theta.data(), rows, rows + 1);
      w.node_x = w.node_s;
    }
    else if (!readMatrix (rd, "node_supervoxel", rows, node_cols, w.node_s) ||
             !readMatrix (rd, "node_point", rows, node_cols, w.node_x))
      return false;
    if (!readMatrix (rd, "local_edge", rows, cols, w.local_edge) ||
        !readMatrix (rd, "regional_edge", rows, cols, w.regional_edge))
      return false;
    if (!rd.next ("edge_scale") || !rd.expect ("edge_scale", 1) ||
        !rd.number (1, w.edge_scale))
      return false;
    if (!(w.edge_scale > 0.0))
      return rd.fail ("the edge scale must be positive");
    if (!rd.next ("end") || !rd.expect ("end", 0))
      return false;
    return true;
  };
  if (!parse()) {
    PCL_ERROR ("[pcl_ext::MultiscaleCrfModel::loadModel] %s; model not loaded.\n",
               rd.error().c_str());
    return false;
  }
  if (!checkCrfSettings (s, "MultiscaleCrfModel::loadModel"))
    return false;
  settings_ = s;
  names_ = names;
  class_ids_ = ids;
  *weights_ = std::move (w);
  trained_ = true;
  return true;
}
} // namespace pcl_ext
