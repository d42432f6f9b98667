/*
 * Classification metrics on a small case worked out by hand.
 */
#include <pcl_ext/evaluation/classification_metrics.h>

#include <gtest/gtest.h>

using Labels = std::vector<std::uint32_t>;

TEST (ClassificationMetrics, WorkedExample)
{
  // Points 7 and 8 are ignored; point 3 (class 1) is unclassified.
  const Labels truth = {1, 1, 1, 1, 2, 2, 2, 0, 0};
  const Labels predicted = {1, 1, 2, 0, 2, 2, 1, 1, 2};
  pcl_ext::ClassificationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateClassification (predicted, truth, m));
  EXPECT_EQ (m.labels, (Labels{1, 2}));
  EXPECT_EQ (m.evaluated_points, 7u);
  EXPECT_EQ (m.ignored_points, 2u);
  EXPECT_EQ (m.correct_points, 4u);
  ASSERT_EQ (m.confusion.size(), 2u);
  EXPECT_EQ (m.confusion[0], (std::vector<std::size_t>{2, 1}));
  EXPECT_EQ (m.confusion[1], (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ (m.unclassified, (std::vector<std::size_t>{1, 0}));
  const auto& c1 = m.classes[0];
  EXPECT_EQ (c1.support, 4u);
  EXPECT_EQ (c1.predicted, 3u);
  EXPECT_EQ (c1.true_positives, 2u);
  EXPECT_DOUBLE_EQ (c1.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ (c1.recall, 0.5);
  EXPECT_DOUBLE_EQ (c1.f1, 4.0 / 7.0);
  EXPECT_DOUBLE_EQ (c1.iou, 0.4);
  const auto& c2 = m.classes[1];
  EXPECT_DOUBLE_EQ (c2.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ (c2.recall, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ (c2.f1, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ (c2.iou, 0.5);
  EXPECT_DOUBLE_EQ (m.overall_accuracy, 4.0 / 7.0);
  EXPECT_DOUBLE_EQ (m.macro_f1, (4.0 / 7.0 + 2.0 / 3.0) / 2.0);
  EXPECT_DOUBLE_EQ (m.mean_iou, 0.45);
  EXPECT_EQ (c1.name, "1");
}

TEST (ClassificationMetrics, NamesAddRowsButOnlyTruthClassesAreAveraged)
{
  const Labels truth = {1, 1, 2, 2};
  const Labels predicted = {1, 1, 2, 5}; // 5 occurs only in the prediction
  pcl_ext::ClassificationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateClassification (
      predicted, truth, m, {{1, "ground"}, {2, "facade"}, {3, "wire"}}));
  EXPECT_EQ (m.labels, (Labels{1, 2, 3, 5}));
  EXPECT_EQ (m.classes[0].name, "ground");
  EXPECT_EQ (m.classes[2].name, "wire");
  EXPECT_EQ (m.classes[2].support, 0u);
  EXPECT_DOUBLE_EQ (m.classes[2].f1, 0.0);
  EXPECT_EQ (m.classes[3].name, "5");
  EXPECT_EQ (m.classes[3].predicted, 1u);
  EXPECT_EQ (m.num_averaged_classes, 2u);
  // ground: P = R = 1; facade: P = 1, R = 0.5, F1 = 2/3, IoU 0.5.
  EXPECT_DOUBLE_EQ (m.macro_f1, (1.0 + 2.0 / 3.0) / 2.0);
  EXPECT_DOUBLE_EQ (m.mean_iou, 0.75);
  EXPECT_DOUBLE_EQ (m.overall_accuracy, 0.75);
}

TEST (ClassificationMetrics, PerfectEmptyAndMismatched)
{
  pcl_ext::ClassificationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateClassification ({3, 3, 4}, {3, 3, 4}, m));
  EXPECT_DOUBLE_EQ (m.overall_accuracy, 1.0);
  EXPECT_DOUBLE_EQ (m.macro_f1, 1.0);
  EXPECT_DOUBLE_EQ (m.mean_iou, 1.0);

  ASSERT_TRUE (pcl_ext::evaluateClassification ({}, {}, m));
  EXPECT_TRUE (m.labels.empty());
  EXPECT_DOUBLE_EQ (m.overall_accuracy, 0.0);

  ASSERT_TRUE (pcl_ext::evaluateClassification ({1, 2}, {0, 0}, m));
  EXPECT_EQ (m.ignored_points, 2u);
  EXPECT_EQ (m.evaluated_points, 0u);
  EXPECT_TRUE (m.labels.empty());

  EXPECT_FALSE (pcl_ext::evaluateClassification ({1}, {1, 1}, m));
}
