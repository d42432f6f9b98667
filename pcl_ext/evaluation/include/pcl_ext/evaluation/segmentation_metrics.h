/*
 * pcl_ext: segmentation metrics against a ground-truth labelling.
 */
#pragma once

#include <pcl/PointIndices.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_ext {
/** \brief What became of one ground-truth segment, after Hoover et al. (1996),
 * section 3. */
enum class SegmentOutcome : std::uint8_t {
  Correct, ///< one predicted segment and this one overlap mutually by the tolerance
  OverSegmented,  ///< split into two or more predicted segments
  UnderSegmented, ///< merged with other ground-truth segments into one predicted
                  ///< segment
  Missed          ///< none of the above
};

/** \brief Lower-case name of an outcome ("correct", "over", "under", "missed"). */
const char*
segmentOutcomeName (SegmentOutcome outcome);

/** \brief The evaluation of one ground-truth segment. */
struct SegmentMatch {
  std::uint32_t truth_label = 0; ///< ground-truth label (never 0)
  std::size_t truth_size = 0;    ///< its number of points
  std::uint32_t best_predicted =
      0; ///< predicted label of highest IoU; 0 when nothing overlaps
  std::size_t predicted_size = 0; ///< evaluated points of that predicted segment
  std::size_t overlap = 0;        ///< points the two share
  double iou = 0.0;               ///< overlap / (truth_size + predicted_size - overlap)
  SegmentOutcome outcome = SegmentOutcome::Missed;
};

/** \brief Segmentation quality of a predicted labelling against a ground truth.
 *
 * Only points whose ground-truth label is not 0 take part ("evaluated points"); sizes
 * of predicted segments count evaluated points only, so a segment is not penalised for
 * covering what the ground truth ignores. Ratios that are undefined (no evaluated
 * point, no segment) are 0.
 */
struct SegmentationMetrics {
  std::vector<SegmentMatch>
      segments;           ///< one per ground-truth segment, by ascending label
  double tolerance = 0.8; ///< the Hoover tolerance T used
  std::size_t num_truth_segments = 0; ///< distinct non-zero ground-truth labels
  std::size_t num_predicted_segments =
      0; ///< distinct non-zero predicted labels on evaluated points
  std::size_t evaluated_points = 0;   ///< points with a non-zero ground-truth label
  std::size_t ignored_points = 0;     ///< points with ground-truth label 0
  std::size_t unsegmented_points = 0; ///< evaluated points with predicted label 0
  double unsegmented_fraction = 0.0;  ///< unsegmented_points / evaluated_points
  double mean_best_iou = 0.0; ///< mean over ground-truth segments of their best IoU
  double weighted_mean_best_iou =
      0.0;                        ///< the same weighted by ground-truth segment size
  std::size_t correct = 0;        ///< ground-truth segments correctly detected
  std::size_t over_segmented = 0; ///< ground-truth segments split (over-segmentation)
  std::size_t under_segmented =
      0;                  ///< ground-truth segments merged (under-segmentation)
  std::size_t missed = 0; ///< ground-truth segments missed
  std::size_t over_segmenting =
      0; ///< predicted segments taking part in an over-segmentation
  std::size_t under_segmenting =
      0;                 ///< predicted segments that merge several truth segments
  std::size_t noise = 0; ///< predicted segments in no correct/over/under instance
};

/** \brief Compare a predicted segmentation with a ground-truth one, point by point.
 *
 * Labels are arbitrary unsigned integers; ground-truth label 0 means "ignore this
 * point", predicted label 0 means "left unsegmented". Overlaps are counted sparsely (a
 * hash map over the label pairs that occur), so the cost is O(N) time and O(pairs)
 * memory.
 *
 * For each ground-truth segment the predicted segment of highest intersection over
 * union is reported (ties go to the smaller label). The counts follow Hoover et al.
 * (1996), "An experimental comparison of range image segmentation algorithms", with
 * tolerance T, where O(m, n) is the number of points ground-truth segment m and
 * predicted segment n share:
 * - correct detection of m by n: O >= T |m| and O >= T |n|;
 * - over-segmentation of m into n_1..n_x (x >= 2): O(m, n_i) >= T |n_i| for each i and
 *   sum_i O(m, n_i) >= T |m|;
 * - under-segmentation of m_1..m_x (x >= 2) into n: O(m_i, n) >= T |m_i| for each i and
 *   sum_i O(m_i, n) >= T |n|;
 * - missed: a ground-truth segment in none of these; noise: a predicted segment in
 * none. Each segment takes part in at most one instance, checked in the order correct,
 * over-, under-segmentation: with T > 0.5 each kind of instance is unique for a
 * segment, but a segment can qualify for two kinds (a correct match plus a small
 * fragment also reads as an over-segmentation), and the first kind wins (the fragment
 * then counts as noise).
 *
 * \param[in] predicted one predicted label per point
 * \param[in] truth one ground-truth label per point, in the same order
 * \param[out] metrics the result (reset first)
 * \param[in] tolerance Hoover's T, in (0.5, 1]; default 0.8 (an 80 % overlap, the value
 *            usually reported with these metrics)
 * \return false (and an error printed, empty metrics) when the sizes differ or the
 * tolerance is out of range
 */
bool
evaluateSegmentation (const std::vector<std::uint32_t>& predicted,
                      const std::vector<std::uint32_t>& truth,
                      SegmentationMetrics& metrics,
                      double tolerance = 0.8);

/** \brief Same, with the prediction as a segmenter's output (e.g.
 * pcl::RegionGrowing::extract).
 *
 * Cluster i becomes label i + 1; points in no cluster are unsegmented. See
 * labelsFromIndices for points in several clusters and out-of-range indices.
 */
bool
evaluateSegmentation (const std::vector<pcl::PointIndices>& predicted,
                      const std::vector<std::uint32_t>& truth,
                      SegmentationMetrics& metrics,
                      double tolerance = 0.8);

/** \brief Same, with both segmentations as clusters over a cloud of \a num_points
 * points (points in no ground-truth cluster are ignored). */
bool
evaluateSegmentation (const std::vector<pcl::PointIndices>& predicted,
                      const std::vector<pcl::PointIndices>& truth,
                      std::size_t num_points,
                      SegmentationMetrics& metrics,
                      double tolerance = 0.8);

/** \brief Turn clusters into one label per point: cluster i gives label i + 1, others
 * get 0.
 *
 * A point listed in several clusters keeps the first cluster's label (segmenters should
 * not produce such points; they are counted so the caller can warn). \param[in]
 * clusters the clusters, indices into a cloud of \a num_points points \param[in]
 * num_points size of the cloud \param[out] labels num_points labels \return the number
 * of indices that were negative, >= num_points (both skipped), or already labelled by
 * an earlier cluster
 */
std::size_t
labelsFromIndices (const std::vector<pcl::PointIndices>& clusters,
                   std::size_t num_points,
                   std::vector<std::uint32_t>& labels);
} // namespace pcl_ext
