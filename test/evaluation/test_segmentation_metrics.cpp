/*
 * Segmentation metrics on hand-made labellings with known answers.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using pcl_ext::SegmentOutcome;
using Labels = std::vector<std::uint32_t>;

namespace {
/** n copies of label. */
Labels
run (std::uint32_t label, std::size_t n)
{
  return Labels (n, label);
}

Labels
concat (std::initializer_list<Labels> parts)
{
  Labels all;
  for (const auto& p : parts)
    all.insert (all.end(), p.begin(), p.end());
  return all;
}

pcl_ext::SegmentationMetrics
evaluate (const Labels& predicted, const Labels& truth, double tolerance = 0.8)
{
  pcl_ext::SegmentationMetrics m;
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (predicted, truth, m, tolerance));
  return m;
}
} // namespace

TEST (SegmentationMetrics, PerfectUnderRelabelling)
{
  const Labels truth = concat ({run (1, 3), run (2, 2), run (3, 4)});
  const Labels predicted = concat ({run (50, 3), run (7, 2), run (9, 4)});
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.num_truth_segments, 3u);
  EXPECT_EQ (m.num_predicted_segments, 3u);
  EXPECT_EQ (m.correct, 3u);
  EXPECT_EQ (m.over_segmented + m.under_segmented + m.missed + m.noise, 0u);
  EXPECT_DOUBLE_EQ (m.mean_best_iou, 1.0);
  EXPECT_DOUBLE_EQ (m.weighted_mean_best_iou, 1.0);
  EXPECT_DOUBLE_EQ (m.unsegmented_fraction, 0.0);
  ASSERT_EQ (m.segments.size(), 3u);
  EXPECT_EQ (m.segments[0].truth_label, 1u);
  EXPECT_EQ (m.segments[0].best_predicted, 50u);
  EXPECT_EQ (m.segments[1].best_predicted, 7u);
  EXPECT_EQ (m.segments[2].best_predicted, 9u);
  EXPECT_EQ (m.segments[2].truth_size, 4u);
  EXPECT_EQ (m.segments[2].outcome, SegmentOutcome::Correct);
}

TEST (SegmentationMetrics, OverSegmentedIntoTwoHalves)
{
  const Labels truth = run (1, 10);
  const Labels predicted = concat ({run (1, 5), run (2, 5)});
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.correct, 0u);
  EXPECT_EQ (m.over_segmented, 1u);
  EXPECT_EQ (m.over_segmenting, 2u);
  EXPECT_EQ (m.noise, 0u);
  EXPECT_EQ (m.segments[0].outcome, SegmentOutcome::OverSegmented);
  EXPECT_DOUBLE_EQ (m.segments[0].iou, 0.5);
  EXPECT_EQ (m.segments[0].best_predicted, 1u); // tie: the smaller label
  EXPECT_EQ (m.segments[0].overlap, 5u);
}

TEST (SegmentationMetrics, UnderSegmentedByOneMergedSegment)
{
  const Labels truth = concat ({run (1, 5), run (2, 5), run (3, 6)});
  const Labels predicted = concat ({run (4, 10), run (8, 6)});
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.correct, 1u);
  EXPECT_EQ (m.under_segmented, 2u);
  EXPECT_EQ (m.under_segmenting, 1u);
  EXPECT_EQ (m.segments[0].outcome, SegmentOutcome::UnderSegmented);
  EXPECT_EQ (m.segments[1].outcome, SegmentOutcome::UnderSegmented);
  EXPECT_EQ (m.segments[2].outcome, SegmentOutcome::Correct);
  EXPECT_DOUBLE_EQ (m.segments[0].iou, 0.5);
  EXPECT_DOUBLE_EQ (m.mean_best_iou, (0.5 + 0.5 + 1.0) / 3.0);
  EXPECT_DOUBLE_EQ (m.weighted_mean_best_iou, (5 * 0.5 + 5 * 0.5 + 6 * 1.0) / 16.0);
}

TEST (SegmentationMetrics, MissedAndNoise)
{
  // 4 of 10 points found, the rest unsegmented: the segment is missed, the fragment is
  // noise.
  const Labels truth = run (1, 10);
  const Labels predicted = concat ({run (6, 4), run (0, 6)});
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.missed, 1u);
  EXPECT_EQ (m.noise, 1u);
  EXPECT_EQ (m.segments[0].outcome, SegmentOutcome::Missed);
  EXPECT_DOUBLE_EQ (m.segments[0].iou, 0.4);
  EXPECT_EQ (m.unsegmented_points, 6u);
  EXPECT_DOUBLE_EQ (m.unsegmented_fraction, 0.6);
}

TEST (SegmentationMetrics, NothingPredicted)
{
  const auto m = evaluate (run (0, 5), run (3, 5));
  EXPECT_EQ (m.missed, 1u);
  EXPECT_EQ (m.segments[0].best_predicted, 0u);
  EXPECT_DOUBLE_EQ (m.segments[0].iou, 0.0);
  EXPECT_DOUBLE_EQ (m.unsegmented_fraction, 1.0);
}

TEST (SegmentationMetrics, IgnoreLabelIsNotScored)
{
  // The predicted segment also covers points the ground truth ignores: still a perfect
  // match.
  const Labels truth = concat ({run (1, 4), run (0, 4)});
  const Labels predicted = run (1, 8);
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.evaluated_points, 4u);
  EXPECT_EQ (m.ignored_points, 4u);
  EXPECT_EQ (m.correct, 1u);
  EXPECT_DOUBLE_EQ (m.segments[0].iou, 1.0);
  EXPECT_EQ (m.segments[0].predicted_size, 4u);
  // A predicted segment lying only on ignored points is not counted at all.
  const auto m2 = evaluate (concat ({run (1, 4), run (2, 4)}), truth);
  EXPECT_EQ (m2.num_predicted_segments, 1u);
  EXPECT_EQ (m2.noise, 0u);
}

TEST (SegmentationMetrics, ToleranceDecidesBetweenCorrectAndOver)
{
  const Labels truth = run (1, 10);
  const Labels predicted = concat ({run (1, 8), run (2, 2)});
  const auto loose = evaluate (predicted, truth, 0.8);
  EXPECT_EQ (loose.correct, 1u);
  EXPECT_EQ (loose.noise, 1u); // the 2-point fragment
  const auto strict = evaluate (predicted, truth, 0.9);
  EXPECT_EQ (strict.correct, 0u);
  EXPECT_EQ (strict.over_segmented, 1u);
  EXPECT_EQ (strict.noise, 0u);
}

TEST (SegmentationMetrics, MixedScene)
{
  // 1: correct (9 of 10, one stray point in 99); 2: over (4 + 4); 3 and 4: under
  // (merged in 30); 5: missed (scattered over 40..44 and unsegmented); 99: noise.
  const Labels truth = concat (
      {run (1, 10), run (2, 8), run (3, 5), run (4, 5), run (5, 5), run (0, 3)});
  const Labels predicted = concat ({run (10, 9),
                                    run (99, 1),
                                    run (20, 4),
                                    run (21, 4),
                                    run (30, 10),
                                    Labels{40, 41, 42, 0, 0},
                                    run (99, 3)});
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.num_truth_segments, 5u);
  EXPECT_EQ (m.correct, 1u);
  EXPECT_EQ (m.over_segmented, 1u);
  EXPECT_EQ (m.under_segmented, 2u);
  EXPECT_EQ (m.missed, 1u);
  // Noise: 99 (1 evaluated point), 40, 41, 42.
  EXPECT_EQ (m.noise, 4u);
  EXPECT_EQ (m.unsegmented_points, 2u);
  EXPECT_EQ (m.segments[4].outcome, SegmentOutcome::Missed);
  EXPECT_NEAR (m.segments[0].iou, 0.9, 1e-12);
}

TEST (SegmentationMetrics, EmptyInput)
{
  const auto m = evaluate ({}, {});
  EXPECT_EQ (m.num_truth_segments, 0u);
  EXPECT_EQ (m.evaluated_points, 0u);
  EXPECT_DOUBLE_EQ (m.mean_best_iou, 0.0);
  EXPECT_DOUBLE_EQ (m.unsegmented_fraction, 0.0);
  // All ignored.
  const auto all_ignored = evaluate (run (3, 4), run (0, 4));
  EXPECT_EQ (all_ignored.ignored_points, 4u);
  EXPECT_EQ (all_ignored.num_predicted_segments, 0u);
}

TEST (SegmentationMetrics, RejectsBadInput)
{
  pcl_ext::SegmentationMetrics m;
  EXPECT_FALSE (pcl_ext::evaluateSegmentation (run (1, 3), run (1, 4), m));
  EXPECT_FALSE (pcl_ext::evaluateSegmentation (run (1, 3), run (1, 3), m, 0.5));
  EXPECT_FALSE (pcl_ext::evaluateSegmentation (run (1, 3), run (1, 3), m, 1.01));
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (run (1, 3), run (1, 3), m, 1.0));
  EXPECT_EQ (m.correct, 1u);
}

TEST (SegmentationMetrics, PointIndicesInput)
{
  // A segmenter's clusters: {0,1,2} and {3,4}; point 5 unsegmented.
  std::vector<pcl::PointIndices> clusters (2);
  clusters[0].indices = {0, 1, 2};
  clusters[1].indices = {3, 4};
  const Labels truth = {7, 7, 7, 8, 8, 8};
  pcl_ext::SegmentationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth, m));
  // Segment 8 is found by 2 of its 3 points: below T = 0.8, missed; above T = 0.6,
  // correct.
  EXPECT_EQ (m.correct, 1u);
  EXPECT_EQ (m.missed, 1u);
  EXPECT_EQ (m.noise, 1u);
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth, m, 0.6));
  EXPECT_EQ (m.correct, 2u);
  EXPECT_EQ (m.segments[0].best_predicted, 1u);
  EXPECT_EQ (m.segments[1].best_predicted, 2u);
  EXPECT_NEAR (m.segments[1].iou, 2.0 / 3.0, 1e-12);
  EXPECT_EQ (m.unsegmented_points, 1u);

  std::vector<pcl::PointIndices> truth_clusters (2);
  truth_clusters[0].indices = {0, 1, 2};
  truth_clusters[1].indices = {3, 4, 5};
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth_clusters, 6, m, 0.6));
  EXPECT_EQ (m.correct, 2u);

  // Out-of-range and repeated indices are skipped and counted.
  clusters[1].indices = {3, 4, 2, 17, -1};
  Labels labels;
  EXPECT_EQ (pcl_ext::labelsFromIndices (clusters, 6, labels), 3u);
  EXPECT_EQ (labels, (Labels{1, 1, 1, 2, 2, 0}));
}

TEST (SegmentationMetrics, MillionsOfPointsManySegments)
{
  // 3 million points, 30,000 ground-truth segments each split in two predicted halves.
  const std::size_t segments = 30000, size = 100;
  Labels truth (segments * size), predicted (segments * size);
  for (std::size_t s = 0; s < segments; ++s)
    for (std::size_t i = 0; i < size; ++i) {
      truth[s * size + i] = static_cast<std::uint32_t> (s + 1);
      predicted[s * size + i] =
          static_cast<std::uint32_t> (2 * s + 1 + (i >= size / 2));
    }
  const auto m = evaluate (predicted, truth);
  EXPECT_EQ (m.over_segmented, segments);
  EXPECT_EQ (m.over_segmenting, 2 * segments);
  EXPECT_DOUBLE_EQ (m.mean_best_iou, 0.5);
}
