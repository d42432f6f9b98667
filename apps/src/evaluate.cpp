/*
 * pcl_ext_evaluate: segmentation or classification metrics of a prediction against
 * ground truth.
 *
 *   pcl_ext_evaluate -segments prediction.pcd truth.pcd [-field label] [-truth_field
 * segment] pcl_ext_evaluate -classes prediction.pcd truth.pcd [-field label]
 * [-truth_field class] pcl_ext_evaluate -transform estimated.txt true.txt [-reference
 * X,Y,Z]
 */
#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/transform_file.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {
/** Fixed-point number as text. */
std::string
num (double value, int digits = 4)
{
  char buffer[64];
  std::snprintf (buffer, sizeof (buffer), "%.*f", digits, value);
  return buffer;
}

/** Quote a CSV cell when it needs it (RFC 4180). */
std::string
csvCell (const std::string& text)
{
  if (text.find_first_of (",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text)
    quoted += c == '"' ? std::string ("\"\"") : std::string (1, c);
  return quoted + "\"";
}

/** Tidy CSV: one value a row, `scope,label,name,metric,value`, so that runs can be
 * appended and filtered without knowing the layout. */
class CsvRows {
public:
  CsvRows() { text_ << "scope,label,name,metric,value\n"; }

  template <typename T>
  void
  add (const std::string& scope,
       const std::string& label,
       const std::string& name,
       const std::string& metric,
       const T& value)
  {
    text_ << scope << ',' << csvCell (label) << ',' << csvCell (name) << ',' << metric
          << ',' << value << '\n';
  }

  std::string
  str () const
  {
    return text_.str();
  }

private:
  std::ostringstream text_;
};

bool
loadLabels (const std::string& path,
            const std::string& field,
            std::vector<std::uint32_t>& labels)
{
  pcl_ext::apps::StageTimer timer ("Loading " + path + " ...");
  // Any point file the tools read (LAS, LAZ, E57, PTX, PTS, PCD, PLY, ASCII): only the
  // label fields are compared, point by point.
  pcl_ext::io::PointFile file;
  try {
    pcl_ext::io::loadPointFile (path, file);
  }
  catch (const pcl_ext::io::ReadError& e) {
    std::cout << std::endl;
    std::cerr << "Error: " << e.what() << '\n';
    return false;
  }
  std::string error;
  if (!pcl_ext::io::getLabelField (file.cloud, field, labels, &error)) {
    std::cout << std::endl;
    std::cerr << "Error: " << path << ": " << error << ".\n";
    return false;
  }
  timer.done (labels.size());
  return true;
}

void
printSegmentation (const pcl_ext::SegmentationMetrics& m,
                   std::size_t rows,
                   CsvRows& csv)
{
  const auto percent = [] (std::size_t part, std::size_t whole) {
    return whole
               ? num (100.0 * static_cast<double> (part) / static_cast<double> (whole),
                      1) +
                     " %"
               : std::string ("-");
  };
  std::cout << "\nSegmentation (Hoover et al. 1996, tolerance " << m.tolerance << "):\n"
            << "  evaluated points         " << m.evaluated_points
            << " (ignored: " << m.ignored_points << ")\n"
            << "  unsegmented points       " << m.unsegmented_points << " ("
            << percent (m.unsegmented_points, m.evaluated_points) << ")\n"
            << "  ground-truth segments    " << m.num_truth_segments << "\n"
            << "  predicted segments       " << m.num_predicted_segments << "\n"
            << "  correct                  " << m.correct << " ("
            << percent (m.correct, m.num_truth_segments) << ")\n"
            << "  over-segmented           " << m.over_segmented << " (into "
            << m.over_segmenting << " predicted segments)\n"
            << "  under-segmented          " << m.under_segmented << " (merged by "
            << m.under_segmenting << " predicted segments)\n"
            << "  missed                   " << m.missed << "\n"
            << "  noise (predicted)        " << m.noise << "\n"
            << "  mean best IoU            " << num (m.mean_best_iou) << "\n"
            << "  weighted mean best IoU   " << num (m.weighted_mean_best_iou) << "\n";
  const std::pair<const char*, double> summary[] = {
      {"tolerance", m.tolerance},
      {"evaluated_points", static_cast<double> (m.evaluated_points)},
      {"ignored_points", static_cast<double> (m.ignored_points)},
      {"unsegmented_points", static_cast<double> (m.unsegmented_points)},
      {"unsegmented_fraction", m.unsegmented_fraction},
      {"truth_segments", static_cast<double> (m.num_truth_segments)},
      {"predicted_segments", static_cast<double> (m.num_predicted_segments)},
      {"correct", static_cast<double> (m.correct)},
      {"over_segmented", static_cast<double> (m.over_segmented)},
      {"under_segmented", static_cast<double> (m.under_segmented)},
      {"missed", static_cast<double> (m.missed)},
      {"over_segmenting", static_cast<double> (m.over_segmenting)},
      {"under_segmenting", static_cast<double> (m.under_segmenting)},
      {"noise", static_cast<double> (m.noise)},
      {"mean_best_iou", m.mean_best_iou},
      {"weighted_mean_best_iou", m.weighted_mean_best_iou}};
  for (const auto& [metric, value] : summary)
    csv.add ("summary", "", "", metric, value);

  // The largest segments first: they dominate what a reader wants to check.
  std::vector<const pcl_ext::SegmentMatch*> order;
  for (const auto& s : m.segments) {
    order.push_back (&s);
    const std::string label = std::to_string (s.truth_label);
    csv.add ("segment", label, "", "points", s.truth_size);
    csv.add ("segment", label, "", "best_predicted", s.best_predicted);
    csv.add ("segment", label, "", "predicted_points", s.predicted_size);
    csv.add ("segment", label, "", "overlap", s.overlap);
    csv.add ("segment", label, "", "iou", s.iou);
    csv.add ("segment", label, "", "outcome", pcl_ext::segmentOutcomeName (s.outcome));
  }
  std::stable_sort (order.begin(), order.end(), [] (const auto* a, const auto* b) {
    return a->truth_size > b->truth_size;
  });
  if (rows == 0 || order.empty())
    return;
  std::cout << "\nPer ground-truth segment"
            << (order.size() > rows
                    ? " (the " + std::to_string (rows) + " largest of " +
                          std::to_string (order.size()) + ")"
                    : std::string())
            << ":\n";
  char line[160];
  std::snprintf (line,
                 sizeof (line),
                 "  %10s %10s %10s %10s %10s %8s  %s\n",
                 "truth",
                 "points",
                 "best pred",
                 "pred pts",
                 "overlap",
                 "IoU",
                 "outcome");
  std::cout << line;
  for (std::size_t i = 0; i < std::min (rows, order.size()); ++i) {
    const auto& s = *order[i];
    std::snprintf (line,
                   sizeof (line),
                   "  %10u %10zu %10u %10zu %10zu %8.4f  %s\n",
                   s.truth_label,
                   s.truth_size,
                   s.best_predicted,
                   s.predicted_size,
                   s.overlap,
                   s.iou,
                   pcl_ext::segmentOutcomeName (s.outcome));
    std::cout << line;
  }
}

void
printClassification (const pcl_ext::ClassificationMetrics& m, CsvRows& csv)
{
  std::cout << "\nClassification:\n"
            << "  evaluated points   " << m.evaluated_points
            << " (ignored: " << m.ignored_points << ")\n"
            << "  overall accuracy   " << num (m.overall_accuracy) << "\n"
            << "  macro F1           " << num (m.macro_f1) << " (over "
            << m.num_averaged_classes << " classes present in the ground truth)\n"
            << "  mean IoU           " << num (m.mean_iou) << "\n";
  csv.add ("summary", "", "", "evaluated_points", m.evaluated_points);
  csv.add ("summary", "", "", "ignored_points", m.ignored_points);
  csv.add ("summary", "", "", "overall_accuracy", m.overall_accuracy);
  csv.add ("summary", "", "", "macro_f1", m.macro_f1);
  csv.add ("summary", "", "", "mean_iou", m.mean_iou);

  char line[200];
  std::snprintf (line,
                 sizeof (line),
                 "\n  %8s %-16s %10s %10s %9s %9s %9s %9s\n",
                 "label",
                 "name",
                 "support",
                 "predicted",
                 "precision",
                 "recall",
                 "F1",
                 "IoU");
  std::cout << line;
  for (const auto& c : m.classes) {
    std::snprintf (line,
                   sizeof (line),
                   "  %8u %-16s %10zu %10zu %9.4f %9.4f %9.4f %9.4f\n",
                   c.label,
                   c.name.c_str(),
                   c.support,
                   c.predicted,
                   c.precision,
                   c.recall,
                   c.f1,
                   c.iou);
    std::cout << line;
    const std::string label = std::to_string (c.label);
    csv.add ("class", label, c.name, "support", c.support);
    csv.add ("class", label, c.name, "predicted", c.predicted);
    csv.add ("class", label, c.name, "precision", c.precision);
    csv.add ("class", label, c.name, "recall", c.recall);
    csv.add ("class", label, c.name, "f1", c.f1);
    csv.add ("class", label, c.name, "iou", c.iou);
  }

  std::cout << "\n  Confusion matrix (rows: ground truth, columns: prediction; 0 = "
               "unclassified)\n  "
            << std::string (10, ' ');
  for (const auto l : m.labels) {
    std::snprintf (line, sizeof (line), " %10u", l);
    std::cout << line;
  }
  std::snprintf (line, sizeof (line), " %10s\n", "0");
  std::cout << line;
  for (std::size_t i = 0; i < m.labels.size(); ++i) {
    std::snprintf (line, sizeof (line), "  %10u", m.labels[i]);
    std::cout << line;
    const std::string label = std::to_string (m.labels[i]);
    for (std::size_t j = 0; j < m.labels.size(); ++j) {
      std::snprintf (line, sizeof (line), " %10zu", m.confusion[i][j]);
      std::cout << line;
      csv.add ("confusion",
               label,
               m.classes[i].name,
               "predicted_" + std::to_string (m.labels[j]),
               m.confusion[i][j]);
    }
    std::snprintf (line, sizeof (line), " %10zu\n", m.unclassified[i]);
    std::cout << line;
    csv.add ("confusion", label, m.classes[i].name, "predicted_0", m.unclassified[i]);
  }
}
/** -transform: rotation and translation error of an estimated transform. */
int
evaluateTransform (const std::string& estimated_path,
                   const std::string& true_path,
                   const std::string& reference_text,
                   const std::string& csv_path)
{
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  if (!reference_text.empty()) {
    double v[3];
    char tail;
    if (std::sscanf (
            reference_text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3) {
      std::cerr << "pcl_ext_evaluate: error: invalid -reference '" << reference_text
                << "' (expected X,Y,Z).\n";
      return 1;
    }
    reference = Eigen::Vector3d (v[0], v[1], v[2]);
  }
  Eigen::Matrix4d estimated, truth;
  try {
    pcl_ext::io::loadTransform (estimated_path, estimated);
    pcl_ext::io::loadTransform (true_path, truth);
  }
  catch (const pcl_ext::io::ReadError& e) {
    std::cerr << "Error: " << e.what() << "\n";
    return 1;
  }
  const auto e = pcl_ext::computeTransformationError (estimated, truth, reference);
  std::cout << "\nTransformation error of " << estimated_path << " against "
            << true_path << ":\n"
            << "  rotation error     " << num (e.rotation_deg) << " deg\n"
            << "  translation error  " << num (e.translation)
            << " m (at reference point " << reference.x() << ", " << reference.y()
            << ", " << reference.z() << ")\n"
            << "  scale ratio        " << num (e.scale_ratio, 6) << "\n";
  if (csv_path.empty())
    return 0;
  CsvRows csv;
  csv.add ("input", "", "", "estimated", estimated_path);
  csv.add ("input", "", "", "truth", true_path);
  csv.add ("summary", "", "", "rotation_error_deg", e.rotation_deg);
  csv.add ("summary", "", "", "translation_error", e.translation);
  csv.add ("summary", "", "", "scale_ratio", e.scale_ratio);
  if (!pcl_ext::io::writeTextFile (csv_path, csv.str()))
    return 1;
  std::cout << "\nWrote " << csv_path << "\n";
  return 0;
}
} // namespace

int
main (int argc, char** argv)
{
  bool segments = false, classes = false, transform = false;
  std::string prediction_path, truth_path, field = "label", truth_field, names_path,
                                           csv_path;
  std::string reference;
  double tolerance = 0.8;
  int rows = 40;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_evaluate",
      "Scores a predicted per-point labelling against a ground truth, point by point "
      "(both clouds\n"
      "in the same point order). -segments: best IoU per ground-truth segment and the "
      "counts of\n"
      "Hoover et al. (1996): correct, over-, under-segmented, missed, noise. -classes: "
      "confusion\n"
      "matrix, overall accuracy, per-class precision, recall, F1 and IoU, macro F1, "
      "mean IoU.\n"
      "Ground-truth label 0 is ignored; predicted 0 means unsegmented / unclassified. "
      "Label\n"
      "fields may have any numeric type; negative and NaN values read as 0. "
      "-transform: the\n"
      "rotation error (degrees) and translation error of an estimated 4 x 4 transform "
      "against\n"
      "the true one, both text files of 16 (or 12) numbers row by row.");
  cl.addPositional ("prediction.pcd",
                    prediction_path,
                    "cloud holding the predicted labels (LAS, LAZ, E57, PTX, PTS, PCD, "
                    "PLY or ASCII)");
  cl.addPositional (
      "truth.pcd", truth_path, "cloud holding the ground truth (the same formats)");
  cl.addSwitch ("segments", segments, "evaluate a segmentation");
  cl.addSwitch ("classes", classes, "evaluate a classification");
  cl.addSwitch ("transform",
                transform,
                "compare two transforms: the arguments are estimated.txt true.txt");
  cl.addOption ("field", field, "field of prediction.pcd holding the predicted labels");
  cl.addOption (
      "truth_field",
      truth_field,
      "field of truth.pcd holding the ground truth (none: 'segment' with -segments, "
      "'class' with -classes)");
  cl.addOption (
      "tolerance", tolerance, "Hoover overlap tolerance T, in (0.5, 1] (-segments)");
  cl.addOption (
      "names",
      names_path,
      "class names, lines '<id> <name> [: ...]' as in a class mapping file (-classes; "
      "none: surface/edge/boundary for the 'class' field, else the ids)");
  cl.addOption (
      "rows", rows, "largest ground-truth segments listed, 0 for none (-segments)");
  cl.addOption ("reference",
                reference,
                "X,Y,Z: point (source frame) where the translation error is measured "
                "(-transform; "
                "none: the origin, i.e. |t_estimated - t_true|)");
  cl.addOption (
      "csv",
      csv_path,
      "also write the metrics to this CSV file (scope,label,name,metric,value)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (int (segments) + int (classes) + int (transform) != 1) {
    std::cerr << "pcl_ext_evaluate: error: give exactly one of -segments, -classes and "
                 "-transform.\n"
              << "Run 'pcl_ext_evaluate -h' for the options.\n";
    return 1;
  }
  if (segments && !(tolerance > 0.5 && tolerance <= 1.0)) {
    std::cerr << "pcl_ext_evaluate: error: -tolerance " << tolerance
              << " is outside (0.5, 1].\n";
    return 1;
  }
  if (rows < 0) {
    std::cerr << "pcl_ext_evaluate: error: -rows must be 0 or more.\n";
    return 1;
  }
  if (truth_field.empty())
    truth_field = segments ? "segment" : "class";
  if (!csv_path.empty() && !pcl_ext::io::checkWritable (csv_path))
    return 1;
  if (transform)
    return evaluateTransform (prediction_path, truth_path, reference, csv_path);

  std::map<std::uint32_t, std::string> names;
  if (!names_path.empty()) {
    pcl_ext::io::ClassMapping mapping;
    try {
      mapping.load (names_path);
    }
    catch (const pcl_ext::io::ReadError& e) {
      std::cerr << "Error: " << e.what() << "\n";
      return 1;
    }
    names = mapping.names();
  }
  else if (classes && truth_field == "class")
    for (const auto c : {pcl_ext::PointClass::Surface,
                         pcl_ext::PointClass::Edge,
                         pcl_ext::PointClass::Boundary})
      names[static_cast<std::uint32_t> (c)] = pcl_ext::pointClassName (c);

  std::vector<std::uint32_t> predicted, truth;
  if (!loadLabels (prediction_path, field, predicted) ||
      !loadLabels (truth_path, truth_field, truth))
    return 1;
  if (predicted.size() != truth.size()) {
    std::cerr << "Error: " << prediction_path << " has " << predicted.size()
              << " points but " << truth_path << " has " << truth.size()
              << ": the clouds must hold the same points in the same order.\n";
    return 1;
  }

  CsvRows csv;
  csv.add ("input", "", "", "prediction", prediction_path + ":" + field);
  csv.add ("input", "", "", "truth", truth_path + ":" + truth_field);
  if (segments) {
    pcl_ext::apps::StageTimer timer ("Evaluating the segmentation ...");
    pcl_ext::SegmentationMetrics m;
    if (!pcl_ext::evaluateSegmentation (predicted, truth, m, tolerance))
      return 1;
    timer.done (predicted.size());
    printSegmentation (m, static_cast<std::size_t> (rows), csv);
  }
  else {
    pcl_ext::apps::StageTimer timer ("Evaluating the classification ...");
    pcl_ext::ClassificationMetrics m;
    if (!pcl_ext::evaluateClassification (predicted, truth, m, names))
      return 1;
    timer.done (predicted.size());
    printClassification (m, csv);
  }
  if (!csv_path.empty()) {
    if (!pcl_ext::io::writeTextFile (csv_path, csv.str()))
      return 1;
    std::cout << "\nWrote " << csv_path << "\n";
  }
  return 0;
}
