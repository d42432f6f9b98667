/*
 * Benchmark of Lim & Suter's pipeline on a generated street scene: super-voxels,
 * features, inference (the paper's data set 2 has 158,922 points), and optionally
 * Oakland training.
 */
#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/point_table.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/scene_crf_input.h>

#include <cstdio>

namespace {
bool
street (std::uint64_t seed,
        std::size_t points,
        pcl_ext::CrfInput& in,
        std::vector<std::uint32_t>& labels)
{
  pcl_ext::simulation::SceneParameters p;
  p.seed = seed;
  p.points = points;
  pcl_ext::simulation::SyntheticScene scene;
  if (!pcl_ext::simulation::generateScene ("street", p, scene))
    return false;
  in = pcl_ext::apps::makeCrfInput (scene, labels);
  return true;
}

void
printStats (const char* what, const pcl_ext::CrfStatistics& s)
{
  std::printf (
      "%-10s super-voxels %8.1f ms | features %8.1f ms | training %8.1f ms | inference "
      "%8.1f ms | total %8.1f ms  (%zu points, %zu super-voxels, %zu local points)\n",
      what,
      s.supervoxels_ms,
      s.features_ms,
      s.training_ms,
      s.inference_ms,
      s.supervoxels_ms + s.features_ms + s.training_ms + s.inference_ms,
      s.points,
      s.supervoxels,
      s.local_points);
}
} // namespace

int
main (int argc, char** argv)
{
  unsigned int points = 160000, threads = 2;
  std::string oakland;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_crf",
      "Times super-voxels, features, training and inference of the "
      "multi-scale CRF on generated street scenes.");
  cl.addOption ("points", points, "points of the generated street scenes");
  cl.addOption ("threads", threads, "threads");
  cl.addOption (
      "oakland", oakland, "Oakland 3-D folder: also time training on part3_am + an");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  pcl_ext::CrfInput train_in, test_in;
  std::vector<std::uint32_t> train_labels, test_labels;
  if (!street (1, points, train_in, train_labels) ||
      !street (2, points, test_in, test_labels))
    return 1;
  pcl_ext::MultiscaleCrfModel model;
  pcl_ext::CrfSettings model_settings = model.getSettings();
  model_settings.threads = threads;
  model.setSettings (model_settings);
  if (!model.train ({train_in}, {train_labels}))
    return 1;
  printStats ("train", model.getStatistics());
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf prob;
  if (!model.classify (test_in, labels, prob))
    return 1;
  const auto& s = model.getStatistics();
  printStats ("classify", s);
  pcl_ext::ClassificationMetrics m;
  pcl_ext::evaluateClassification (labels, test_labels, m);
  std::printf (
      "street %u points, %u threads: super-voxels + features + inference %.2f s "
      "(goal <= 10 s); overall accuracy %.4f\n",
      points,
      threads,
      (s.supervoxels_ms + s.features_ms + s.inference_ms) / 1000.0,
      m.overall_accuracy);
  if (!oakland.empty()) {
    pcl_ext::io::ClassMapping mapping;
    mapping.load (oakland + "/classes.txt");
    std::vector<pcl_ext::CrfInput> inputs;
    std::vector<std::vector<std::uint32_t>> ls;
    for (const char* chunk : {"am", "an"}) {
      pcl_ext::io::PointTable t;
      pcl_ext::io::loadOaklandFile (
          oakland + "/oakland_part3_" + chunk + ".xyz_label_conf", t);
      pcl_ext::CrfInput in;
      auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
      const Eigen::Vector3d origin = pcl_ext::io::computeLocalOrigin (t);
      for (const auto& p : t.xyz)
        xyz->push_back (pcl::PointXYZ (static_cast<float> (p.x() - origin.x()),
                                       static_cast<float> (p.y() - origin.y()),
                                       static_cast<float> (p.z() - origin.z())));
      in.xyz = xyz;
      mapping.apply (t.label);
      inputs.push_back (in);
      ls.push_back (t.label);
    }
    pcl_ext::MultiscaleCrfModel oak;
    pcl_ext::CrfSettings oak_settings = oak.getSettings();
    oak_settings.threads = threads;
    oak.setSettings (oak_settings);
    oak.setClassNames (mapping.names());
    if (!oak.train (inputs, ls))
      return 1;
    printStats ("oakland", oak.getStatistics());
    std::printf ("Oakland training on part3_am + part3_an: %.2f s (goal <= 120 s)\n",
                 (oak.getStatistics().supervoxels_ms + oak.getStatistics().features_ms +
                  oak.getStatistics().training_ms) /
                     1000.0);
  }
  return 0;
}
