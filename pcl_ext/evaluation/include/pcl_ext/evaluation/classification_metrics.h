/*
 * pcl_ext: per-point classification metrics.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
/** \brief Scores of one class. Undefined ratios (0 / 0) are 0. */
struct ClassScores {
  std::uint32_t label = 0;   ///< class label (never 0)
  std::string name;          ///< from the names given, else the label as text
  std::size_t support = 0;   ///< evaluated points of this class in the ground truth
  std::size_t predicted = 0; ///< evaluated points predicted as this class
  std::size_t true_positives = 0; ///< points of this class predicted as this class
  double precision = 0.0;         ///< TP / predicted
  double recall = 0.0;            ///< TP / support
  double f1 = 0.0;                ///< 2 P R / (P + R)
  double iou = 0.0;               ///< TP / (support + predicted - TP)
};

/** \brief Per-point classification quality against a ground truth.
 *
 * Points of ground-truth label 0 are ignored. A point predicted 0 ("unclassified") with
 * a non-zero ground truth counts as wrong: it lowers its class's recall and the
 * accuracy, but no class's precision.
 */
struct ClassificationMetrics {
  /** Labels of the rows and columns of the confusion matrix, ascending: every non-zero
   * label that occurs in the ground truth or the prediction (on evaluated points), plus
   * every label that was given a name. */
  std::vector<std::uint32_t> labels;
  /** confusion[i][j]: evaluated points of ground truth labels[i] predicted as
   * labels[j]. */
  std::vector<std::vector<std::size_t>> confusion;
  /** unclassified[i]: evaluated points of ground truth labels[i] predicted 0. */
  std::vector<std::size_t> unclassified;
  std::vector<ClassScores> classes; ///< one per entry of labels, same order
  std::size_t evaluated_points = 0; ///< points of non-zero ground-truth label
  std::size_t ignored_points = 0;   ///< points of ground-truth label 0
  std::size_t correct_points = 0; ///< evaluated points predicted as their ground truth
  double overall_accuracy = 0.0;  ///< correct_points / evaluated_points
  /** Mean F1 over the classes present in the ground truth (support > 0): a class that
   * is only predicted still lowers the others' precision, but is not averaged. */
  double macro_f1 = 0.0;
  double mean_iou = 0.0;                ///< mean IoU over the same classes
  std::size_t num_averaged_classes = 0; ///< number of classes in those means
};

/** \brief Confusion matrix and scores of a per-point classification.
 *
 * \param[in] predicted one predicted class label per point (0 = unclassified)
 * \param[in] truth one ground-truth class label per point (0 = ignore), same order
 * \param[out] metrics the result (reset first)
 * \param[in] names optional class names by label; named labels always get a row, even
 * when absent from both labellings (they are averaged only when present in the truth)
 * \return false (error printed, empty metrics) when the sizes differ
 */
bool
evaluateClassification (const std::vector<std::uint32_t>& predicted,
                        const std::vector<std::uint32_t>& truth,
                        ClassificationMetrics& metrics,
                        const std::map<std::uint32_t, std::string>& names = {});
} // namespace pcl_ext
