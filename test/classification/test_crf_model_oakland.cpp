/*
 * Lim & Suter's three models on real data: Oakland 3-D (Munoz et al.), trained on
 * part3_am and part3_an, evaluated on the other part3 chunks with the coarse classes of
 * classes.txt. The measured tables and the cross-validation behind the defaults are in
 * docs/lim_suter.md.
 */
#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/point_table.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace {
const std::string kDir = std::string (PCL_EXT_SHARED_DATA_DIR) + "/oakland3d";

bool
load (const std::string& chunk,
      const pcl_ext::io::ClassMapping& mapping,
      pcl_ext::CrfInput& in,
      std::vector<std::uint32_t>& labels)
{
  pcl_ext::io::PointTable t;
  pcl_ext::io::loadOaklandFile (kDir + "/oakland_part3_" + chunk + ".xyz_label_conf",
                                t);
  const Eigen::Vector3d origin = pcl_ext::io::computeLocalOrigin (t);
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : t.xyz)
    xyz->push_back (pcl::PointXYZ (static_cast<float> (p.x() - origin.x()),
                                   static_cast<float> (p.y() - origin.y()),
                                   static_cast<float> (p.z() - origin.z())));
  in.xyz = xyz;
  labels = t.label;
  mapping.apply (labels);
  return !labels.empty();
}

struct Scores {
  double macro[3] = {0, 0, 0}, oa[3] = {0, 0, 0};
};

/** Trains the three models on am + an with the node inputs \a expansion (K = 2 hinges
 * for the splines) and the super-voxel radius bound \a min_radius, and scores them on
 * the validation chunks, printing the table. */
void
threeModels (pcl_ext::CrfNodeExpansion expansion, double min_radius, Scores& out)
{
  pcl_ext::io::ClassMapping mapping;
  mapping.load (kDir + "/classes.txt");
  std::vector<pcl_ext::CrfInput> train (2);
  std::vector<std::vector<std::uint32_t>> train_labels (2);
  ASSERT_TRUE (load ("am", mapping, train[0], train_labels[0]));
  ASSERT_TRUE (load ("an", mapping, train[1], train_labels[1]));
  const char* chunks[] = {"aj", "ak", "al", "ao", "ap"};
  std::vector<pcl_ext::CrfInput> test (5);
  std::vector<std::vector<std::uint32_t>> truth (5);
  for (int c = 0; c < 5; ++c)
    ASSERT_TRUE (load (chunks[c], mapping, test[c], truth[c]));
  int k = 0;
  for (const pcl_ext::CrfMode mode : {pcl_ext::CrfMode::NodeOnly,
                                      pcl_ext::CrfMode::LocalCrf,
                                      pcl_ext::CrfMode::MultiscaleCrf}) {
    pcl_ext::MultiscaleCrfModel model;
    pcl_ext::CrfSettings model_settings = model.getSettings();
    model_settings.mode = mode;
    model_settings.node_expansion = expansion;
    model_settings.spline_knots = 2;
    model_settings.supervoxels.radius.min_radius = min_radius;
    model.setSettings (model_settings);
    model.setClassNames (mapping.names());
    ASSERT_TRUE (model.train (train, train_labels));
    const double train_s =
        (model.getStatistics().supervoxels_ms + model.getStatistics().features_ms +
         model.getStatistics().training_ms) /
        1000.0;
    std::vector<std::uint32_t> all_pred, all_truth;
    for (int c = 0; c < 5; ++c) {
      std::vector<std::uint32_t> pred;
      Eigen::MatrixXf prob;
      ASSERT_TRUE (model.classify (test[c], pred, prob));
      all_pred.insert (all_pred.end(), pred.begin(), pred.end());
      all_truth.insert (all_truth.end(), truth[c].begin(), truth[c].end());
    }
    pcl_ext::ClassificationMetrics m;
    ASSERT_TRUE (
        pcl_ext::evaluateClassification (all_pred, all_truth, m, mapping.names()));
    std::printf ("Oakland %-4s %-6s min radius %g (training %.1f s):",
                 pcl_ext::crfModeName (mode),
                 pcl_ext::crfNodeExpansionName (expansion),
                 min_radius,
                 train_s);
    for (const auto& c : m.classes)
      std::printf (" %s F1 %.3f |", c.name.c_str(), c.f1);
    std::printf (
        " macro F1 %.4f, overall accuracy %.4f (BP on the last chunk: %d sweeps%s)\n",
        m.macro_f1,
        m.overall_accuracy,
        model.getStatistics().iterations,
        model.getStatistics().converged ? ", converged" : ", not converged");
    std::fflush (stdout);
    out.macro[k] = m.macro_f1;
    out.oa[k] = m.overall_accuracy;
    ++k;
  }
}
} // namespace

TEST (MultiscaleCrfOakland, ThreeModelsOnTheValidationChunks)
{
  if (!std::ifstream (kDir + "/classes.txt").good())
    GTEST_SKIP() << "Oakland 3-D data not found in " << kDir;
  // The defaults: the paper's linear node model, super-voxels of at least 0.5 m radius.
  Scores s;
  threeModels (pcl_ext::CrfNodeExpansion::Linear,
               pcl_ext::defaultCrfSupervoxelParameters().radius.min_radius,
               s);
  const double* macro = s.macro;
  const double* oa = s.oa;
  // No parameter was chosen on the validation chunks: the radius bound (0.5 m) was
  // chosen by cross-validation between am and an (train on one, test on the other) and
  // then checked here once; the edge scale beta is fitted on the training chunks by
  // train(). The goals: mCRF overall accuracy >= 0.95 and macro F1 >= 0.78, and the
  // mCRF at least 3 points of macro F1 above node-only.
  EXPECT_GE (oa[2], 0.95);
  EXPECT_GE (macro[2], 0.78);
  EXPECT_GE (macro[2] - macro[0], 0.03);
  // The node-only model and the local CRF hold their measured level.
  EXPECT_GE (oa[0], 0.95);
  EXPECT_GE (macro[0], 0.75);
  EXPECT_GE (oa[1], 0.95);
  EXPECT_GE (macro[1], 0.75);
  // The CRFs must not undo their own node potentials (the stacked training of the edges
  // is what keeps them).
  EXPECT_GE (oa[2], oa[0]);
}

// The same goals with the spline node model (K = 2 hinges per feature, chosen by
// cross-validation between am and an) and the paper's super-voxels (no radius bound).
// Not met on the validation chunks (what the model gains between am and an does not
// carry over to the other chunks), hence disabled: the defaults above meet them. Run
// with
// --gtest_also_run_disabled_tests; docs/lim_suter.md has the figures.
TEST (MultiscaleCrfOakland, DISABLED_SplineNodeModelMeetsTheGoals)
{
  if (!std::ifstream (kDir + "/classes.txt").good())
    GTEST_SKIP() << "Oakland 3-D data not found in " << kDir;
  Scores s;
  threeModels (pcl_ext::CrfNodeExpansion::Spline, 0.0, s);
  EXPECT_GE (s.oa[2], 0.95);
  EXPECT_GE (s.macro[2], 0.78);
  EXPECT_GE (s.macro[2] - s.macro[0], 0.03);
}
