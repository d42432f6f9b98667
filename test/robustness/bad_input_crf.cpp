/*
 * The row of the bad-input matrix for the multiscale CRF classification, and the model
 * files it refuses (a folder, a missing file).
 */
#include "bad_input.h"

#include <pcl_ext/classification/multiscale_crf_classification.h>
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <memory>
#include <string>

namespace pcl_ext {
namespace test {
namespace bad_input {
namespace {
/** A trained CRF model for the classification subject (a small generated street). */
const MultiscaleCrfClassification<Point>&
trainedCrf ()
{
  static const auto crf = [] {
    simulation::SceneParameters p;
    p.seed = 3;
    p.points = 6000;
    p.threads = 1;
    simulation::SyntheticScene scene;
    EXPECT_TRUE (simulation::generateScene ("street", p, scene));
    Cloud::Ptr cloud (new Cloud);
    std::vector<std::uint32_t> labels;
    for (const auto& q : scene.cloud) {
      cloud->push_back (Point (q.x, q.y, q.z));
      labels.push_back (q.label);
    }
    auto c = std::make_unique<MultiscaleCrfClassification<Point>>();
    c->setNumberOfThreads (2);
    // The subject is classification's input handling, not the model's quality: a few
    // optimiser steps and a fixed edge scale (no search over BP runs) give a valid
    // model in a fraction of the time, paid by every case (ctest runs each case in its
    // own process).
    pcl_ext::CrfSettings settings = c->getModel().getSettings();
    settings.max_training_iterations = 10;
    c->getModel().setSettings (settings);
    c->setEdgeScale (1.0);
    EXPECT_TRUE (c->train ({cloud}, {labels}));
    return c;
  }();
  return *crf;
}
} // namespace

void
addCrfSubjects (std::vector<Subject>& s)
{
  // The parameters come from the trained model: no parameter inputs. The model is
  // trained before stderr is captured: its messages are not the subject's.
  s.push_back (
      {"MultiscaleCrfClassification",
       without (kCloudInputs,
                {Bad::NegativeParameter, Bad::ZeroParameter, Bad::NaNParameter}),
       {{Bad::Collinear, Expect::Computed}},
       [] (const Input& in) {
         MultiscaleCrfClassification<Point> crf = trainedCrf();
         crf.setInputCloud (in.cloud);
         if (in.indices)
           crf.setIndices (in.indices);
         pcl::PointCloud<pcl::Label> labels;
         crf.classify (labels);
         return perPoint (labels, [] (const pcl::Label& l) { return l.label == 0; });
       },
       [] { trainedCrf(); }});
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext

TEST (ModelFile, FolderAndMissingFileAreRefused)
{
  char pattern[] = "/tmp/pcl_ext_model_folder_XXXXXX";
  ASSERT_NE (::mkdtemp (pattern), nullptr);
  const std::string folder = pattern;
  pcl_ext::MultiscaleCrfModel model;
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE (model.loadModel (folder));
  EXPECT_FALSE (model.loadModel (folder + "/missing.txt"));
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_NE (log.find ("not a regular file"), std::string::npos) << log;
  EXPECT_NE (log.find ("missing.txt is missing"), std::string::npos) << log;
  EXPECT_FALSE (model.isTrained());
  ::rmdir (folder.c_str());
}
