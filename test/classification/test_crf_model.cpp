/*
 * Tests of MultiscaleCrfModel, the multi-scale CRF (Lim & Suter 2008, section 3.2)
 * without the point type, on generated street scenes: training, inference, model files,
 * bad input.
 */
#include "crf_test_scenes.h"

#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/evaluation/classification_metrics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

using pcl_ext::CrfMode;
using pcl_ext::MultiscaleCrfModel;

namespace {
constexpr std::size_t kPoints = 40000;

struct Street {
  pcl_ext::CrfInput input;
  std::vector<std::uint32_t> labels;
};

const Street&
street (std::uint64_t seed)
{
  static std::map<std::uint64_t, Street> cache;
  auto it = cache.find (seed);
  if (it == cache.end()) {
    Street s;
    crf_test::streetScene (seed, kPoints, s.input, s.labels);
    it = cache.emplace (seed, std::move (s)).first;
  }
  return it->second;
}

/** A model trained on street seed 1, one per mode, trained once. */
MultiscaleCrfModel&
trained (CrfMode mode)
{
  static std::map<CrfMode, MultiscaleCrfModel> models;
  auto it = models.find (mode);
  if (it == models.end()) {
    MultiscaleCrfModel m;
    pcl_ext::CrfSettings m_settings = m.getSettings();
    m_settings.mode = mode;
    m.setSettings (m_settings);
    EXPECT_TRUE (m.train ({street (1).input}, {street (1).labels}));
    it = models.emplace (mode, m).first;
  }
  return it->second;
}

double
accuracy (MultiscaleCrfModel& m,
          const Street& s,
          pcl_ext::ClassificationMetrics* out = nullptr)
{
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf prob;
  if (!m.classify (s.input, labels, prob))
    return 0.0;
  pcl_ext::ClassificationMetrics metrics;
  pcl_ext::evaluateClassification (labels, s.labels, metrics);
  if (out)
    *out = metrics;
  return metrics.overall_accuracy;
}

std::string
tempPath (const char* name)
{
  return std::string (::testing::TempDir()) + name;
}
} // namespace

TEST (MultiscaleCrf, StreetTrainOnOneSeedTestOnAnother)
{
  for (const CrfMode mode :
       {CrfMode::NodeOnly, CrfMode::LocalCrf, CrfMode::MultiscaleCrf}) {
    MultiscaleCrfModel& m = trained (mode);
    ASSERT_TRUE (m.isTrained());
    pcl_ext::ClassificationMetrics metrics;
    const double oa = accuracy (m, street (2), &metrics);
    const auto& st = m.getStatistics();
    std::printf ("street %-4s: overall accuracy %.4f, macro F1 %.4f (%zu super-voxels, "
                 "BP %d sweeps%s)\n",
                 pcl_ext::crfModeName (mode),
                 oa,
                 metrics.macro_f1,
                 st.supervoxels,
                 st.iterations,
                 st.converged ? ", converged" : "");
    if (mode == CrfMode::MultiscaleCrf) {
      EXPECT_GE (oa, 0.95);
      EXPECT_TRUE (st.converged);
    }
    else
      EXPECT_GE (oa, 0.85);
  }
}

TEST (MultiscaleCrf, ProbabilitiesFollowEquation11)
{
  // One draw of the super-voxels: eq. 11 on its marginals.
  MultiscaleCrfModel m = trained (CrfMode::MultiscaleCrf);
  pcl_ext::CrfSettings one = m.getSettings();
  one.draws = 1;
  m.setSettings (one);
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf prob;
  ASSERT_TRUE (m.classify (street (2).input, labels, prob));
  ASSERT_EQ (prob.rows(), static_cast<Eigen::Index> (labels.size()));
  ASSERT_EQ (prob.cols(), 5);
  const auto& svs = m.getSupervoxels();
  const Eigen::MatrixXf& marg = m.getSupervoxelProbabilities();
  for (std::size_t i = 0; i < labels.size(); i += 97) {
    EXPECT_NEAR (prob.row (i).sum(), 1.f, 1e-4f);
    Eigen::VectorXd logp = Eigen::VectorXd::Zero (5);
    for (std::size_t k = svs.membership_offsets[i]; k < svs.membership_offsets[i + 1];
         ++k)
      logp += marg.row (svs.membership[k])
                  .transpose()
                  .cast<double>()
                  .array()
                  .max (1e-30)
                  .log()
                  .matrix();
    Eigen::Index best;
    logp.maxCoeff (&best);
    EXPECT_EQ (labels[i], m.getClassLabels()[best]);
  }
}

TEST (MultiscaleCrf, DrawsAverageTheProbabilitiesOfOneDrawPerSeed)
{
  // Three draws: each point's probabilities are the mean of those of three one-draw
  // classifications with seeds s, s + 1, s + 2, and its class the most probable.
  const MultiscaleCrfModel& trained_model = trained (CrfMode::MultiscaleCrf);
  MultiscaleCrfModel m = trained_model;
  pcl_ext::CrfSettings s = m.getSettings();
  s.draws = 3;
  m.setSettings (s);
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf prob;
  ASSERT_TRUE (m.classify (street (2).input, labels, prob));
  ASSERT_EQ (m.getDrawSupervoxels().size(), 3u);
  Eigen::MatrixXf mean = Eigen::MatrixXf::Zero (prob.rows(), prob.cols());
  std::vector<std::vector<std::uint32_t>> single (3);
  for (int d = 0; d < 3; ++d) {
    MultiscaleCrfModel one = trained_model;
    pcl_ext::CrfSettings o = s;
    o.draws = 1;
    o.supervoxels.seed = s.supervoxels.seed + static_cast<std::uint64_t> (d);
    one.setSettings (o);
    Eigen::MatrixXf p;
    ASSERT_TRUE (one.classify (street (2).input, single[d], p));
    mean += p / 3.f;
    // The draws differ: their super-voxels do.
    EXPECT_EQ (one.getSupervoxels().size(), m.getDrawSupervoxels()[d].size());
  }
  EXPECT_NE (single[0], single[1]);
  EXPECT_LT ((prob - mean).cwiseAbs().maxCoeff(), 1e-5f);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    Eigen::Index best;
    prob.row (static_cast<Eigen::Index> (i)).maxCoeff (&best);
    EXPECT_EQ (labels[i], m.getClassLabels()[best]);
    changed += labels[i] != single[0][i];
  }
  EXPECT_GT (changed, 0u);
  // The averaged draws are at least as accurate as the first draw alone.
  pcl_ext::ClassificationMetrics averaged, first;
  pcl_ext::evaluateClassification (labels, street (2).labels, averaged);
  pcl_ext::evaluateClassification (single[0], street (2).labels, first);
  EXPECT_GE (averaged.overall_accuracy, first.overall_accuracy - 0.002);
}

TEST (MultiscaleCrf, DeterministicForAnyThreadCount)
{
  MultiscaleCrfModel a, b;
  pcl_ext::CrfSettings a_settings = a.getSettings();
  a_settings.threads = 1;
  a.setSettings (a_settings);
  pcl_ext::CrfSettings b_settings = b.getSettings();
  b_settings.threads = 2;
  b.setSettings (b_settings);
  ASSERT_TRUE (a.train ({street (1).input}, {street (1).labels}));
  ASSERT_TRUE (b.train ({street (1).input}, {street (1).labels}));
  EXPECT_EQ (a.toText(), b.toText());
  std::vector<std::uint32_t> la, lb;
  Eigen::MatrixXf pa, pb;
  ASSERT_TRUE (a.classify (street (2).input, la, pa));
  ASSERT_TRUE (b.classify (street (2).input, lb, pb));
  EXPECT_EQ (la, lb);
  EXPECT_TRUE (pa == pb);
}

TEST (MultiscaleCrf, SaveAndLoadGiveTheSameLabels)
{
  MultiscaleCrfModel& m = trained (CrfMode::MultiscaleCrf);
  const std::string path = tempPath ("crf_model.txt");
  ASSERT_TRUE (m.saveModel (path));
  MultiscaleCrfModel loaded;
  ASSERT_TRUE (loaded.loadModel (path));
  EXPECT_EQ (loaded.toText(), m.toText());
  std::vector<std::uint32_t> la, lb;
  Eigen::MatrixXf pa, pb;
  ASSERT_TRUE (m.classify (street (2).input, la, pa));
  ASSERT_TRUE (loaded.classify (street (2).input, lb, pb));
  EXPECT_EQ (la, lb);
}

TEST (MultiscaleCrf, MalformedModelFilesAreRefused)
{
  const std::string good = trained (CrfMode::MultiscaleCrf).toText();
  auto replaced = [&] (const std::string& from, const std::string& to) {
    std::string t = good;
    const auto at = t.find (from);
    EXPECT_NE (at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace (at, from.size(), to);
  };
  const std::string cols =
      std::to_string (trained (CrfMode::MultiscaleCrf).getFeatureNames().size() + 1);
  const std::vector<std::pair<const char*, std::string>> cases = {
      {"empty", ""},
      {"not a model", "hello world\n"},
      {"other version", replaced ("pcl_ext_crf_model 5", "pcl_ext_crf_model 4")},
      {"unknown ground estimate", replaced (" lowest_in_block\n", " lowest\n")},
      {"no ground estimate", replaced (" lowest_in_block\n", "\n")},
      {"unknown mode", replaced ("mode mcrf", "mode best")},
      {"truncated", good.substr (0, good.size() / 2)},
      {"no end", replaced ("end\n", "")},
      {"bad number", replaced ("prior_sigma 1", "prior_sigma one")},
      {"negative sigma", replaced ("prior_sigma 1", "prior_sigma -1")},
      {"other feature set", replaced ("feature clutterness", "feature spin_image")},
      {"too few classes", replaced ("classes 5", "classes 4")},
      {"wrong matrix size", replaced ("weights local_edge 5", "weights local_edge 4")},
      {"NaN weight",
       replaced ("weights regional_edge 5 " + cols + "\n",
                 "weights regional_edge 5 " + cols + "\nnan ")},
      // The feature set follows the scales: a single-scale model claiming scales is
      // refused.
      {"other feature scales", replaced ("feature_scales 0", "feature_scales 1 0.5")},
      {"negative scale", replaced ("feature_scales 0", "feature_scales 1 -1")},
      {"scale count", replaced ("feature_scales 0", "feature_scales 1")},
      {"no scales line", replaced ("feature_scales 0\n", "")},
      {"no expansion line", replaced ("node_expansion linear 2\n", "")},
      {"no edge scale", replaced ("edge_scale ", "edge_scales ")},
      {"negative edge scale", replaced ("edge_scale ", "edge_scale -")},
      {"no draws", replaced (" 4 1 3\nlocal_edges", " 4 1 0\nlocal_edges")},
      {"too many draws", replaced (" 4 1 3\nlocal_edges", " 4 1 65\nlocal_edges")},
  };
  for (const auto& [name, text] : cases) {
    MultiscaleCrfModel m;
    EXPECT_FALSE (m.parseModel (text, name)) << name;
    EXPECT_FALSE (m.isTrained()) << name;
  }
  // A model written before the draws (14 values on the super-voxels line) has one.
  MultiscaleCrfModel older;
  ASSERT_TRUE (older.parseModel (replaced (" 4 1 3\nlocal_edges", " 4 1\nlocal_edges"),
                                 "older"));
  EXPECT_EQ (older.getSettings().draws, 1);
  EXPECT_EQ (trained (CrfMode::MultiscaleCrf).getSettings().draws, 3);
  MultiscaleCrfModel m;
  EXPECT_FALSE (m.loadModel (tempPath ("no_such_model.txt")));
  // A good model stays when a bad one is loaded over it.
  MultiscaleCrfModel kept;
  ASSERT_TRUE (kept.parseModel (good, "good"));
  EXPECT_FALSE (kept.parseModel (cases[4].second, "truncated"));
  EXPECT_EQ (kept.toText(), good);
}

TEST (MultiscaleCrf, NodeExpansionsAreStoredAndRefusedWhenInconsistent)
{
  // The spline expansion with products (inputs of the logistic node model): a knots
  // line per feature, node weights over the expanded inputs, edge weights over the
  // features alone.
  MultiscaleCrfModel m;
  pcl_ext::CrfSettings m_settings = m.getSettings();
  m_settings.mode = CrfMode::MultiscaleCrf;
  m_settings.node_model = pcl_ext::CrfNodeModel::Logistic;
  m_settings.node_expansion = pcl_ext::CrfNodeExpansion::SplineProducts;
  m_settings.spline_knots = 3;
  m.setSettings (m_settings);
  ASSERT_TRUE (m.train ({street (1).input}, {street (1).labels}));
  EXPECT_GE (accuracy (m, street (2)), 0.95);
  const std::string good = m.toText();
  const std::size_t D = m.getFeatureNames().size();
  std::size_t knots = 0, lines = 0;
  for (std::size_t at = good.find ("\nknots "); at != std::string::npos;
       at = good.find ("\nknots ", at + 1)) {
    std::istringstream line (good.substr (at + 7, good.find ('\n', at + 1) - at - 7));
    std::string name;
    std::size_t n = 0;
    line >> name >> n;
    EXPECT_EQ (name, m.getFeatureNames()[lines]);
    EXPECT_LE (n, 3u);
    double previous = -6.0, t = 0.0;
    for (std::size_t k = 0; k < n && line >> t; ++k) {
      EXPECT_GT (t, previous) << name;
      EXPECT_LT (t, 5.0) << name;
      previous = t;
    }
    knots += n;
    ++lines;
  }
  EXPECT_EQ (lines, D);
  EXPECT_GT (knots, D) << "most features take more than two values";
  const std::string node_cols = std::to_string (D + knots + D * (D - 1) / 2 + 1);
  const std::string edge_cols = std::to_string (D + 1);
  EXPECT_NE (good.find ("weights node_supervoxel 5 " + node_cols + "\n"),
             std::string::npos);
  EXPECT_NE (good.find ("weights regional_edge 5 " + edge_cols + "\n"),
             std::string::npos);
  MultiscaleCrfModel loaded;
  ASSERT_TRUE (loaded.parseModel (good, "spline model"));
  EXPECT_EQ (loaded.toText(), good);
  std::vector<std::uint32_t> la, lb;
  Eigen::MatrixXf pa, pb;
  ASSERT_TRUE (m.classify (street (2).input, la, pa));
  ASSERT_TRUE (loaded.classify (street (2).input, lb, pb));
  EXPECT_EQ (la, lb);

  auto replaced = [&] (const std::string& from, const std::string& to) {
    std::string t = good;
    const auto at = t.find (from);
    EXPECT_NE (at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace (at, from.size(), to);
  };
  const std::string first = good.substr (good.find ("knots clutterness"));
  const std::string first_line = first.substr (0, first.find ('\n') + 1);
  const std::vector<std::pair<const char*, std::string>> cases = {
      {"unknown expansion",
       replaced ("node_expansion spline_products", "node_expansion cubic")},
      {"no knots", replaced (first_line, "")},
      {"more knots than K",
       replaced ("node_expansion spline_products 3",
                 "node_expansion spline_products 1")},
      {"knots descending", replaced (first_line, "knots clutterness 2 1 0\n")},
      {"knots of another feature", replaced (first_line, "knots height 1 0\n")},
      {"NaN knot", replaced (first_line, "knots clutterness 1 nan\n")},
      // The linear model has fewer node inputs than these weights.
      {"linear with spline weights",
       replaced ("node_expansion spline_products 3", "node_expansion linear 3")},
  };
  for (const auto& [name, text] : cases) {
    MultiscaleCrfModel bad;
    EXPECT_FALSE (bad.parseModel (text, name)) << name;
    EXPECT_FALSE (bad.isTrained()) << name;
  }
  MultiscaleCrfModel bad_knots;
  pcl_ext::CrfSettings bad_knots_settings = bad_knots.getSettings();
  bad_knots_settings.spline_knots = 0;
  bad_knots.setSettings (bad_knots_settings);
  EXPECT_FALSE (bad_knots.train ({street (1).input}, {street (1).labels}));
}

TEST (MultiscaleCrf, BadTrainingInput)
{
  const Street& s = street (1);
  MultiscaleCrfModel m;
  EXPECT_FALSE (m.train ({}, {}));
  EXPECT_FALSE (m.train ({s.input}, {}));
  EXPECT_FALSE (
      m.train ({s.input}, {std::vector<std::uint32_t> (10, 1)})); // size mismatch
  EXPECT_FALSE (m.train (
      {s.input}, {std::vector<std::uint32_t> (s.labels.size(), 0)})); // unlabelled
  EXPECT_FALSE (m.train (
      {s.input}, {std::vector<std::uint32_t> (s.labels.size(), 3)})); // one class
  MultiscaleCrfModel named;
  named.setClassNames (
      {{1, "vegetation"}, {2, "trunk"}, {9, "water"}}); // water has no points
  EXPECT_FALSE (named.train ({s.input}, {s.labels}));
  pcl_ext::CrfInput empty;
  empty.xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  EXPECT_FALSE (m.train ({empty}, {{}}));
  MultiscaleCrfModel bad_sigma;
  pcl_ext::CrfSettings bad_sigma_settings = bad_sigma.getSettings();
  bad_sigma_settings.sigma = -1.0;
  bad_sigma.setSettings (bad_sigma_settings);
  EXPECT_FALSE (bad_sigma.train ({s.input}, {s.labels}));
  EXPECT_FALSE (m.isTrained());
  EXPECT_FALSE (m.saveModel (tempPath ("untrained.txt")));
  std::ifstream none (tempPath ("untrained.txt"));
  EXPECT_FALSE (none.good()) << "no partial model file";
}

TEST (MultiscaleCrf, BadClassificationInput)
{
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf prob;
  MultiscaleCrfModel untrained;
  EXPECT_FALSE (untrained.classify (street (2).input, labels, prob));
  EXPECT_TRUE (labels.empty());
  MultiscaleCrfModel& m = trained (CrfMode::MultiscaleCrf);
  pcl_ext::CrfInput no_colour = street (2).input;
  no_colour.colours.clear(); // the model was trained with colour
  EXPECT_FALSE (m.classify (no_colour, labels, prob));
  EXPECT_TRUE (labels.empty());
  pcl_ext::CrfInput empty;
  EXPECT_FALSE (m.classify (empty, labels, prob));
  // NaN points get label 0; the others are classified.
  pcl_ext::CrfInput with_nan = street (2).input;
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*with_nan.xyz);
  (*xyz)[10].x = std::numeric_limits<float>::quiet_NaN();
  with_nan.xyz = xyz;
  ASSERT_TRUE (m.classify (with_nan, labels, prob));
  EXPECT_EQ (labels[10], 0u);
  EXPECT_NE (labels[11], 0u);
}

TEST (MultiscaleCrf, PaperTrainingFitsEveryWeightAtOnceWithoutAnEdgeScale)
{
  // Eq. 9: the pseudo-likelihood of the model inference runs, every weight at once
  // given the neighbours' true labels; the edges' weight at inference stays 1.
  MultiscaleCrfModel paper;
  pcl_ext::CrfSettings s = paper.getSettings();
  s.training = pcl_ext::CrfTraining::PseudoLikelihood;
  paper.setSettings (s);
  ASSERT_TRUE (paper.train ({street (1).input}, {street (1).labels}));
  EXPECT_NE (paper.toText().find ("\nedge_scale 1\n"), std::string::npos);
  const std::string staged = trained (CrfMode::MultiscaleCrf).toText();
  EXPECT_NE (paper.toText(), staged);
  pcl_ext::ClassificationMetrics metrics;
  const double oa = accuracy (paper, street (2), &metrics);
  std::printf ("street mcrf, paper's training: overall accuracy %.4f, macro F1 %.4f\n",
               oa,
               metrics.macro_f1);
  EXPECT_GE (oa, 0.95);
  // Boosted trees are not the paper's node weights.
  s.node_model = pcl_ext::CrfNodeModel::BoostedTrees;
  EXPECT_FALSE (pcl_ext::checkCrfSettings (s, "test"));
  pcl_ext::CrfTraining t;
  EXPECT_TRUE (pcl_ext::parseCrfTraining ("pseudo_likelihood", t));
  EXPECT_EQ (t, pcl_ext::CrfTraining::PseudoLikelihood);
  EXPECT_STREQ (pcl_ext::crfTrainingName (t), "pseudo_likelihood");
  EXPECT_FALSE (pcl_ext::parseCrfTraining ("joint", t));
}

// Both node models: the paper's logistic regression (the default) and the boosted
// trees, each the same model for one and two threads, and the boosted trees' file
// refused when its boosters are damaged or missing.
TEST (MultiscaleCrf, NodeModels)
{
  EXPECT_EQ (pcl_ext::CrfSettings().node_model, pcl_ext::CrfNodeModel::Logistic);
  std::string good;
  for (const auto node_model :
       {pcl_ext::CrfNodeModel::Logistic, pcl_ext::CrfNodeModel::BoostedTrees}) {
    SCOPED_TRACE (pcl_ext::crfNodeModelName (node_model));
    MultiscaleCrfModel one, two;
    pcl_ext::CrfSettings settings;
    settings.node_model = node_model;
    settings.threads = 1;
    one.setSettings (settings);
    settings.threads = 2;
    two.setSettings (settings);
    ASSERT_TRUE (one.train ({street (1).input}, {street (1).labels}));
    ASSERT_TRUE (two.train ({street (1).input}, {street (1).labels}));
    EXPECT_EQ (one.toText(), two.toText());
    pcl_ext::ClassificationMetrics metrics;
    EXPECT_GE (accuracy (one, street (2), &metrics), 0.95);
    std::printf ("street mcrf, %s nodes: overall accuracy %.4f, macro F1 %.4f\n",
                 pcl_ext::crfNodeModelName (node_model),
                 metrics.overall_accuracy,
                 metrics.macro_f1);
    std::vector<std::uint32_t> la, lb;
    Eigen::MatrixXf pa, pb;
    ASSERT_TRUE (one.classify (street (2).input, la, pa));
    ASSERT_TRUE (two.classify (street (2).input, lb, pb));
    EXPECT_EQ (la, lb);
    MultiscaleCrfModel loaded;
    ASSERT_TRUE (loaded.parseModel (one.toText(), "round trip"));
    EXPECT_EQ (loaded.getSettings().node_model, node_model);
    EXPECT_EQ (loaded.toText(), one.toText());
    good = one.toText();
  }
  ASSERT_NE (good.find ("node_model boosted_trees"), std::string::npos);
  auto replaced = [&] (const std::string& from, const std::string& to) {
    std::string t = good;
    const auto at = t.find (from);
    EXPECT_NE (at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace (at, from.size(), to);
  };
  const auto point = good.find ("booster point ");
  ASSERT_NE (point, std::string::npos);
  std::string cut = good;
  cut.erase (point + 14 + 40, 8); // 8 base64 characters (6 bytes) gone
  const std::vector<std::pair<const char*, std::string>> cases = {
      {"logistic without weights",
       replaced ("node_model boosted_trees", "node_model logistic")},
      {"unknown node model",
       replaced ("node_model boosted_trees", "node_model forest")},
      {"no point booster", replaced ("booster point ", "booster point - ")},
      {"not base64", replaced ("booster supervoxel ", "booster supervoxel *")},
      {"booster cut short", cut},
      {"boosters swapped", replaced ("booster supervoxel ", "booster point ")},
  };
  for (const auto& [name, text] : cases) {
    MultiscaleCrfModel m;
    EXPECT_FALSE (m.parseModel (text, name)) << name;
    EXPECT_FALSE (m.isTrained()) << name;
  }
}

// The multi-scale features with the neighbourhood means and boosted trees, trained on
// two clouds (the node potentials of the edge training cross-fitted between them): the
// same model and labels for one and two threads.
TEST (MultiscaleCrf, MultiScaleBoostedDeterministicForAnyThreadCount)
{
  MultiscaleCrfModel one, two;
  pcl_ext::CrfSettings settings;
  settings.node_model = pcl_ext::CrfNodeModel::BoostedTrees;
  settings.features.scales = pcl_ext::defaultFeatureScales();
  settings.boost_rounds = 50;
  settings.threads = 1;
  one.setSettings (settings);
  settings.threads = 2;
  two.setSettings (settings);
  ASSERT_TRUE (one.train ({street (1).input, street (3).input},
                          {street (1).labels, street (3).labels}));
  ASSERT_TRUE (two.train ({street (1).input, street (3).input},
                          {street (1).labels, street (3).labels}));
  EXPECT_EQ (one.toText(), two.toText());
  const auto names = one.getFeatureNames();
  for (const char* name :
       {"dimension@2", "neighbours_height", "neighbours_linearity@0.5"})
    EXPECT_NE (std::find (names.begin(), names.end(), name), names.end()) << name;
  std::vector<std::uint32_t> la, lb;
  Eigen::MatrixXf pa, pb;
  ASSERT_TRUE (one.classify (street (2).input, la, pa));
  ASSERT_TRUE (two.classify (street (2).input, lb, pb));
  EXPECT_EQ (la, lb);
  EXPECT_TRUE (pa == pb);
  pcl_ext::ClassificationMetrics metrics;
  EXPECT_GE (accuracy (one, street (2), &metrics), 0.95);
  MultiscaleCrfModel loaded;
  ASSERT_TRUE (loaded.parseModel (one.toText(), "round trip"));
  EXPECT_EQ (loaded.getFeatureNames(), names);
}
