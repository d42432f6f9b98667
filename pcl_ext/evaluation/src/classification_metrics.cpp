/*
 * pcl_ext: per-point classification metrics.
 */
#include <pcl_ext/evaluation/classification_metrics.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <unordered_map>

namespace pcl_ext {
namespace {
double
ratio (std::size_t numerator, std::size_t denominator)
{
  return denominator == 0
             ? 0.0
             : static_cast<double> (numerator) / static_cast<double> (denominator);
}
} // namespace

bool
evaluateClassification (const std::vector<std::uint32_t>& predicted,
                        const std::vector<std::uint32_t>& truth,
                        ClassificationMetrics& metrics,
                        const std::map<std::uint32_t, std::string>& names)
{
  metrics = ClassificationMetrics();
  if (predicted.size() != truth.size()) {
    PCL_ERROR (
        "[pcl_ext::evaluateClassification] %zu predicted labels for %zu ground-truth "
        "labels: the sizes must be equal.\n",
        predicted.size(),
        truth.size());
    return false;
  }
  // Classes are few: count label pairs sparsely first, then lay out the dense matrix.
  std::unordered_map<std::uint64_t, std::size_t> pairs;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] == 0) {
      ++metrics.ignored_points;
      continue;
    }
    ++pairs[(static_cast<std::uint64_t> (truth[i]) << 32) | predicted[i]];
  }
  std::vector<std::uint32_t>& labels = metrics.labels;
  for (const auto& entry : names)
    if (entry.first != 0)
      labels.push_back (entry.first);
  for (const auto& [key, count] : pairs) {
    labels.push_back (static_cast<std::uint32_t> (key >> 32));
    if ((key & 0xffffffffu) != 0)
      labels.push_back (static_cast<std::uint32_t> (key & 0xffffffffu));
  }
  std::sort (labels.begin(), labels.end());
  labels.erase (std::unique (labels.begin(), labels.end()), labels.end());
  const auto row = [&labels] (std::uint32_t label) {
    return static_cast<std::size_t> (
        std::lower_bound (labels.begin(), labels.end(), label) - labels.begin());
  };

  const std::size_t k = labels.size();
  metrics.confusion.assign (k, std::vector<std::size_t> (k, 0));
  metrics.unclassified.assign (k, 0);
  for (const auto& [key, count] : pairs) {
    const std::size_t i = row (static_cast<std::uint32_t> (key >> 32));
    const std::uint32_t p = static_cast<std::uint32_t> (key & 0xffffffffu);
    if (p == 0)
      metrics.unclassified[i] += count;
    else
      metrics.confusion[i][row (p)] += count;
    metrics.evaluated_points += count;
  }

  metrics.classes.resize (k);
  double f1_sum = 0.0, iou_sum = 0.0;
  for (std::size_t i = 0; i < k; ++i) {
    ClassScores& c = metrics.classes[i];
    c.label = labels[i];
    const auto named = names.find (labels[i]);
    c.name = named != names.end() ? named->second : std::to_string (labels[i]);
    c.true_positives = metrics.confusion[i][i];
    c.support = metrics.unclassified[i];
    for (std::size_t j = 0; j < k; ++j) {
      c.support += metrics.confusion[i][j];
      c.predicted += metrics.confusion[j][i];
    }
    c.precision = ratio (c.true_positives, c.predicted);
    c.recall = ratio (c.true_positives, c.support);
    c.f1 = c.precision + c.recall > 0.0
               ? 2.0 * c.precision * c.recall / (c.precision + c.recall)
               : 0.0;
    c.iou = ratio (c.true_positives, c.support + c.predicted - c.true_positives);
    metrics.correct_points += c.true_positives;
    if (c.support > 0) {
      f1_sum += c.f1;
      iou_sum += c.iou;
      ++metrics.num_averaged_classes;
    }
  }
  metrics.overall_accuracy = ratio (metrics.correct_points, metrics.evaluated_points);
  if (metrics.num_averaged_classes > 0) {
    metrics.macro_f1 = f1_sum / static_cast<double> (metrics.num_averaged_classes);
    metrics.mean_iou = iou_sum / static_cast<double> (metrics.num_averaged_classes);
  }
  return true;
}
} // namespace pcl_ext
