/*
 * pcl_ext_crf_classify: classify a cloud with a trained multi-scale CRF model; the
 * input points and fields written back in the input's coordinates with the class id in
 * the field `crf_class` (-output_field), and with -asprs in a LAS output's
 * Classification as ASPRS codes.
 */
#include "crf/crf_inputs.h"

#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/apps/picture_options.h>
#include <pcl_ext/io/cloud_fields.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

namespace {
void
printMetrics (const pcl_ext::ClassificationMetrics& m)
{
  std::printf ("%-14s %9s %9s %9s %9s %9s %9s %9s\n",
               "class",
               "support",
               "precision",
               "recall",
               "F1",
               "IoU",
               "predicted",
               "correct");
  for (const auto& c : m.classes)
    std::printf ("%-14s %9zu %9.4f %9.4f %9.4f %9.4f %9zu %9zu\n",
                 c.name.c_str(),
                 c.support,
                 c.precision,
                 c.recall,
                 c.f1,
                 c.iou,
                 c.predicted,
                 c.true_positives);
  std::printf (
      "overall accuracy %.4f, macro F1 %.4f, mean IoU %.4f (%zu points evaluated, "
      "%zu ignored)\n",
      m.overall_accuracy,
      m.macro_f1,
      m.mean_iou,
      m.evaluated_points,
      m.ignored_points);
}

/** The points of each class of the model (and those left unlabelled, non-finite). */
void
printClassCounts (const std::vector<std::uint32_t>& labels,
                  const std::map<std::uint32_t, std::string>& names)
{
  std::map<std::uint32_t, std::size_t> counts;
  for (const auto l : labels)
    ++counts[l];
  const double total = static_cast<double> (std::max<std::size_t> (1, labels.size()));
  std::printf ("%-6s %-14s %10s %8s\n", "id", "class", "points", "share");
  for (const auto& [id, name] : names) {
    const std::size_t n = counts.count (id) ? counts[id] : 0;
    std::printf ("%-6u %-14s %10zu %7.2f%%\n", id, name.c_str(), n, 100.0 * n / total);
  }
  if (counts.count (0))
    std::printf ("%-6u %-14s %10zu %7.2f%%\n",
                 0u,
                 "(none)",
                 counts[0],
                 100.0 * counts[0] / total);
}
} // namespace

int
main (int argc, char** argv)
{
  std::string model_path, input, output, png, classes_file, probability_field;
  bool truth = false;
  unsigned int threads = 0;
  int draws = 0;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_crf_classify",
      "Classifies a cloud with a multi-scale CRF model (Lim "
      "& Suter 2008) and writes its points and fields, in the "
      "input's coordinates, with the class id in the field "
      "'crf_class'.");
  pcl_ext::apps::ResultField result = pcl_ext::apps::crfClassField();
  cl.addPositional ("model.txt", model_path, "a model written by pcl_ext_crf_train");
  cl.addPositional ("input",
                    input,
                    std::string (pcl_ext::apps::kInputFormats) +
                        ", or an Oakland .xyz_label_conf file with -classes");
  cl.addPositional ("output", output, pcl_ext::apps::kOutputFormats);
  cl.addOption (
      "png", png, "also render the result (and the truth with -truth) to this PNG");
  cl.addOption (
      "classes", classes_file, "class file mapping the input's labels (Oakland)");
  cl.addOption ("threads", threads, "threads (0: all cores)");
  cl.addOption ("draws",
                draws,
                "over-segmentations averaged (0: the model's; 1: one draw, the "
                "paper's)");
  cl.addOption ("probability_field",
                probability_field,
                "also write each point's probability of its class (float, 0 for "
                "non-finite points) into this field; empty: not written");
  result.addTo (cl);
  cl.addSwitch (
      "truth", truth, "the input's labels are ground truth: print the metrics");
  pcl_ext::apps::PictureOptions picture;
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;
  if (!result.checkOutput (output, {png}))
    return 1;
  pcl_ext::MultiscaleCrfModel model;
  {
    pcl_ext::apps::StageTimer timer ("Loading the model " + model_path);
    if (!model.loadModel (model_path))
      return 1;
    timer.done (0);
  }
  pcl_ext::CrfSettings settings = model.getSettings();
  settings.threads = threads;
  if (draws != 0)
    settings.draws = draws;
  if (!pcl_ext::checkCrfSettings (settings, "pcl_ext_crf_classify"))
    return 1;
  model.setSettings (settings);
  pcl_ext::io::ClassMapping mapping;
  if (!classes_file.empty()) {
    try {
      mapping.load (classes_file);
    }
    catch (const std::exception& e) {
      std::cerr << "pcl_ext_crf_classify: " << e.what() << '\n';
      return 1;
    }
  }
  pcl_ext::apps::CrfCloud cloud;
  {
    pcl_ext::apps::StageTimer timer ("Loading " + input);
    std::string error;
    if (!pcl_ext::apps::loadCrfCloud (input, &mapping, cloud, error)) {
      std::cerr << "\npcl_ext_crf_classify: " << error << '\n';
      return 1;
    }
    timer.done (cloud.input.xyz->size());
  }
  if (!result.checkInput (cloud.file, input))
    return 1;
  if (!probability_field.empty() && probability_field == result.name()) {
    std::cerr << "pcl_ext_crf_classify: -probability_field must differ from the class "
                 "field '"
              << result.name() << "'\n";
    return 1;
  }
  if (truth && cloud.labels.empty()) {
    std::cerr << "pcl_ext_crf_classify: -truth needs a labelled input\n";
    return 1;
  }
  std::vector<std::uint32_t> labels;
  Eigen::MatrixXf probabilities;
  pcl_ext::apps::StageTimer timer ("Classifying");
  if (!model.classify (cloud.input, labels, probabilities)) {
    std::cerr << "\npcl_ext_crf_classify: classification failed (see above)\n";
    return 1;
  }
  timer.done (labels.size());
  const auto& st = model.getStatistics();
  std::printf (
      "  super-voxels %.0f ms, features %.0f ms, inference %.0f ms (%d draw%s; the "
      "first: %zu super-voxels; BP at most %d sweeps%s)\n",
      st.supervoxels_ms,
      st.features_ms,
      st.inference_ms,
      model.getSettings().draws,
      model.getSettings().draws == 1 ? "" : "s",
      st.supervoxels,
      st.iterations,
      st.converged ? ", converged" : ", not converged");
  std::vector<std::uint32_t> truth_labels = cloud.labels;
  pcl::PCLPointCloud2 classified = cloud.file.cloud;
  if (!result.attach (classified, labels))
    return 1;
  if (!probability_field.empty()) {
    std::vector<float> winning (labels.size(), 0.f);
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] != 0)
        winning[i] = probabilities.row (static_cast<Eigen::Index> (i)).maxCoeff();
    if (!pcl_ext::io::setFloatField (classified, probability_field, winning)) {
      std::cerr << "pcl_ext_crf_classify: cannot write the field '" << probability_field
                << "'\n";
      return 1;
    }
  }
  printClassCounts (labels, model.getClassNames());
  if (result.asprs()) {
    const auto codes = pcl_ext::apps::crfAsprsCodes (model.getClassNames());
    std::vector<std::uint32_t> asprs (labels.size(), 1);
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (const auto it = codes.find (labels[i]); it != codes.end())
        asprs[i] = it->second;
    if (!pcl_ext::io::setLabelField (classified, "classification", asprs))
      return 1;
  }
  if (!pcl_ext::apps::saveOutput (output, classified, cloud.file))
    return 1;
  if (truth) {
    pcl_ext::ClassificationMetrics metrics;
    pcl_ext::evaluateClassification (
        labels, truth_labels, metrics, model.getClassNames());
    printMetrics (metrics);
  }
  if (!png.empty()) {
#ifdef PCL_EXT_HAVE_VISUALIZATION
    using namespace pcl_ext::visualization;
    // One legend line per class of the model.
    std::vector<LegendEntry> legend;
    const auto& names = model.getClassNames();
    for (const auto& [id, name] : names)
      legend.push_back ({name, colourByLabel ({id}).front()});
    legend.push_back ({"unclassified", colourByLabel ({0u}).front()});
    std::vector<View> views;
    if (truth)
      views.push_back (
          {"ground truth",
           {{makeColouredCloud (*cloud.input.xyz, colourByLabel (truth_labels))}},
           legend});
    views.push_back ({"multi-scale CRF (Lim & Suter)",
                      {{makeColouredCloud (*cloud.input.xyz, colourByLabel (labels))}},
                      legend});
    if (!renderToPng (views, png, picture.renderOptions (*cloud.input.xyz)))
      return 1;
#else
    std::cerr << "pcl_ext_crf_classify: built without rendering; -png ignored\n";
#endif
  }
  return 0;
}
